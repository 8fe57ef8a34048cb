// Identification from measured series (to be written).
#include "bindings.h"

namespace musclesim::python {

void BindIdentifySeries(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
