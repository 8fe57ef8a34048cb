#include "optimize/shooting_parts.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "musclesim/core/errors.h"

namespace musclesim {

void InitialStateDerivative::RightHandSide(double, const double*, double* dfdp) const {
  std::fill(dfdp, dfdp + state_size_, 0.0);
}

double ControlValueDerivative::Weight(double t) const {
  const double rising = std::clamp((t - t0_) / (t1_ - t0_), 0.0, 1.0);
  return at_end_ ? rising : 1.0 - rising;
}

double ControlValueDerivative::TensionSlope(double t, const double* y) const {
  ElementSample sample;
  system_.ObserveElement(element_, t, y, sample);
  return sample.parts.d_activation * Weight(t);
}

void ControlValueDerivative::RightHandSide(double t, const double* y, double* dfdp) const {
  std::fill(dfdp, dfdp + system_.state_size(), 0.0);
  system_.AddTension(element_, t, y, TensionSlope(t, y), dfdp);
}

void ControlValueDerivative::Elements(double t, const double* y,
                                      NetworkSystem::ElementPartials* elements) const {
  const double slope = TensionSlope(t, y);
  elements[element_] = {0.0, slope, 0.0, slope};
}

void IntervalEnd::Record(double, const double* y, const double* const* s) {
  state_.assign(y, y + n_);
  sensitivities_.resize(static_cast<std::size_t>(n_) * static_cast<std::size_t>(parameters_));
  for (int p = 0; p < parameters_; ++p) {
    std::copy(s[p], s[p] + n_, sensitivities_.begin() + static_cast<std::ptrdiff_t>(p) * n_);
  }
  recorded_ = true;
}

Effort SegmentEffort(double a, double b, int power) {
  if (power == 2) {
    return {(a * a + a * b + b * b) / 3.0, (2.0 * a + b) / 3.0, (a + 2.0 * b) / 3.0};
  }
  // q = 3, a and b within [0, 1]
  return {(a * a * a + a * a * b + a * b * b + b * b * b) / 4.0,
          (3.0 * a * a + 2.0 * a * b + b * b) / 4.0, (a * a + 2.0 * a * b + 3.0 * b * b) / 4.0};
}

namespace {

std::string Entry(const char* list, std::size_t i, const char* key) {
  std::string path = list;
  path.append("[").append(std::to_string(i)).append("].").append(key);
  return path;
}

// The state index of a free node's column ("mass.position" on a line, "mass.vy" in space).
int ColumnState(const NetworkSystem& system, const std::string& column, const std::string& path) {
  const std::size_t dot = column.rfind('.');
  const std::string node = dot == std::string::npos ? column : column.substr(0, dot);
  const std::string quantity = dot == std::string::npos ? "" : column.substr(dot + 1);
  const int i = system.FindNode(node);
  const int d = system.dimensions();
  int offset = -1;
  if (d == 1) {
    if (quantity == "position") offset = 0;
    if (quantity == "velocity") offset = 1;
  } else {
    constexpr const char* kPositions[] = {"x", "y", "z"};
    constexpr const char* kVelocities[] = {"vx", "vy", "vz"};
    for (int c = 0; c < d; ++c) {
      if (quantity == kPositions[c]) offset = c;
      if (quantity == kVelocities[c]) offset = d + c;
    }
  }
  const std::string columns =
      d == 1 ? "NODE.position or NODE.velocity"
             : (d == 2 ? "NODE.x, .y, .vx or .vy" : "NODE.x, .y, .z, .vx, .vy or .vz");
  if (i < 0 || offset < 0) {
    throw InputError(path + ": '" + column + "' is no node column; a final value is a free " +
                     "node's " + columns);
  }
  if (system.StateIndex(i) < 0) {
    throw InputError(path + ": '" + column + "': node " + node +
                     " is not free (its motion is given, not a state)");
  }
  return system.StateIndex(i) + offset;
}

}  // namespace

NetworkSystem CheckProblem(const OptimalControlProblem& problem, std::vector<int>& elements,
                           std::vector<int>& final_states) {
  if (problem.intervals < 1 || problem.intervals > 100000) {
    throw InputError("intervals: " + std::to_string(problem.intervals) +
                     ": must be an integer in [1, 100000]");
  }
  if (problem.controls.empty()) throw InputError("controls: at least one control is needed");
  const NetworkSystem system = problem.scenario.Build();
  elements.clear();
  for (std::size_t j = 0; j < problem.controls.size(); ++j) {
    const ControlSpec& control = problem.controls[j];
    const std::string path = Entry("controls", j, "actuator");
    const int e = system.FindElement(control.actuator);
    if (e < 0 || system.elements()[static_cast<std::size_t>(e)].kind != ElementKind::kActuator) {
      throw InputError(path + ": '" + control.actuator + "' is no actuator of the scenario");
    }
    const Element& element = system.elements()[static_cast<std::size_t>(e)];
    if (element.excitation || element.controlled || system.ActivationStateIndex(e) >= 0) {
      throw InputError(path + ": '" + control.actuator +
                       "' has activation dynamics or a controller; controlling its excitation "
                       "is not supported yet");
    }
    if (std::find(elements.begin(), elements.end(), e) != elements.end()) {
      throw InputError(path + ": '" + control.actuator + "' is controlled twice");
    }
    if (!(0.0 <= control.lower && control.lower <= control.upper && control.upper <= 1.0)) {
      throw InputError(Entry("controls", j, "bounds") + ": [" + std::to_string(control.lower) +
                       ", " + std::to_string(control.upper) +
                       "]: must satisfy 0 <= lower <= upper <= 1");
    }
    if (!(std::isfinite(control.effort_weight) && control.effort_weight >= 0.0)) {
      throw InputError(Entry("controls", j, "effort_weight") + ": must be a finite number >= 0");
    }
    if (control.effort_power != 2 && control.effort_power != 3) {
      throw InputError(Entry("controls", j, "effort_power") + ": " +
                       std::to_string(control.effort_power) + ": must be 2 or 3");
    }
    elements.push_back(e);
  }
  final_states.clear();
  for (std::size_t k = 0; k < problem.final_values.size(); ++k) {
    const FinalValue& final = problem.final_values[k];
    final_states.push_back(ColumnState(system, final.column, Entry("final_values", k, "column")));
    if (!(std::isfinite(final.lower) && std::isfinite(final.upper) && final.lower <= final.upper)) {
      throw InputError(Entry("final_values", k, "bounds") +
                       ": must be finite numbers with lower <= upper");
    }
  }
  return system;
}

}  // namespace musclesim
