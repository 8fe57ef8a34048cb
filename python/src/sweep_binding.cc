#include "bindings.h"

namespace musclesim::python {

void BindSweep(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
