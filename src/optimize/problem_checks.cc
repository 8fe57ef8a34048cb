#include "optimize/problem_checks.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/memory.h"
#include "musclesim/core/number_format.h"
#include "scenario/sensitivity_columns.h"
#include "scenario/sensitivity_derivatives.h"

namespace musclesim {

namespace {

// A fault of the problem's entry `key`; the problem's reader places it in the file.
[[noreturn]] void Fail(const std::string& key, std::optional<std::string> value,
                       const std::string& rule) {
  throw InputError(InputFault{std::nullopt, key, std::move(value), rule});
}

std::string Entry(const char* list, std::size_t i, const char* key) {
  std::string path = list;
  path.append("[").append(std::to_string(i)).append("].").append(key);
  return path;
}

std::string Range(double lower, double upper) {
  std::string text = "[";
  text.append(FormatNumber(lower)).append(", ").append(FormatNumber(upper)).append("]");
  return text;
}

void CheckWeight(double weight, const std::string& path) {
  if (!(std::isfinite(weight) && weight >= 0.0)) {
    Fail(path, FormatNumber(weight), "must be a finite number >= 0");
  }
}

void CheckBounds(double lower, double upper, const std::string& path) {
  if (std::isnan(lower) || std::isnan(upper) || lower > upper) {
    Fail(path, Range(lower, upper), "must be numbers with lower <= upper");
  }
}

// The differentiated columns of the problem's scenario, and the entry of `column` among the
// problem's columns (added on first use).
class ColumnResolver {
 public:
  ColumnResolver(const OptimalControlProblem& problem, const NetworkSystem& system,
                 ProblemIndex& index)
      : columns_(problem.scenario.form, system, no_parameters_),
        free_time_(problem.final_time.has_value()),
        index_(index) {}

  int Resolve(const std::string& column, const std::string& path) {
    const std::vector<std::string>& names = columns_.names();
    const auto found = std::find(names.begin(), names.end(), column);
    if (found == names.end()) {
      std::string known;
      for (std::size_t c = 0; c < names.size() && c < 12; ++c) {
        known.append(c > 0 ? ", " : "").append(names[c]);
      }
      if (names.size() > 12) known += ", ...";
      Fail(path, column,
           "is no differentiated column of the scenario (a free node's coordinate or "
           "velocity, an element's length or tension, ...): " +
               known);
    }
    const int c = static_cast<int>(found - names.begin());
    double sign = 1.0;
    const int state = columns_.StateOf(static_cast<std::size_t>(c), sign);
    if (free_time_ && state < 0) {
      Fail(path, column,
           "with a free final time, a column must be a state (a free node's coordinate or "
           "velocity, an activation with dynamics)");
    }
    const auto known = std::find(index_.columns.begin(), index_.columns.end(), c);
    if (known != index_.columns.end()) return static_cast<int>(known - index_.columns.begin());
    index_.columns.push_back(c);
    index_.column_states.push_back(state);
    index_.column_signs.push_back(sign);
    return static_cast<int>(index_.columns.size()) - 1;
  }

 private:
  std::vector<SensitivityParameter> no_parameters_;
  SensitivityColumns columns_;
  bool free_time_;
  ProblemIndex& index_;
};

void CheckControls(const OptimalControlProblem& problem, const NetworkSystem& system,
                   ProblemIndex& index) {
  if (problem.controls.empty()) Fail("controls", std::nullopt, "at least one control is needed");
  if (system.junction_count() > 0) {
    // the optimiser's gradients come from sensitivities, which do not take junctions yet
    Fail("scenario", std::nullopt,
         "a network with a massless junction (a node of mass 0) cannot "
         "be optimised yet: its sensitivities are not derived; give the node a mass");
  }
  if (system.skeleton() != nullptr) {
    // nor skeletons' (docs/model.md 15.5): the gradients would miss the bodies
    Fail("scenario", std::nullopt,
         "a scenario with bodies, joints or wrap surfaces cannot be optimised yet: its "
         "sensitivities are not derived (docs/guide/skeletons.md)");
  }
  for (std::size_t j = 0; j < problem.controls.size(); ++j) {
    const ControlSpec& control = problem.controls[j];
    const std::string path = Entry("controls", j, "actuator");
    const int e = system.FindElement(control.actuator);
    if (e < 0 || system.elements()[static_cast<std::size_t>(e)].kind != ElementKind::kActuator) {
      Fail(path, control.actuator, "is no actuator of the scenario");
    }
    const Element& element = system.elements()[static_cast<std::size_t>(e)];
    if (element.controlled) {
      Fail(path, control.actuator,
           "is driven by a controller: a control of the optimiser must be free");
    }
    if (std::find(index.elements.begin(), index.elements.end(), e) != index.elements.end()) {
      Fail(path, control.actuator, "is controlled twice");
    }
    if (!(0.0 <= control.lower && control.lower <= control.upper && control.upper <= 1.0)) {
      Fail(Entry("controls", j, "bounds"), Range(control.lower, control.upper),
           "must satisfy 0 <= lower <= upper <= 1");
    }
    CheckWeight(control.effort_weight, Entry("controls", j, "effort.weight"));
    if (control.effort_power != 2 && control.effort_power != 3) {
      Fail(Entry("controls", j, "effort.power"), std::to_string(control.effort_power),
           "must be 2 or 3");
    }
    index.elements.push_back(e);
    index.activation_states.push_back(system.ActivationStateIndex(e));
    // with activation dynamics and no initial activation given, u(t_start) = e(t_start): the
    // first control value moves the initial state
    index.moves_start.push_back(element.excitation && !element.excitation->initial_activation ? 1
                                                                                              : 0);
  }
}

void CheckTracking(const OptimalControlProblem& problem, ColumnResolver& columns,
                   ProblemIndex& index) {
  for (std::size_t k = 0; k < problem.tracking.size(); ++k) {
    const TrackingTerm& term = problem.tracking[k];
    if (problem.final_time) {
      Fail(Entry("tracking", k, "column"), std::nullopt,
           "a tracking term needs a fixed final time (its reference is a "
           "record over a fixed span)");
    }
    index.tracked.push_back(columns.Resolve(term.column, Entry("tracking", k, "column")));
    CheckWeight(term.weight, Entry("tracking", k, "weight"));
    const std::vector<TablePoint>& r = term.reference;
    const std::string at = Entry("tracking", k, "reference");
    if (r.size() < 2) Fail(at, std::nullopt, "needs at least 2 points (t, value)");
    if (r.size() > kMaxReferencePoints) {
      Fail(at, std::nullopt,
           std::to_string(r.size()) + " points, more than the " +
               std::to_string(kMaxReferencePoints) +
               " a reference may hold: each point cuts the cost's quadrature (5 samples "
               "of the trajectory and its sensitivities), so every iteration grows with "
               "them; resample the record");
    }
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!std::isfinite(r[i].t) || !std::isfinite(r[i].value) || (i > 0 && r[i].t <= r[i - 1].t)) {
        Fail(at, std::nullopt,
             "point " + std::to_string(i) + " (t = " + FormatNumber(r[i].t) +
                 "): times must be finite and strictly increasing, values finite");
      }
    }
    if (r.front().t > problem.scenario.t_start || r.back().t < problem.scenario.t_end) {
      Fail(at, std::nullopt,
           "covers " + Range(r.front().t, r.back().t) + " s but must cover the span " +
               Range(problem.scenario.t_start, problem.scenario.t_end) + " s");
    }
  }
}

// The program's memory, refused before it is allocated when the machine cannot hold it: per
// interval its plan, its state's and columns' sensitivities (n + K values each, K = n + 2
// controls + parameters) kept for the constraint Jacobian and IPOPT's copies of its blocks,
// and a tracked column's samples at every quadrature point (measured: 4 KiB per interval for
// the antagonist pair's 2 states and 2 controls, which this counts as 6 KiB).
void RequireRoomForGrid(const OptimalControlProblem& problem, const NetworkSystem& system,
                        const ProblemIndex& index) {
  const double n = system.state_size();
  const double k = n + 2.0 * static_cast<double>(problem.controls.size()) +
                   static_cast<double>(problem.parameters.size());
  double samples = 0.0;  // quadrature points over the whole span, per tracked column
  for (const TrackingTerm& term : problem.tracking) {
    samples += 5.0 * (static_cast<double>(term.reference.size()) + problem.intervals);
  }
  const double columns = static_cast<double>(index.columns.size());
  const double bytes =
      problem.intervals * (4096.0 + 64.0 * (n + k) * (n + k)) + 8.0 * samples * columns * (k + 1.0);
  const double allowed = AllocatableBytes();
  if (bytes <= allowed) return;
  Fail("intervals", std::to_string(problem.intervals),
       "the program needs about " + MebibytesText(bytes) + " for its " +
           std::to_string(problem.intervals) + " intervals of " + FormatNumber(n) +
           " states, more than the " + MebibytesText(allowed) +
           " this process may allocate: use fewer intervals");
}

void CheckParameters(const OptimalControlProblem& problem, ProblemIndex& index) {
  for (std::size_t k = 0; k < problem.parameters.size(); ++k) {
    const FreeParameter& free = problem.parameters[k];
    const std::string path = Entry("parameters", k, "path");
    Parameter handle = [&] {
      try {
        return FindParameter(problem.scenario, free.path);
      } catch (const ParameterError& e) {
        Fail(path, std::nullopt, e.what());
      }
    }();
    if (handle.is_setting() || handle.is_integer()) {
      Fail(path, free.path,
           "is a setting of the run or an integer, not a number the optimiser can move");
    }
    CheckBounds(free.lower, free.upper, Entry("parameters", k, "bounds"));
    for (std::size_t j = 0; j < index.elements.size(); ++j) {
      // the control replaces that activation (or excitation): the number would do nothing
      const std::string element = "elements[" + std::to_string(index.elements[j]) + "].";
      for (const char* drive : {"activation", "excitation"}) {
        if (handle.network_path().rfind(element + drive + ".", 0) == 0) {
          Fail(path, free.path,
               std::string("is part of the ") + drive + " of " + problem.controls[j].actuator +
                   ", which the control replaces: it cannot be a free parameter");
        }
      }
    }
    // both bounds must be values the scenario accepts: every point IPOPT tries lies between
    for (const double bound : {free.lower, free.upper}) {
      Scenario copy = problem.scenario;
      try {
        handle.Set(copy, bound);
      } catch (const ParameterError& e) {
        Fail(Entry("parameters", k, "bounds"), Range(free.lower, free.upper),
             FormatNumber(bound) + " is no valid value of " + free.path + ": " + e.rule());
      }
    }
    for (const Parameter& other : index.parameters) {
      if (other.network_path() == handle.network_path()) {
        Fail(path, free.path, "is free twice");
      }
    }
    // resolved once here, so that a parameter no run can differentiate (one that moves an
    // input's breakpoint, say) is refused now rather than at every point
    ResolveParameter(problem.scenario, BuildScenario(problem.scenario), handle, path);
    index.parameters.push_back(std::move(handle));
  }
}

}  // namespace

ProblemIndex CheckProblem(const OptimalControlProblem& problem) {
  if (problem.intervals < 1 || problem.intervals > 100000) {
    Fail("intervals", std::to_string(problem.intervals), "must be an integer in [1, 100000]");
  }
  const NetworkSystem system = problem.scenario.Build();
  ProblemIndex index;
  CheckControls(problem, system, index);
  if (const std::optional<FreeFinalTime>& time = problem.final_time) {
    CheckBounds(time->lower, time->upper, "final_time.bounds");
    if (!(std::isfinite(time->upper) && time->lower > problem.scenario.t_start)) {
      Fail("final_time.bounds", Range(time->lower, time->upper),
           "must be finite and after the start, " + FormatNumber(problem.scenario.t_start) + " s");
    }
    CheckWeight(time->weight, "final_time.weight");
    for (const double bound : {time->lower, time->upper}) {
      // the scenario must run to either bound (its output grid, its limits)
      Scenario copy = problem.scenario;
      copy.t_end = bound;
      try {
        copy.Validate();
      } catch (const ParameterError& e) {
        Fail("final_time.bounds", Range(time->lower, time->upper),
             FormatNumber(bound) + " s as the final time breaks the scenario: " + e.path() + ": " +
                 e.rule());
      }
    }
  }
  ColumnResolver columns(problem, system, index);
  for (std::size_t k = 0; k < problem.final_values.size(); ++k) {
    const FinalValue& final = problem.final_values[k];
    index.finals.push_back(columns.Resolve(final.column, Entry("final_values", k, "column")));
    CheckBounds(final.lower, final.upper, Entry("final_values", k, "bounds"));
  }
  for (std::size_t k = 0; k < problem.path_bounds.size(); ++k) {
    const PathBound& bound = problem.path_bounds[k];
    index.paths.push_back(columns.Resolve(bound.column, Entry("path_bounds", k, "column")));
    CheckBounds(bound.lower, bound.upper, Entry("path_bounds", k, "bounds"));
  }
  CheckTracking(problem, columns, index);
  for (std::size_t k = 0; k < problem.terminal.size(); ++k) {
    const TerminalTerm& term = problem.terminal[k];
    index.terminals.push_back(columns.Resolve(term.column, Entry("terminal", k, "column")));
    CheckWeight(term.weight, Entry("terminal", k, "weight"));
    if (!std::isfinite(term.target)) {
      Fail(Entry("terminal", k, "target"), std::nullopt, "must be a finite number");
    }
  }
  CheckParameters(problem, index);
  RequireRoomForGrid(problem, system, index);
  return index;
}

}  // namespace musclesim
