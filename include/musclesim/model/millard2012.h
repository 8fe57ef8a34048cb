// Millard 2012's four muscle curves as OpenSim 4.6's Millard2012EquilibriumMuscle builds them
// (docs/model.md 14.5): quintic Bezier corners (model/quintic_bezier.h) placed by each curve's
// properties, those a file leaves out at OpenSim's defaults (the optional ones of the fiber's
// and the tendon's curves computed from their strains, all of them or none). musclesim runs
// no muscle of this family: `musclesim import` converts it to family degroote2016 and reports
// how far each curve moved (io/import/muscle_import.h).
#pragma once

#include <optional>

#include "musclesim/model/quintic_bezier.h"

namespace musclesim {

// OpenSim's ActiveForceLengthCurve: f_act(l~), l~ the fiber length over the optimal one.
struct MillardActiveForceLength {
  double min_norm_active_fiber_length = 0.4441;
  double transition_norm_fiber_length = 0.73;
  double max_norm_active_fiber_length = 1.8123;
  double shallow_ascending_slope = 0.8616;
  double minimum_value = 0.1;
};

// OpenSim's ForceVelocityCurve: f_v(v~), v~ the lengthening velocity over v_max l_opt.
struct MillardForceVelocity {
  double concentric_slope_at_vmax = 0.0;
  double concentric_slope_near_vmax = 0.25;
  double isometric_slope = 5.0;
  double eccentric_slope_at_vmax = 0.0;
  double eccentric_slope_near_vmax = 0.15;
  double max_eccentric_velocity_force_multiplier = 1.4;
  double concentric_curviness = 0.6;
  double eccentric_curviness = 0.9;
};

// OpenSim's FiberForceLengthCurve: f_pas(l~). Without the optional three: stiffness at one
// norm force 2 / (strain_at_one_norm_force - strain_at_zero_force), at low force 0.2,
// curviness 0.75.
struct MillardFiberForceLength {
  double strain_at_zero_force = 0.0;
  double strain_at_one_norm_force = 0.7;
  std::optional<double> stiffness_at_low_force, stiffness_at_one_norm_force, curviness;
};

// OpenSim's TendonForceLengthCurve: f_T(l~_T), l~_T the tendon length over its slack length.
// Without the optional three: stiffness 1.375 / strain_at_one_norm_force, norm force at the
// toe's end 2/3, curviness 0.5.
struct MillardTendonForceLength {
  double strain_at_one_norm_force = 0.049;
  std::optional<double> stiffness_at_one_norm_force, norm_force_at_toe_end, curviness;
};

// A Millard muscle's four curves.
struct MillardCurves {
  MillardActiveForceLength active;
  MillardForceVelocity velocity;
  MillardFiberForceLength passive;
  MillardTendonForceLength tendon;
};

// Each curve, or ParameterError naming the property ("shallow_ascending_slope") and the rule
// OpenSim applies to it (or, where OpenSim's message says less, the condition it checks).
SegmentedBezierCurve MillardCurve(const MillardActiveForceLength& p);
SegmentedBezierCurve MillardCurve(const MillardForceVelocity& p);
SegmentedBezierCurve MillardCurve(const MillardFiberForceLength& p);
SegmentedBezierCurve MillardCurve(const MillardTendonForceLength& p);

}  // namespace musclesim
