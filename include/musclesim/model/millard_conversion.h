// A Millard 2012 muscle's curves brought to the nearest degroote2016 muscle (docs/model.md
// 14.5), with how far each curve moved. The two families share their structure (curves
// normalised by the optimal fiber length, v_max and the isometric force, the same fiber
// damping, a tendon normalised by its slack length), not their shapes: the quantities both
// name are kept (each strain at one norm force), De Groote's active curve, which names no
// point, is widened to Millard's by least squares.
#pragma once

#include "musclesim/model/millard2012.h"

namespace musclesim {

struct MillardCurves {
  MillardActiveForceLength active;
  MillardForceVelocity velocity;
  MillardFiberForceLength passive;
  MillardTendonForceLength tendon;
};

// How far one converted curve lies from Millard's, in normalised force, over the interval
// that curve is compared on (below).
struct CurveDeparture {
  double largest = 0.0;  // max |f_DeGroote - f_Millard| [-]
  double at = 0.0;       // where it is largest (the curve's argument)
  double rms = 0.0;      // root mean square over the interval [-]
};

struct DeGrooteConversion {
  double active_force_width_scale = 1.0;  // least squares over Millard's active range, in [1, 10]
  double passive_fiber_strain_at_one_norm_force = 0.6;  // Millard's fiber strain_at_one_norm_force
  double tendon_strain_at_one_norm_force = 0.049;       // Millard's tendon's
  // compared on: l~ over Millard's [min, max]_norm_active_fiber_length; l~ from
  // min(1, 1 + strain_at_zero_force) to 1 + strain_at_one_norm_force; v~ over [-1, 1]; the
  // tendon's strain over [0, strain_at_one_norm_force]
  CurveDeparture active, passive, velocity, tendon;
};

// `curves` as Millard2012EquilibriumMuscle runs them (its adjustments for the damped and the
// classic model already applied); throws ParameterError as MillardCurve does.
DeGrooteConversion NearestDeGroote(const MillardCurves& curves);

}  // namespace musclesim
