// Identification from measured curves (to be written).
#include "bindings.h"

namespace musclesim::python {

void BindIdentifyCurves(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
