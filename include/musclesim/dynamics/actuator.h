// The actuator/load dynamics of docs/model.md section 6 as a first-order system in y = (x, xdot):
//   m_eff xddot = F_load(t, x) - T(x, -xdot, u(t)) - c xdot - k (x - l0)
// with its analytic Jacobian; or, given an excitation with activation dynamics (docs/model.md
// section 8), in y = (x, xdot, u) with u a state. Immutable once built; evaluation allocates
// nothing.
#pragma once

#include <cassert>
#include <memory>
#include <optional>

#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/model/tension.h"
#include "musclesim/dynamics/waveform.h"

namespace musclesim {

// The actuator's own mechanics around its tension: moving mass and a parallel spring-damper.
struct ActuatorParams {
  double mass = 1.0;         // moving mass of the actuator [kg], > 0
  double damping = 0.0;      // parallel damper c [N s/m], >= 0
  double stiffness = 0.0;    // parallel spring k [N/m], >= 0
  double rest_length = 0.0;  // rest length l0 of that spring [m]
};

// Throws ParameterError ("mass", "damping", "stiffness", "rest_length").
void Validate(const ActuatorParams& params);

// Everything the state observes at one instant: what the output CSV records.
struct ActuatorSample {
  double length = 0.0;               // x [m]
  double shortening_velocity = 0.0;  // v = -xdot [m/s]
  double activation = 0.0;           // u, dimensionless in [0, 1]: u(t), or the state's
  double excitation = 0.0;           // e(t) with activation dynamics; without them u(t)
  TensionSample tension;
  double load = 0.0;  // F_load [N]
};

// The immutable system one run integrates. It shares its tension model (read-only), so many
// systems (a sweep's points, threads) can use one model built once.
class ActuatorSystem {
 public:
  // Validates the actuator, activation and loads (ParameterError); the activation must stay
  // within [0, 1]. `model` must not be null.
  ActuatorSystem(std::shared_ptr<const TensionModel> model, const ActuatorParams& actuator,
                 Waveform activation, std::vector<Load> loads);
  // The same with a model built from `model` (validated, ParameterError).
  ActuatorSystem(const ModelParams& model, const ActuatorParams& actuator, Waveform activation,
                 std::vector<Load> loads);
  // With activation dynamics: the activation is a state driven by `excitation` (validated,
  // ParameterError with paths "excitation.<key>", "activation_dynamics.<key>",
  // "initial.activation"). Runs then integrate y = (x, xdot, u) through network().
  ActuatorSystem(std::shared_ptr<const TensionModel> model, const ActuatorParams& actuator,
                 ExcitationInput excitation, std::vector<Load> loads);
  ActuatorSystem(const ModelParams& model, const ActuatorParams& actuator,
                 ExcitationInput excitation, std::vector<Load> loads);

  // xddot at (t, x, xdot). Without activation dynamics only (with them u is a state: see
  // network()), as are Jacobian and the three-argument Observe.
  double Acceleration(double t, double x, double xdot) const {
    assert(!excitation_);
    const TensionSample s = model_->Evaluate(x, -xdot, activation_.Evaluate(t));
    return (loads_.Force(t, x) - s.total - actuator_.damping * xdot -
            actuator_.stiffness * (x - actuator_.rest_length)) *
           inverse_mass_;
  }

  // d xddot / dx and d xddot / dxdot: the lower row of the Jacobian (the upper is [0, 1]).
  struct JacobianRow {
    double by_length;  // d xddot / dx [1/s^2]
    double by_rate;    // d xddot / dxdot [1/s]
  };
  JacobianRow Jacobian(double t, double x, double xdot) const {
    assert(!excitation_);
    const TensionSample s = model_->Evaluate(x, -xdot, activation_.Evaluate(t));
    // dT/dxdot = -dT/dv since v = -xdot
    return {(loads_.ForceSlope() - s.d_length - actuator_.stiffness) * inverse_mass_,
            (s.d_velocity - actuator_.damping) * inverse_mass_};
  }

  ActuatorSample Observe(double t, double x, double xdot) const;
  // With activation dynamics: u is the activation state.
  ActuatorSample Observe(double t, double x, double xdot, double u) const;

  // Where the inputs jump: breakpoints of activation (or excitation) and force loads in
  // (t0, t1), sorted.
  std::vector<double> Breakpoints(double t0, double t1) const;

  const TensionModel& model() const { return *model_; }
  const std::shared_ptr<const TensionModel>& shared_model() const { return model_; }
  const ActuatorParams& actuator() const { return actuator_; }
  const Waveform& activation() const { return activation_; }  // without activation dynamics
  // What drives the activation when it is a state; nullopt without activation dynamics.
  const std::optional<ExcitationInput>& excitation() const { return excitation_; }
  const LoadSet& loads() const { return loads_; }
  double effective_mass() const { return 1.0 / inverse_mass_; }  // [kg]

  // The same system as a network (docs/model.md 7.4): node `ground` fixed at 0, node `tip`
  // free (its initial state is the run's), elements `actuator`, `damper` and `spring` from
  // ground to tip (the last two only when their coefficient is not 0), the loads on tip. Its
  // right-hand side is this one's, bit for bit; with activation dynamics its state is
  // (x, xdot, u).
  const NetworkSystem& network() const { return network_; }

 private:
  std::shared_ptr<const TensionModel> model_;
  ActuatorParams actuator_;
  Waveform activation_;                        // unused with activation dynamics
  std::optional<ExcitationInput> excitation_;  // set for activation dynamics
  LoadSet loads_;
  double inverse_mass_;  // 1 / (actuator mass + load masses) [1/kg]
  NetworkSystem network_;
};

}  // namespace musclesim
