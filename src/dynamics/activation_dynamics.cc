#include "musclesim/dynamics/activation_dynamics.h"

#include <cmath>
#include <string>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/activation_families.h"

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
  ValidateFields(*VariantOf(ActivationFamilies(), d), d);
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
