#include "musclesim/dynamics/activation_dynamics.h"

#include <cmath>
#include <string>
#include <utility>

#include "musclesim/core/errors.h"

namespace musclesim {

const char* ActivationFamilyName(ActivationFamily family) {
  switch (family) {
    case ActivationFamily::kDeGroote2016: return "degroote2016";
    case ActivationFamily::kMujoco: return "mujoco";
    case ActivationFamily::kThelen2003: break;
  }
  return "thelen2003";
}

void Validate(const ActivationDynamics& d) {
  const std::string rule = "must be from " + FormatNumber(kMinActivationTimeConstant) + " to " +
                           FormatNumber(kMaxActivationTimeConstant) +
                           " [s]: muscles take 5 to 60 ms; shorter is in effect instantaneous "
                           "(give the activation itself), longer is no muscle-like actuator";
  for (const auto& [key, value] : {std::pair{"tau_activation", d.tau_activation},
                                   std::pair{"tau_deactivation", d.tau_deactivation}}) {
    Require(value >= kMinActivationTimeConstant && value <= kMaxActivationTimeConstant, key, value,
            rule);
  }
  if (d.family == ActivationFamily::kDeGroote2016) {
    Require(kActivationSmoothingRange.Contains(d.smoothing), "smoothing", d.smoothing,
            kActivationSmoothingRange.Rule());
  }
  if (d.family == ActivationFamily::kMujoco) {
    Require(kTauSmoothRange.Contains(d.tausmooth), "tausmooth", d.tausmooth,
            kTauSmoothRange.Rule());
  }
}

void Validate(const ExcitationInput& input) {
  try {
    ValidateExcitation(input.signal);
  } catch (const ParameterError& e) {
    throw ParameterError("excitation." + e.path(), e.value(), e.rule());
  }
  try {
    Validate(input.dynamics);
  } catch (const ParameterError& e) {
    throw ParameterError("activation_dynamics." + e.path(), e.value(), e.rule());
  }
  if (input.initial_activation) {
    Require(*input.initial_activation >= 0.0 && *input.initial_activation <= 1.0,
            "initial_activation", *input.initial_activation,
            "must be within [0, 1]: an activation is a fraction of the full one");
  }
}

}  // namespace musclesim
