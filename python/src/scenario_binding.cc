#include "bindings.h"

namespace musclesim::python {

void BindScenario(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
