// Private: one parameter of a run with sensitivities (docs/model.md 10) resolved through its
// handle into its right-hand-side derivative, closed form for a tension model's or an
// element's own coefficient, else a difference quotient over copies of the scenario set at
// nearby values, and its initial sensitivity.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"

namespace musclesim {

// A scenario as integrated: its system and the state it starts from.
struct BuiltScenario {
  std::shared_ptr<const NetworkSystem> system;
  std::vector<double> initial;  // y(t_start)
};
// `system`, when given, is scenario.Build()'s; otherwise it is built.
BuiltScenario BuildScenario(const Scenario& scenario,
                            std::shared_ptr<const NetworkSystem> system = nullptr);

struct ResolvedParameter {
  std::string path;    // written one way
  double value = 0.0;  // in the scenario
  DerivativeSource source = DerivativeSource::kAnalytic;
  std::unique_ptr<ParameterDerivative> derivative;
  std::vector<double> initial;  // dy(t_start)/dp
};

// The magnitude a parameter's changes are measured against: max(|value|, size), 1 where
// both are 0 (SensitivityRequest::size).
double ParameterSize(double value, double size);

// Resolves `parameter` of `scenario`, whose system `base` is (the models it holds are the
// scenario's); a difference quotient steps by a fraction of ParameterSize(value, size).
// `where` heads messages ("--sensitivity model.f_iso"). Throws InputError for a path that
// names no number of the dynamics, a setting, a value that cannot move, or one that moves an
// input breakpoint or changes the state's size.
ResolvedParameter ResolveParameter(const Scenario& scenario, const BuiltScenario& base,
                                   const Parameter& parameter, const std::string& where,
                                   double size = 0.0);

}  // namespace musclesim
