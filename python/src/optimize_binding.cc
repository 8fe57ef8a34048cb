// musclesim._optimize: optimal control of a Scenario in memory (docs/guide/optimize.md), the
// GIL released while IPOPT and CVODES work. musclesim.optimize checks the dicts and is the
// public way.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.h"
#include "musclesim/io/document.h"
#include "musclesim/core/errors.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/optimize/optimum_files.h"
#include "py_scenario.h"

namespace musclesim::python {

namespace py = pybind11;

using ControlTuple = std::tuple<std::string, double, double, double, int>;
using FinalTuple = std::tuple<std::string, double, double>;  // also a path bound, a parameter
using TrackingTuple = std::tuple<std::string, std::vector<double>, std::vector<double>, double>;
using TerminalTuple = std::tuple<std::string, double, double>;
using TimeTuple = std::tuple<double, double, double>;

// The terms and constraints beyond the controls and final values, from their tuples.
void AddTerms(OptimalControlProblem& problem, const std::vector<FinalTuple>& paths,
              const std::vector<TrackingTuple>& tracking,
              const std::vector<TerminalTuple>& terminal, const std::vector<FinalTuple>& parameters,
              const std::optional<TimeTuple>& time) {
  for (const auto& [column, lower, upper] : paths) {
    problem.path_bounds.push_back({column, lower, upper});
  }
  for (const auto& [column, times, values, weight] : tracking) {
    if (times.size() != values.size()) {
      throw InputError("tracking: " + column +
                       ": the reference's times and values differ in "
                       "length");
    }
    std::vector<TablePoint> reference;
    for (std::size_t i = 0; i < times.size(); ++i) reference.push_back({times[i], values[i]});
    problem.tracking.push_back({column, std::move(reference), weight});
  }
  for (const auto& [column, target, weight] : terminal) {
    problem.terminal.push_back({column, target, weight});
  }
  for (const auto& [path, lower, upper] : parameters) {
    problem.parameters.push_back({path, lower, upper});
  }
  if (time)
    problem.final_time = FreeFinalTime{std::get<0>(*time), std::get<1>(*time), std::get<2>(*time)};
}

py::array_t<double> Array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

void BindOptimize(py::module_& m) {
  m.def(
      "_optimize",
      [](const py::handle& scenario, const std::vector<ControlTuple>& controls,
         const std::vector<FinalTuple>& finals, int intervals, double tolerance, int max_iterations,
         const std::vector<FinalTuple>& paths, const std::vector<TrackingTuple>& tracking,
         const std::vector<TerminalTuple>& terminal, const std::vector<FinalTuple>& parameters,
         const std::optional<TimeTuple>& time) {
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
        AddTerms(problem, paths, tracking, terminal, parameters, time);
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
        py::dict terms;
        terms["effort"] = result.terms.effort;
        terms["tracking"] = result.terms.tracking;
        terms["terminal"] = result.terms.terminal;
        terms["final_time"] = result.terms.final_time;
        out["terms"] = terms;
        out["dual_infeasibility"] = result.dual_infeasibility;
        out["gradient_check"] = result.gradient_check;
        out["resimulation_deviation"] = result.resimulation_deviation;
        out["final_time"] = result.final_time;
        py::dict chosen;
        for (std::size_t q = 0; q < result.parameter_values.size(); ++q) {
          chosen[py::str(problem.parameters[q].path)] = result.parameter_values[q];
        }
        out["parameters"] = chosen;
        const auto n = static_cast<py::ssize_t>(result.state_size);
        py::array_t<double> states(
            {n > 0 ? static_cast<py::ssize_t>(result.states.size()) / n : 0, n});
        std::copy(result.states.begin(), result.states.end(), states.mutable_data());
        out["states"] = states;
        out["constraint_violation"] = result.constraint_violation;
        out["largest_violation"] = result.largest_violation;
        out["infeasible"] = result.infeasible;
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
        PyScenario optimum = DocumentPyScenario(std::move(document), given.display + " (optimum)");
        for (std::size_t q = 0; q < result.parameter_values.size(); ++q) {
          optimum.Set(problem.parameters[q].path, py::float_(result.parameter_values[q]));
        }
        if (problem.final_time && !result.times.empty()) {
          optimum.Set("time.end", py::float_(result.final_time));
        }
        out["scenario"] = py::cast(std::move(optimum));
        return out;
      },
      py::arg("scenario"), py::arg("controls"), py::arg("final_values"), py::arg("intervals"),
      py::arg("tolerance"), py::arg("max_iterations"), py::arg("path_bounds"), py::arg("tracking"),
      py::arg("terminal"), py::arg("parameters"), py::arg("final_time"),
      "optimize's C++ half: controls as (actuator, lower, upper, weight, power), final values "
      "and path bounds as (column, lower, upper), tracking as (column, times, values, weight), "
      "terminal as (column, target, weight), parameters as (path, lower, upper), final_time "
      "None or (lower, upper, weight); returns a dict of the result with the optimum as a "
      "Scenario. musclesim.optimize is the public way.");
}

}  // namespace musclesim::python
