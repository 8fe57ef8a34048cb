// External loads on the actuator: forces pulling it longer (docs/model.md section 6). A force
// follows a waveform of time, a spring pulls towards its anchor, a hanging mass adds its
// weight and its inertia.
#pragma once

#include <string_view>
#include <vector>

#include "musclesim/dynamics/waveform.h"

namespace musclesim {

enum class LoadKind { kForce, kSpring, kMass };

// One load. Make one with the factories (Load::Constant(40.0)), which validate.
struct Load {
  LoadKind kind = LoadKind::kForce;
  Waveform force;          // kForce: F(t) [N]
  double stiffness = 0.0;  // kSpring: F = stiffness (anchor - x) [N/m], >= 0
  double anchor = 0.0;     // kSpring: length where the spring pulls nothing [m]
  double mass = 0.0;       // kMass: F = mass gravity, and mass joins m_eff [kg], > 0
  double gravity = 9.81;   // kMass: acceleration along +x (longer) [m/s^2]

  // Validated factories; each throws ParameterError (paths named as the YAML keys).
  static Load Force(Waveform force);                     // F(t) [N]
  static Load Constant(double force);                    // a constant force [N]
  static Load Spring(double stiffness, double anchor);   // [N/m], [m]
  static Load Mass(double mass, double gravity = 9.81);  // [kg], [m/s^2]
};

// Throws ParameterError (paths as the YAML keys of the load).
void Validate(const Load& load);

// The sum of all loads, evaluated without allocation.
class LoadSet {
 public:
  // Validates every load (ParameterError with paths such as "load[1].stiffness").
  explicit LoadSet(std::vector<Load> loads);

  // Total force [N] at time t and length x, and its derivative in x [N/m].
  double Force(double t, double x) const;
  double ForceSlope() const { return -spring_stiffness_; }
  // Mass the loads add to the actuator's [kg].
  double AddedMass() const { return added_mass_; }
  // Breakpoints of every force waveform in (t0, t1), sorted.
  std::vector<double> Breakpoints(double t0, double t1) const;
  const std::vector<Load>& loads() const { return loads_; }

 private:
  std::vector<Load> loads_;
  std::vector<Waveform> forces_;   // the kForce waveforms
  double spring_stiffness_ = 0.0;  // sum of the springs
  double spring_pull_ = 0.0;       // sum of stiffness * anchor
  double weight_ = 0.0;            // sum of mass * gravity
  double added_mass_ = 0.0;
};

}  // namespace musclesim
