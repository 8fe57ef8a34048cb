// A muscle of another family brought to the nearest degroote2016 muscle (docs/model.md 14.5),
// with how far each curve moved: OpenSim's Millard2012EquilibriumMuscle and Thelen2003Muscle.
// The families share their structure (curves normalised by the optimal fiber length, v_max
// and the isometric force, pennation at constant thickness, a tendon normalised by its slack
// length), not their shapes: the quantities both name are kept (each strain at one norm
// force), De Groote's active curve, which names no point, is widened to the other's by least
// squares.
#pragma once

#include <functional>

#include "musclesim/model/millard2012.h"
#include "musclesim/model/thelen2003.h"

namespace musclesim {

// How far one converted curve lies from the original, in normalised force, over the interval
// that curve is compared on.
struct CurveDeparture {
  double largest = 0.0;         // max |f_DeGroote - f_original| [-]
  double at = 0.0;              // where it is largest (the curve's argument)
  double rms = 0.0;             // root mean square over the interval [-]
  double from = 0.0, to = 0.0;  // the interval compared on
};

struct DeGrooteConversion {
  double active_force_width_scale = 1.0;  // least squares over the active interval, in [1, 10]
  double passive_fiber_strain_at_one_norm_force = 0.6;  // set to the original muscle's
  double tendon_strain_at_one_norm_force = 0.049;       // likewise
  CurveDeparture active, passive, tendon;
  CurveDeparture shortening, lengthening;  // the force-velocity curve's two sides
};

// Another family's curves, each of its normalised argument, and where to compare them: the
// active and passive curves of l~ over [low, high]; the force-velocity curve of the
// lengthening v~ over [-1, 0] and [0, 1]; the tendon's of its strain over [0, its strain at
// one norm force].
struct ComparedCurves {
  std::function<double(double)> active, passive, velocity, tendon;
  double active_low = 0.0, active_high = 0.0;
  double passive_low = 0.0, passive_high = 0.0;
  double passive_strain_at_one_norm_force = 0.0;
  double tendon_strain_at_one_norm_force = 0.0;
};

DeGrooteConversion NearestDeGroote(const ComparedCurves& curves);

// Millard's curves as Millard2012EquilibriumMuscle runs them (its adjustments for the damped
// and the classic formulation already applied), compared over [min, max]_norm_active_fiber_length
// and, passive, from there (or 1 + strain_at_zero_force, if less) to 1 +
// strain_at_one_norm_force; throws ParameterError as MillardCurve does.
DeGrooteConversion NearestDeGroote(const MillardCurves& curves);

// Thelen's, at activation 1 (its force-velocity curve's only shape of De Groote's kind),
// compared over l~ where its active Gaussian exceeds 1 % (from 0.2 at least) and, passive, from
// there to 1 + FmaxMuscleStrain; throws ParameterError as Validate does.
DeGrooteConversion NearestDeGroote(const ThelenCurves& curves);

}  // namespace musclesim
