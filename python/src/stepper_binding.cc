#include "bindings.h"

namespace musclesim::python {

void BindStepper(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
