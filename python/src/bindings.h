// The parts of the Python module, one source each; module.cc calls them in this order.
#pragma once

#include <pybind11/pybind11.h>

namespace musclesim::python {

// First: refuses to import under a NumPy this build's pybind11 cannot serve (numpy_support.cc).
void RequireSupportedNumpy(pybind11::module_& m);
// musclesim.InputError and ParameterError: C++ exceptions translated.
void BindErrors(pybind11::module_& m);
// Tension curves on NumPy arrays with their derivatives; the closed-form Gaussian fit.
void BindModel(pybind11::module_& m);
// Scenarios from files or dicts, changed with set(), run to NumPy columns; sensitivities.
void BindScenario(pybind11::module_& m);
// Stepping a network from a Python loop.
void BindStepper(pybind11::module_& m);
// Many scenarios, or a sweep file, on every core with the GIL released.
void BindSweep(pybind11::module_& m);
// musclesim._optimize (optimize_binding.cc)
void BindOptimize(pybind11::module_& m);
// Model parameters identified from measured curves (`musclesim identify` on curves).
void BindIdentifyCurves(pybind11::module_& m);
// Scenario parameters identified from measured time series (`musclesim identify` on series).
void BindIdentifySeries(pybind11::module_& m);
// Figures drawn by gnuplot, as `musclesim plot` draws them.
void BindPlot(pybind11::module_& m);
// Last: every bound type raises TypeError when used without its constructor having run.
void RefuseUninitialisedObjects(pybind11::module_& m);

}  // namespace musclesim::python
