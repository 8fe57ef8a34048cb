// MuJoCo's muscle (engine_util_misc.c: mju_muscleGain, mju_muscleBias; docs/model.md section
// 14.1; every definition in bench/peers/README.md): piecewise-quadratic length and velocity
// curves, C1, over the length normalised by `range` and `lengthrange`. MuJoCo's force is
// negative when pulling and its velocity positive when lengthening; musclesim's tension is
// positive when pulling and v positive when shortening: T = -(gain u + bias), V = -v / (L0 vmax).
#pragma once

#include "musclesim/model/curve_point.h"
#include "musclesim/model/tension_sample.h"

namespace musclesim {

struct MujocoMuscleParams {
  double range[2] = {0.75, 1.05};      // normalised lengths at the ends of lengthrange [-]
  double lengthrange[2] = {0.0, 0.0};  // actuator lengths [m], lengthrange[0] < [1]
  double lmin = 0.5, lmax = 1.6;       // where the active curve vanishes [-]
  double vmax = 1.5;                   // shortening velocity of zero force [L0/s]
  double fpmax = 1.3;                  // passive force at lmax, over F0 [-]
  double fvmax = 1.2;                  // lengthening force, over F0 [-]
};

// Throws ParameterError with the key as its path ("range[1]", "lengthrange[0]", "lmin"): the
// lists and lmin, whose rules are not a range; the other fields' ranges are its description's
// (model/family_fields.h), which Validate(ModelParams) checks.
void Validate(const MujocoMuscleParams& params);

namespace mujoco_muscle {

// L0: the actuator length per unit of normalised length [m].
inline double LengthScale(const MujocoMuscleParams& p) {
  return (p.lengthrange[1] - p.lengthrange[0]) / (p.range[1] - p.range[0]);
}

// FL(L) and its slope in L.
inline CurvePoint ActiveForceLength(const MujocoMuscleParams& p, double L) {
  if (L < p.lmin || L > p.lmax) return {0.0, 0.0};
  const double a = 0.5 * (p.lmin + 1.0), b = 0.5 * (1.0 + p.lmax);
  if (L <= a) {
    const double x = (L - p.lmin) / (a - p.lmin);
    return {0.5 * x * x, x / (a - p.lmin)};
  }
  if (L <= 1.0) {
    const double x = (1.0 - L) / (1.0 - a);
    return {1.0 - 0.5 * x * x, x / (1.0 - a)};
  }
  if (L <= b) {
    const double x = (L - 1.0) / (b - 1.0);
    return {1.0 - 0.5 * x * x, -x / (b - 1.0)};
  }
  const double x = (p.lmax - L) / (p.lmax - b);
  return {0.5 * x * x, -x / (p.lmax - b)};
}

// FV(V) and its slope, V the normalised lengthening velocity.
inline CurvePoint ForceVelocity(const MujocoMuscleParams& p, double V) {
  const double y = p.fvmax - 1.0;
  if (V <= -1.0) return {0.0, 0.0};
  if (V <= 0.0) return {(V + 1.0) * (V + 1.0), 2.0 * (V + 1.0)};
  if (V <= y) return {p.fvmax - (y - V) * (y - V) / y, 2.0 * (y - V) / y};
  return {p.fvmax, 0.0};
}

// FP(L) and its slope: quadratic from L = 1 to b = (1 + lmax) / 2, linear beyond.
inline CurvePoint PassiveForceLength(const MujocoMuscleParams& p, double L) {
  const double b = 0.5 * (1.0 + p.lmax);
  if (L <= 1.0) return {0.0, 0.0};
  if (L <= b) {
    const double x = (L - 1.0) / (b - 1.0);
    return {p.fpmax * 0.5 * x * x, p.fpmax * x / (b - 1.0)};
  }
  const double x = (L - b) / (b - 1.0);
  return {p.fpmax * (0.5 + x), p.fpmax / (b - 1.0)};
}

}  // namespace mujoco_muscle

// T = F0 (u FL FV + FP) [N] with its derivatives, at actuator length x [m], shortening
// velocity v [m/s], activation u.
inline TensionSample MujocoFiber(const MujocoMuscleParams& p, double f_iso, double x, double v,
                                 double u) {
  const double scale = mujoco_muscle::LengthScale(p);
  const double L = p.range[0] + (x - p.lengthrange[0]) / scale;
  const double V = -v / (scale * p.vmax);
  const CurvePoint active = mujoco_muscle::ActiveForceLength(p, L);
  const CurvePoint velocity = mujoco_muscle::ForceVelocity(p, V);
  const CurvePoint passive = mujoco_muscle::PassiveForceLength(p, L);
  TensionSample out;
  out.passive = f_iso * passive.value;
  out.d_activation = f_iso * active.value * velocity.value;
  out.active = u * out.d_activation;
  out.total = out.passive + out.active;
  out.d_length = f_iso * (u * active.slope * velocity.value + passive.slope) / scale;
  out.d_velocity = -f_iso * u * active.value * velocity.slope / (scale * p.vmax);
  return out;
}

}  // namespace musclesim
