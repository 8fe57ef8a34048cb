#include "bindings.h"

namespace musclesim::python {

void BindModel(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
