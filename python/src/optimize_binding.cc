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
#include "musclesim/io/readers/document.h"
#include "musclesim/core/errors.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/optimize/optimum_files.h"
#include "document.h"
#include "musclesim/optimize/problem_file.h"
#include "py_scenario.h"

namespace musclesim::python {

namespace py = pybind11;

void BindOptimize(py::module_& m) {
  m.def(
      "_optimize",
      [](const py::handle& scenario, const py::dict& spec) {
        const PyScenario& given = ScenarioArgument(scenario, "optimize: scenario");
        // the problem file's keys, read by its reader: the same rules and messages
        const ProblemFile file =
            ReadProblem(DocumentFrom(spec, "optimize"), "optimize(...)", given.scenario);
        const OptimalControlProblem& problem = file.problem;
        const OptimizeOptions& options = file.options;
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
          document = WithControlTables(given.ToDocument(), problem, result);
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
      py::arg("scenario"), py::arg("problem"),
      "optimize's C++ half: `problem` a dict of a problem file's keys but base and output "
      "(intervals, controls, final_values, path_bounds, tracking, terminal, parameters, "
      "final_time, optimizer), read by the problem file's reader; returns a dict of the "
      "result with the optimum as a Scenario. musclesim.optimize is the public way.");
}

}  // namespace musclesim::python
