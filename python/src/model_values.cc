#include "model_values.h"

#include <pybind11/stl.h>

#include "musclesim/model/family_fields.h"
#include "part_dict.h"

namespace py = pybind11;

namespace musclesim::python {

py::dict GaussianDict(const Gaussian& g) {
  py::dict out;
  AddFields(OnlyVariant<Gaussian>("gaussian", "", GaussianFields()), g, out);
  return out;
}

py::dict ParamsDict(const ModelParams& p) {
  // the described fields and lists (model/family_fields.h)
  py::dict out;
  if (p.family != CurveFamily::kPaper) out["family"] = ToString(p.family);
  const ModelFamily& family = *VariantOf(ModelFamilies(), p);
  AddFields(family, p, out);
  AddLists(family, p, out);
  return out;
}

}  // namespace musclesim::python
