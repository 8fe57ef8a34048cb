// Activation dynamics (docs/model.md section 8): an actuator given an excitation e(t) instead
// of an activation has the activation u as a state of the ODE, following a first-order lag
// whose time constant switches between activation and deactivation (section 8.1):
//   thelen2003 (the default; Thelen 2003, Millard et al. 2013):
//     udot = (e - u) / tau,  tau = tau_act (0.5 + 1.5 u) if e > u,  tau_deact / (0.5 + 1.5 u)
//     otherwise. udot is continuous at e = u, where its slope in u jumps: the simulator
//     restarts the integrator there (NetworkSystem::Kink::kExcitation).
//   degroote2016 (OpenSim's DeGrooteFregly2016Muscle): the two rates blended by
//     f = 0.5 tanh(b (e - u)): udot = [(f + 0.5) / (tau_act z) + (0.5 - f) z / tau_deact] (e - u),
//     z = 0.5 + 1.5 u; smooth everywhere.
//   mujoco (MuJoCo's mju_muscleDynamics): the thelen2003 time constants, with u clamped to
//     [0, 1] inside them, blended over a width w = tausmooth of e - u by the quintic
//     smoothstep S: tau = tau_d + (tau_a - tau_d) S((e - u) / w + 0.5). w = 0 is thelen2003's
//     step exactly; w > 0 is twice continuously differentiable, with no kink.
// u stays in [0, 1] when e does.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "musclesim/core/input_ranges.h"  // the time constants' bounds
#include "musclesim/dynamics/waveform.h"

namespace musclesim {

enum class ActivationFamily { kThelen2003, kDeGroote2016, kMujoco };

struct ActivationDynamics {
  double tau_activation = 0.015;   // tau_act [s], in [1e-4, 10]
  double tau_deactivation = 0.05;  // tau_deact [s], in [1e-4, 10]
  ActivationFamily family = ActivationFamily::kThelen2003;
  double smoothing = 0.1;  // degroote2016: b [-], OpenSim's default
  double tausmooth = 0.0;  // mujoco: w [-], MuJoCo's default (the step)
};

// The YAML name of a family ("thelen2003", "degroote2016", "mujoco").
const char* ActivationFamilyName(ActivationFamily family);

// Throws ParameterError ("tau_activation", "tau_deactivation", "smoothing", "tausmooth").
void Validate(const ActivationDynamics& dynamics);

// Whether d(udot)/du jumps at e = u, where the integrator must restart.
inline bool HasExcitationKink(const ActivationDynamics& d) {
  return d.family == ActivationFamily::kThelen2003 ||
         (d.family == ActivationFamily::kMujoco && d.tausmooth == 0.0);
}

// udot and its slope in u at one instant.
struct ActivationRate {
  double value = 0.0;          // du/dt [1/s]
  double by_activation = 0.0;  // d(du/dt)/du [1/s]; at a kink e = u, the slope on the e <= u side
  double by_excitation = 0.0;  // d(du/dt)/de [1/s]; at a kink e = u, the slope on the e <= u side
};

namespace activation_law {

inline ActivationRate Thelen2003(const ActivationDynamics& d, double e, double u) {
  const double shape = 0.5 + 1.5 * u;
  if (e > u) {
    // (e - u) / (tau_act shape): its u-derivative is -(shape + 1.5 (e - u)) / (tau_act shape^2)
    const double tau = d.tau_activation * shape;
    return {(e - u) / tau, -(0.5 + 1.5 * e) / (tau * shape), 1.0 / tau};
  }
  // (e - u) shape / tau_deact: its u-derivative is (1.5 (e - u) - shape) / tau_deact
  return {(e - u) * shape / d.tau_deactivation, (1.5 * (e - u) - shape) / d.tau_deactivation,
          shape / d.tau_deactivation};
}

inline ActivationRate DeGroote2016(const ActivationDynamics& d, double e, double u) {
  const double z = 0.5 + 1.5 * u, gap = e - u;
  const double rise = 1.0 / (d.tau_activation * z), fall = z / d.tau_deactivation;
  const double tanh = std::tanh(d.smoothing * gap), f = 0.5 * tanh;
  const double df_dgap = 0.5 * d.smoothing * (1.0 - tanh * tanh);
  const double rate = rise * (f + 0.5) + fall * (0.5 - f);  // [1/s]
  // d rate/du through z (d rise/dz = -rise/z, d fall/dz = fall/z) and through f (gap = e - u)
  const double rate_by_u =
      1.5 * (-rise / z * (f + 0.5) + fall / z * (0.5 - f)) - (rise - fall) * df_dgap;
  const double rate_by_e = (rise - fall) * df_dgap;
  return {rate * gap, rate_by_u * gap - rate, rate_by_e * gap + rate};
}

inline ActivationRate Mujoco(const ActivationDynamics& d, double e, double u) {
  // MuJoCo clamps e and, inside the time constants, u to [0, 1]; musclesim's e is in [0, 1]
  const double clamped = std::clamp(u, 0.0, 1.0), by_clamp = clamped == u ? 1.0 : 0.0;
  const double z = 0.5 + 1.5 * clamped, gap = e - u;
  const double tau_a = d.tau_activation * z, tau_d = d.tau_deactivation / z;
  const double tau_a_by_u = 1.5 * d.tau_activation * by_clamp;
  const double tau_d_by_u = -1.5 * tau_d / z * by_clamp;
  double s = gap > 0.0 ? 1.0 : 0.0, s_by_gap = 0.0;  // the step, and its slope in e - u
  if (d.tausmooth > 0.0) {
    const double x = gap / d.tausmooth + 0.5;
    if (x <= 0.0) {
      s = 0.0;
    } else if (x >= 1.0) {
      s = 1.0;
    } else {
      s = x * x * x * (3.0 * x * (2.0 * x - 5.0) + 10.0);  // 6x^5 - 15x^4 + 10x^3
      s_by_gap = 30.0 * x * x * (x - 1.0) * (x - 1.0) / d.tausmooth;
    }
  }
  const double tau = tau_d + (tau_a - tau_d) * s;
  const double tau_by_u = tau_d_by_u + (tau_a_by_u - tau_d_by_u) * s - (tau_a - tau_d) * s_by_gap;
  const double tau_by_e = (tau_a - tau_d) * s_by_gap;
  // gap / tau: (d gap - gap d tau) / tau^2
  return {gap / tau, (-tau - gap * tau_by_u) / (tau * tau), (tau - gap * tau_by_e) / (tau * tau)};
}

}  // namespace activation_law

// The rate of docs/model.md section 8 at excitation e and activation u.
inline ActivationRate EvaluateActivationRate(const ActivationDynamics& d, double e, double u) {
  switch (d.family) {
    case ActivationFamily::kDeGroote2016: return activation_law::DeGroote2016(d, e, u);
    case ActivationFamily::kMujoco: return activation_law::Mujoco(d, e, u);
    case ActivationFamily::kThelen2003: break;
  }
  return activation_law::Thelen2003(d, e, u);
}

// What drives an actuator whose activation is a state: its excitation, its time constants and
// its activation at the start.
struct ExcitationInput {
  Waveform signal;                           // e(t) [-], within [0, 1]
  ActivationDynamics dynamics;               // units as in ActivationDynamics
  std::optional<double> initial_activation;  // u(t_start) [-], in [0, 1]; nullopt: e(t_start)

  // u at the start of a run beginning at t_start [s].
  double InitialActivation(double t_start) const {
    return initial_activation ? *initial_activation : signal.Evaluate(t_start);
  }
};

// Throws ParameterError with paths as the YAML keys of a network's actuator:
// "excitation.<key>", "activation_dynamics.tau_activation", "initial_activation".
void Validate(const ExcitationInput& input);

}  // namespace musclesim
