// De Groote, Kinney, Rao, Fregly (2016) as OpenSim 4.6's DeGrooteFregly2016Muscle implements
// it, constant for constant (docs/model.md section 14.1; every constant and its source in
// bench/peers/README.md). OpenSim's velocities are positive when the fiber lengthens;
// musclesim's v is positive when it shortens: v~ = -v / (v_max l_opt) below.
#pragma once

#include <cmath>

#include "musclesim/model/curve_point.h"
#include "musclesim/model/tension_sample.h"

namespace musclesim {

struct DeGrooteParams {
  double optimal_fiber_length = 0.1;                    // l_opt [m], > 0
  double max_contraction_velocity = 10;                 // v_max [optimal lengths per second], > 0
  double active_force_width_scale = 1;                  // w [-], >= 1 (OpenSim's rule)
  double passive_fiber_strain_at_one_norm_force = 0.6;  // e0 [-], > 0
  double fiber_damping = 0;  // beta [-], >= 0: F0 beta v~ beside the curves
};

// Its fields' ranges are its description's (model/family_fields.h), which Validate(ModelParams)
// checks.

namespace degroote2016 {

// The active force-length multiplier's terms (b1, b2, b3, b4), OpenSim's values.
struct GaussianLike {
  double b1, b2, b3, b4;
};
inline constexpr GaussianLike kActiveTerms[3] = {
    {0.8150671134243542, 1.055033428970575, 0.162384573599574, 0.063303448465465},
    {0.433004984392647, 0.716775413397760, -0.029947116970696, 0.200356847296188},
    {0.1, 1.0, 0.353553390593274, 0.0}};
// force-velocity: d1 asinh(d2 v~ + d3) + d4
inline constexpr double kD1 = -0.3211346127989808, kD2 = -8.149, kD3 = -0.374,
                        kD4 = 0.8825327733249912;
// passive: (exp(kPE (l~ - 1) / e0) - o) / (exp(kPE) - o), o = exp(kPE (l_min - 1) / e0)
inline constexpr double kPassiveRate = 4.0, kPassiveMinimumLength = 0.2;

// f_act(l~) and its slope in l~ (the normalised fiber length).
inline CurvePoint ActiveForceLength(double normalized_length, double width_scale) {
  const double x = 1.0 + (normalized_length - 1.0) / width_scale;
  CurvePoint out{0.0, 0.0};
  for (const GaussianLike& g : kActiveTerms) {
    const double s = g.b3 + g.b4 * x, d = x - g.b2;
    const double f = g.b1 * std::exp(-0.5 * d * d / (s * s));
    out.value += f;
    out.slope += f * (-d / (s * s) + d * d * g.b4 / (s * s * s));
  }
  out.slope /= width_scale;
  return out;
}

// f_pas(l~) and its slope; negative below l~ = 0.2, as OpenSim has it.
inline CurvePoint PassiveForceLength(double normalized_length, double strain_at_one) {
  const double offset = std::exp(kPassiveRate * (kPassiveMinimumLength - 1.0) / strain_at_one);
  const double denominator = std::exp(kPassiveRate) - offset;
  const double growth = std::exp(kPassiveRate * (normalized_length - 1.0) / strain_at_one);
  return {(growth - offset) / denominator, kPassiveRate / strain_at_one * growth / denominator};
}

// f_v(v~) and its slope, v~ the normalised lengthening velocity.
inline CurvePoint ForceVelocity(double normalized_lengthening) {
  const double z = kD2 * normalized_lengthening + kD3;
  return {kD1 * std::asinh(z) + kD4, kD1 * kD2 / std::sqrt(z * z + 1.0)};
}

}  // namespace degroote2016

// Fiber tension F0 (u f_act f_v + f_pas + beta v~) [N] with its derivatives, at fiber length
// l [m], shortening velocity v [m/s], activation u.
inline TensionSample DeGrooteFiber(const DeGrooteParams& p, double f_iso, double l, double v,
                                   double u) {
  const double l_opt = p.optimal_fiber_length;
  const double velocity_scale = p.max_contraction_velocity * l_opt;  // [m/s]
  const double lengthening = -v / velocity_scale;
  const CurvePoint active = degroote2016::ActiveForceLength(l / l_opt, p.active_force_width_scale);
  const CurvePoint passive =
      degroote2016::PassiveForceLength(l / l_opt, p.passive_fiber_strain_at_one_norm_force);
  const CurvePoint velocity = degroote2016::ForceVelocity(lengthening);
  TensionSample out;
  // the damping is a passive force: it acts at zero activation
  out.passive = f_iso * (passive.value + p.fiber_damping * lengthening);
  out.d_activation = f_iso * active.value * velocity.value;
  out.active = u * out.d_activation;
  out.total = out.passive + out.active;
  out.d_length = f_iso * (u * active.slope * velocity.value + passive.slope) / l_opt;
  out.d_velocity = -f_iso * (u * active.value * velocity.slope + p.fiber_damping) / velocity_scale;
  return out;
}

}  // namespace musclesim
