// Figures drawn by gnuplot (to be written).
#include "bindings.h"

namespace musclesim::python {

void BindPlot(pybind11::module_& /*m*/) {}

}  // namespace musclesim::python
