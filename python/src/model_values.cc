#include "model_values.h"

#include <pybind11/stl.h>

#include "musclesim/model/family_fields.h"
#include "part_dict.h"

namespace py = pybind11;

namespace musclesim::python {

py::dict GaussianDict(const Gaussian& g) {
  return py::dict(py::arg("amplitude") = g.amplitude, py::arg("width") = g.precision,
                  py::arg("center") = g.center);
}

py::dict ParamsDict(const ModelParams& p) {
  // the described fields (model/family_fields.h), then the lists each family reads itself
  py::dict out;
  if (p.family != CurveFamily::kPaper) out["family"] = ToString(p.family);
  AddFields(*VariantOf(ModelFamilies(), p), p, out);
  if (p.family == CurveFamily::kMujoco) {
    out["range"] = py::make_tuple(p.mujoco.range[0], p.mujoco.range[1]);
    out["lengthrange"] = py::make_tuple(p.mujoco.lengthrange[0], p.mujoco.lengthrange[1]);
  } else if (p.family == CurveFamily::kPaper) {
    py::list gaussians;
    for (const Gaussian& g : p.active_length.gaussians) gaussians.append(GaussianDict(g));
    py::dict active = out["active_length"].cast<py::dict>();
    active["optimal_range"] =
        py::make_tuple(p.active_length.optimal_min, p.active_length.optimal_max);
    active["gaussians"] = gaussians;
  }
  return out;
}

}  // namespace musclesim::python
