#include "musclesim/dynamics/activation_families.h"

namespace musclesim {

namespace {

using Field = NumberField<ActivationDynamics>;

std::vector<Field> TimeConstants() {
  return {
      {"tau_activation", kActivationTimeConstantRange, std::nullopt,
       "tau_act, the lag while the excitation is above the activation",
       [](const ActivationDynamics& d) { return d.tau_activation; },
       [](ActivationDynamics& d, double v) { d.tau_activation = v; }},
      {"tau_deactivation", kActivationTimeConstantRange, std::nullopt,
       "tau_deact, the lag while it is below",
       [](const ActivationDynamics& d) { return d.tau_deactivation; },
       [](ActivationDynamics& d, double v) { d.tau_deactivation = v; }},
  };
}

ActivationFamilyVariant Family(const char* type, ActivationFamily family, const char* law,
                               std::vector<Field> fields) {
  ActivationFamilyVariant variant;
  variant.type = type;
  variant.name = type;
  variant.law = law;
  variant.fields = std::move(fields);
  variant.is = [family](const ActivationDynamics& d) { return d.family == family; };
  variant.make = [family](ActivationDynamics& d) { d.family = family; };
  return variant;
}

}  // namespace

const std::vector<ActivationFamilyVariant>& ActivationFamilies() {
  static const std::vector<ActivationFamilyVariant> families = [] {
    std::vector<Field> degroote = TimeConstants();
    degroote.push_back({"smoothing", kActivationSmoothingRange, 0.1,
                        "b, the steepness of the tanh blend (OpenSim's default 0.1)",
                        [](const ActivationDynamics& d) { return d.smoothing; },
                        [](ActivationDynamics& d, double v) { d.smoothing = v; }});
    std::vector<Field> mujoco = TimeConstants();
    mujoco.push_back({"tausmooth", kTauSmoothRange, 0.0,
                      "w, the width in e - u of the quintic blend (0: thelen2003's step)",
                      [](const ActivationDynamics& d) { return d.tausmooth; },
                      [](ActivationDynamics& d, double v) { d.tausmooth = v; }});
    return std::vector<ActivationFamilyVariant>{
        Family("thelen2003", ActivationFamily::kThelen2003,
               "udot = (e - u) / tau, tau = tau_act (0.5 + 1.5 u) while e > u, else "
               "tau_deact / (0.5 + 1.5 u) (the default family)",
               TimeConstants()),
        Family("degroote2016", ActivationFamily::kDeGroote2016,
               "the two rates blended by 0.5 tanh(b (e - u)), smooth everywhere (OpenSim)",
               std::move(degroote)),
        Family("mujoco", ActivationFamily::kMujoco,
               "thelen2003's time constants blended over a width w of e - u by a quintic "
               "smoothstep (MuJoCo)",
               std::move(mujoco)),
    };
  }();
  return families;
}

}  // namespace musclesim
