// musclesim._optimize: optimal control of a Scenario in memory (docs/guide/optimize.md), the
// GIL released while IPOPT and CVODES work. musclesim.optimize checks the dicts and is the
// public way.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.h"
#include "musclesim/io/document.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/optimize/optimum_files.h"
#include "py_scenario.h"

namespace musclesim::python {

namespace py = pybind11;

using ControlTuple = std::tuple<std::string, double, double, double, int>;
using FinalTuple = std::tuple<std::string, double, double>;

void BindOptimize(py::module_& m) {
  m.def(
      "_optimize",
      [](const py::handle& scenario, const std::vector<ControlTuple>& controls,
         const std::vector<FinalTuple>& finals, int intervals, double tolerance,
         int max_iterations) {
        const PyScenario& given = ScenarioArgument(scenario, "optimize: scenario");
        OptimalControlProblem problem;
        problem.scenario = given.scenario;
        problem.intervals = intervals;
        for (const auto& [actuator, lower, upper, weight, power] : controls) {
          problem.controls.push_back({actuator, lower, upper, weight, power});
        }
        for (const auto& [column, lower, upper] : finals) {
          problem.final_values.push_back({column, lower, upper});
        }
        OptimizeOptions options;
        options.tolerance = tolerance;
        options.max_iterations = max_iterations;
        OptimalControlResult result;
        {
          py::gil_scoped_release released;
          result = SolveOptimalControl(problem, options);
        }
        py::dict out;
        out["status"] = result.status;
        out["solved"] = result.solved;
        out["objective"] = result.objective;
        out["constraint_violation"] = result.constraint_violation;
        out["iterations"] = result.iterations;
        out["times"] =
            py::array_t<double>(static_cast<py::ssize_t>(result.times.size()), result.times.data());
        py::dict values;
        for (std::size_t j = 0; j < result.controls.size(); ++j) {
          values[py::str(problem.controls[j].actuator)] = py::array_t<double>(
              static_cast<py::ssize_t>(result.controls[j].size()), result.controls[j].data());
        }
        out["controls"] = values;
        // the optimum: the given scenario's document (its set() values in) with each
        // control's activation its table, so that to_yaml() and pickling write it
        Document document;
        {
          py::gil_scoped_release released;
          document =
              WithControlTables(ParseDocument(given.display, given.ToYaml()), problem, result);
        }
        // DocumentPyScenario keeps the document as Python sees it: with the GIL
        out["scenario"] =
            py::cast(DocumentPyScenario(std::move(document), given.display + " (optimum)"));
        return out;
      },
      py::arg("scenario"), py::arg("controls"), py::arg("final_values"), py::arg("intervals"),
      py::arg("tolerance"), py::arg("max_iterations"),
      "optimize's C++ half: controls as (actuator, lower, upper, weight, power), final values "
      "as (column, lower, upper); returns a dict of the result with the optimum as a Scenario. "
      "musclesim.optimize is the public way.");
}

}  // namespace musclesim::python
