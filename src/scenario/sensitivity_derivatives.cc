#include "scenario/sensitivity_derivatives.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

// The relative step of a difference quotient: the cube root of the machine epsilon balances
// a central quotient's truncation error (h^2) against rounding (eps / h).
constexpr double kRelativeStep = 6e-6;

// d/dp at `at` of the interpolating polynomial through `points`: weight_i of value_i.
std::vector<double> DerivativeWeights(const std::vector<double>& points, double at) {
  std::vector<double> weights(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // L_i'(at) = sum over k != i of 1/(x_i - x_k) prod over m != i, k of (at - x_m)/(x_i - x_m)
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (k == i) continue;
      double term = 1.0 / (points[i] - points[k]);
      for (std::size_t m = 0; m < points.size(); ++m) {
        if (m != i && m != k) term *= (at - points[m]) / (points[i] - points[m]);
      }
      weights[i] += term;
    }
  }
  return weights;
}

// The scenario with the parameter at one nearby value, or why that value is not valid.
struct NearbyPoint {
  double value = 0.0;
  std::optional<BuiltScenario> built;
  std::string error;
};

NearbyPoint BuildAt(const Scenario& scenario, const Parameter& parameter, double value) {
  NearbyPoint point{value, std::nullopt, ""};
  try {
    Scenario moved = scenario;
    parameter.Set(moved, value);
    point.built = BuildScenario(moved);
  } catch (const ParameterError& e) {
    point.error = e.what();
  }
  return point;
}

// The points of the quotient: central where both sides are valid values, else one-sided of
// second order (a damping of 0 cannot go below it).
// A fault of the parameter, its message headed by `where` (and " = VALUE" when its value is
// at fault).
[[noreturn]] void Fail(const std::string& where, const Parameter& parameter,
                       std::optional<double> value, const std::string& rule) {
  const std::optional<std::string> text =
      value ? std::optional<std::string>(FormatNumber(*value)) : std::nullopt;
  throw InputError((text ? where + " = " + *text : where) + ": ",
                   InputFault{std::nullopt, parameter.path(), text, rule});
}

std::vector<NearbyPoint> StencilPoints(const Scenario& scenario, const BuiltScenario& base,
                                       const Parameter& parameter, double value, double size,
                                       const std::string& where) {
  const double h = kRelativeStep * ParameterSize(value, size);
  NearbyPoint below = BuildAt(scenario, parameter, value - h);
  NearbyPoint above = BuildAt(scenario, parameter, value + h);
  if (below.built && above.built && base.system->junction_count() > 0) {
    // a junction's velocity moves with p through its balance, often hundreds of times faster
    // than the states do, and the force-velocity curve bends over that motion: a central
    // quotient's h^2 error would then reach 1e-6 of df/dp (and 1e-5 of the sensitivities
    // integrated), so four points, h^4
    NearbyPoint far_below = BuildAt(scenario, parameter, value - 2.0 * h);
    NearbyPoint far_above = BuildAt(scenario, parameter, value + 2.0 * h);
    if (far_below.built && far_above.built) {
      return {std::move(far_below), std::move(below), std::move(above), std::move(far_above)};
    }
  }
  if (below.built && above.built) return {std::move(below), std::move(above)};
  if (!above.built && !below.built) {
    Fail(where, parameter, value,
         "cannot change continuously (an integer, or a value at the edge of its range on both "
         "sides), so it has no sensitivity; near it: " +
             below.error);
  }
  const double direction = above.built ? 1.0 : -1.0;
  NearbyPoint near = above.built ? std::move(above) : std::move(below);
  NearbyPoint far = BuildAt(scenario, parameter, value + 2.0 * direction * h);
  if (!far.built) {
    Fail(where, parameter, value,
         "no neighbourhood of valid values to differentiate in: " + far.error);
  }
  return {NearbyPoint{value, base, ""}, std::move(near), std::move(far)};
}

void AddDifferenceQuotient(const Scenario& scenario, const BuiltScenario& base,
                           const Parameter& parameter, double size, const std::string& where,
                           ResolvedParameter& out) {
  const std::vector<NearbyPoint> points =
      StencilPoints(scenario, base, parameter, out.value, size, where);
  const std::vector<double> breakpoints =
      base.system->Breakpoints(scenario.t_start, scenario.t_end);
  std::vector<double> values;
  for (const NearbyPoint& point : points) {
    const NetworkSystem& moved = *point.built->system;
    if (moved.Breakpoints(scenario.t_start, scenario.t_end) != breakpoints ||
        moved.state_size() != base.system->state_size()) {
      Fail(where, parameter, std::nullopt,
           "moves when an input jumps (a breakpoint of an activation, excitation, load or "
           "motion): the sensitivity jumps there (docs/model.md 10), which musclesim does not "
           "compute; differentiate by a value the times do not depend on");
    }
    values.push_back(point.value);
  }
  const std::vector<double> weights = DerivativeWeights(values, out.value);
  DifferenceQuotientDerivative::Stencil stencil;
  out.initial.assign(base.initial.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    stencil.push_back({points[i].built->system, weights[i], points[i].value - out.value});
    for (std::size_t k = 0; k < out.initial.size(); ++k) {
      out.initial[k] += weights[i] * points[i].built->initial[k];
    }
  }
  out.derivative = std::make_unique<DifferenceQuotientDerivative>(std::move(stencil));
  out.source = DerivativeSource::kDifferenceQuotient;
}

// The closed form of df/dp, when the parameter has one.
std::unique_ptr<ParameterDerivative> ClosedForm(const Scenario& scenario,
                                                const NetworkSystem& system,
                                                const Parameter& parameter) {
  if (!parameter.model().empty() && !parameter.is_integer()) {
    const ScenarioModel& block = scenario.models.at(parameter.model());
    // a fitted block's Gaussians follow its range and sigma through the fit, which the closed
    // form of a fixed sum does not see
    if (block.spec.fit && parameter.model_path().rfind("active_length.", 0) == 0) return nullptr;
    return ModelParameterDerivative(system, block.model.get(), parameter.model_path());
  }
  if (parameter.element() >= 0) {
    return ElementParameterDerivative(system, parameter.element(), parameter.element_path());
  }
  return nullptr;
}

}  // namespace

BuiltScenario BuildScenario(const Scenario& scenario, std::shared_ptr<const NetworkSystem> system) {
  BuiltScenario built;
  if (!system) system = std::make_shared<const NetworkSystem>(scenario.Build());
  built.initial.resize(static_cast<std::size_t>(system->state_size()));
  system->InitialState(scenario.t_start, built.initial.data());
  built.system = std::move(system);
  return built;
}

double ParameterSize(double value, double size) {
  const double larger = std::max(std::abs(value), std::abs(size));
  return larger > 0.0 ? larger : 1.0;
}

ResolvedParameter ResolveParameter(const Scenario& scenario, const BuiltScenario& base,
                                   const Parameter& parameter, const std::string& where,
                                   double size) {
  if (parameter.is_setting()) {
    Fail(where, parameter, std::nullopt,
         "a setting of the run, not a parameter of its dynamics: it has no sensitivity");
  }
  ResolvedParameter out;
  out.path = parameter.path();
  out.value = parameter.Get(scenario);
  if (!std::isfinite(out.value)) {
    Fail(where, parameter, out.value, "not a finite number: it has no sensitivity");
  }
  // a massless junction's velocity moves with the parameter through its balance, which the
  // closed forms leave out: a difference quotient re-solves it at p +- h
  if (base.system->junction_count() == 0) {
    out.derivative = ClosedForm(scenario, *base.system, parameter);
  }
  if (out.derivative != nullptr) {
    // no model or element coefficient moves the initial state
    out.initial.assign(base.initial.size(), 0.0);
    return out;
  }
  AddDifferenceQuotient(scenario, base, parameter, size, where, out);
  return out;
}

}  // namespace musclesim
