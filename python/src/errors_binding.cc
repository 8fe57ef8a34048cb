#include "bindings.h"

namespace musclesim::python {

void BindErrors(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
