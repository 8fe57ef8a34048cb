// Activation dynamics (docs/model.md section 8): an actuator given an excitation e(t) instead
// of an activation has the activation u as a state of the ODE, following the first-order lag
// of the Thelen (2003) and Millard et al. (2013) muscles,
//   udot = (e - u) / tau(e, u),
//   tau  = tau_act (0.5 + 1.5 u)  if e > u,   tau_deact / (0.5 + 1.5 u)  otherwise.
// u stays in [0, 1] when e does. udot is continuous at e = u, where its slope in u jumps:
// the simulator restarts the integrator there (NetworkSystem::Kink::kExcitation).
#pragma once

#include <optional>

#include "musclesim/core/input_ranges.h"  // the time constants' bounds
#include "musclesim/dynamics/waveform.h"

namespace musclesim {

struct ActivationDynamics {
  double tau_activation = 0.015;   // tau_act [s], in [1e-4, 10]
  double tau_deactivation = 0.05;  // tau_deact [s], in [1e-4, 10]
};

// Throws ParameterError ("tau_activation", "tau_deactivation").
void Validate(const ActivationDynamics& dynamics);

// udot and its slope in u at one instant.
struct ActivationRate {
  double value = 0.0;          // du/dt [1/s]
  double by_activation = 0.0;  // d(du/dt)/du [1/s]; at e = u, the slope on the e <= u side
  double by_excitation = 0.0;  // d(du/dt)/de [1/s]; at e = u, the slope on the e <= u side
};

// The rate of docs/model.md section 8 at excitation e and activation u.
inline ActivationRate EvaluateActivationRate(const ActivationDynamics& d, double e, double u) {
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
