// The extension module musclesim._musclesim; the package musclesim (python/musclesim/)
// re-exports it with a few pure-Python helpers.
#include "bindings.h"

PYBIND11_MODULE(_musclesim, m) {
  m.doc() =
      "musclesim: muscle-like actuator tension, networks and control, on SUNDIALS CVODES. "
      "SI units throughout: lengths in m, speeds in m/s, forces in N, times in s; activations "
      "and excitations in [0, 1]. A shortening velocity v is positive when the actuator "
      "shortens.";
  // the CMake project's version, as `musclesim --version` prints it
  m.attr("__version__") = MUSCLESIM_VERSION;
  musclesim::python::RequireSupportedNumpy(m);
  musclesim::python::BindErrors(m);
  musclesim::python::BindModel(m);
  musclesim::python::BindScenario(m);
  musclesim::python::BindStepper(m);
  musclesim::python::BindSweep(m);
  musclesim::python::BindOptimize(m);
  musclesim::python::BindIdentifyCurves(m);
  musclesim::python::BindIdentifySeries(m);
  musclesim::python::BindPlot(m);
  musclesim::python::RefuseUninitialisedObjects(m);
}
