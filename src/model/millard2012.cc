// Placement of each curve's corners: Millard et al. 2013 and OpenSim 4.6's
// SmoothSegmentedFunctionFactory, point for point; the rules are the factory's checks.
#include "musclesim/model/millard2012.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

const double kRootEpsilon = std::sqrt(std::numeric_limits<double>::epsilon());

// OpenSim's scaling of a curviness in [0, 1] to the control points' pull
double ScaledCurviness(double curviness) { return 0.1 + 0.8 * curviness; }

void RequireCurviness(double curviness, const char* path) {
  Require(curviness >= 0.0 && curviness <= 1.0, path, curviness, "must be in [0, 1]");
}

// A corner, its refusal naming the curve and where the corner runs: the properties together
// put two points and their slopes where no corner joins them.
BezierCorner Corner(const char* curve, double x0, double y0, double dydx0, double x1, double y1,
                    double dydx1, double c) {
  try {
    return MakeBezierCorner(x0, y0, dydx0, x1, y1, dydx1, c);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(curve,
                         "(" + FormatNumber(x0) + ", " + FormatNumber(y0) + ") slope " +
                             FormatNumber(dydx0) + " to (" + FormatNumber(x1) + ", " +
                             FormatNumber(y1) + ") slope " + FormatNumber(dydx1),
                         std::string(e.what()) + ": its properties place this part of the curve");
  }
}

// The optional properties: all of them, or none (OpenSim's rule), else ParameterError.
void RequireAllOrNone(const std::vector<std::pair<const char*, std::optional<double>>>& fields) {
  int given = 0;
  std::string names;
  for (const auto& [name, value] : fields) {
    given += value.has_value();
    names += std::string(names.empty() ? "" : ", ") + name;
  }
  if (given == 0 || given == static_cast<int>(fields.size())) return;
  for (const auto& [name, value] : fields) {
    if (value) {
      Require(
          false, name, *value,
          "is one of the optional " + names + ", which OpenSim takes all together or not at all");
    }
  }
}

}  // namespace

SegmentedBezierCurve MillardCurve(const MillardActiveForceLength& p) {
  const double x0 = p.min_norm_active_fiber_length, x1 = p.transition_norm_fiber_length;
  const double x2 = 1.0, x3 = p.max_norm_active_fiber_length;
  const double y_low = p.minimum_value, dydx = p.shallow_ascending_slope;
  Require(std::isfinite(x0) && x0 >= 0.0, "min_norm_active_fiber_length", x0, "must be >= 0");
  Require(std::isfinite(x1) && x1 > x0 + kRootEpsilon, "transition_norm_fiber_length", x1,
          "must exceed min_norm_active_fiber_length");
  Require(x1 < x2 - kRootEpsilon, "transition_norm_fiber_length", x1, "must be below 1");
  Require(std::isfinite(x3) && x3 > x2 + kRootEpsilon && x3 <= 1e3, "max_norm_active_fiber_length",
          x3, "must be above 1 and at most 1e3");
  Require(std::isfinite(y_low) && y_low >= 0.0 && y_low < 1.0, "minimum_value", y_low,
          "must be in [0, 1)");
  Require(std::isfinite(dydx) && dydx >= 0.0 && dydx < (1.0 - y_low) / (x2 - x1),
          "shallow_ascending_slope", dydx,
          "must be >= 0 and below (1 - minimum_value) / (1 - transition_norm_fiber_length)");
  const double c = ScaledCurviness(1.0);  // OpenSim's ActiveForceLengthCurve: curviness 1
  // the plateau's shoulder, 5 % of the optimal length either side of it
  const double delta = 0.05 * x2, shoulder = x2 - delta;
  const double y1 = 1.0 - dydx * (shoulder - x1);
  const double dydx01 = 1.25 * y1 / (x1 - x0);
  const double x01 = x0 + 0.5 * (x1 - x0), y01 = 0.5 * y1;
  const double x1s = x1 + 0.5 * (shoulder - x1), y1s = y1 + 0.5 * (1.0 - y1);
  const double x23 = (x2 + delta) + 0.5 * (x3 - (x2 + delta)), y23 = 0.5;
  const double dydx23 = -1.0 / ((x3 - delta) - (x2 + delta));
  const char* name = "ActiveForceLengthCurve";
  return SegmentedBezierCurve({Corner(name, x0, y_low, 0.0, x01, y01, dydx01, c),
                               Corner(name, x01, y01, dydx01, x1s, y1s, dydx, c),
                               Corner(name, x1s, y1s, dydx, x2, 1.0, 0.0, c),
                               Corner(name, x2, 1.0, 0.0, x23, y23, dydx23, c),
                               Corner(name, x23, y23, dydx23, x3, y_low, 0.0, c)},
                              0.0, 0.0);
}

SegmentedBezierCurve MillardCurve(const MillardForceVelocity& p) {
  const double f_max = p.max_eccentric_velocity_force_multiplier;
  const double c_vmax = p.concentric_slope_at_vmax, c_near = p.concentric_slope_near_vmax;
  const double e_vmax = p.eccentric_slope_at_vmax, e_near = p.eccentric_slope_near_vmax;
  const double iso = p.isometric_slope;
  Require(std::isfinite(f_max) && f_max > 1.0 && f_max <= 1e3,
          "max_eccentric_velocity_force_multiplier", f_max, "must be above 1 and at most 1e3");
  Require(std::isfinite(c_vmax) && c_vmax >= 0.0 && c_vmax < 1.0, "concentric_slope_at_vmax",
          c_vmax, "must be in [0, 1)");
  // below 1: OpenSim's muscle inverts the curve, whose inverse needs it (ForceVelocityInverseCurve)
  Require(std::isfinite(c_near) && c_near > c_vmax && c_near < 1.0, "concentric_slope_near_vmax",
          c_near, "must exceed concentric_slope_at_vmax and be below 1");
  Require(c_near >= kRootEpsilon, "concentric_slope_near_vmax", c_near,
          "must be at least 1.49e-8 (OpenSim's Millard2012EquilibriumMuscle)");
  Require(std::isfinite(iso) && iso > 1.0 && iso <= 1e6, "isometric_slope", iso,
          "must be above 1 and at most 1e6");
  Require(std::isfinite(e_vmax) && e_vmax >= 0.0 && e_vmax < f_max - 1.0, "eccentric_slope_at_vmax",
          e_vmax, "must be >= 0 and below max_eccentric_velocity_force_multiplier - 1");
  Require(std::isfinite(e_near) && e_near >= e_vmax && e_near < f_max - 1.0,
          "eccentric_slope_near_vmax", e_near,
          "must be at least eccentric_slope_at_vmax and below "
          "max_eccentric_velocity_force_multiplier - 1");
  Require(e_near >= kRootEpsilon, "eccentric_slope_near_vmax", e_near,
          "must be at least 1.49e-8 (OpenSim's Millard2012EquilibriumMuscle)");
  RequireCurviness(p.concentric_curviness, "concentric_curviness");
  RequireCurviness(p.eccentric_curviness, "eccentric_curviness");
  const double c_conc = ScaledCurviness(p.concentric_curviness);
  const double c_ecc = ScaledCurviness(p.eccentric_curviness);
  // v~ = -1 (shortening at v_max): 0; v~ = 1: f_max; the "near" points at +-0.9
  const double y_near_c = 0.5 * c_near * 0.1 + 0.5 * c_vmax * 0.1;
  const double y_near_e = f_max - 0.5 * e_near * 0.1 - 0.5 * e_vmax * 0.1;
  const char* name = "ForceVelocityCurve";
  return SegmentedBezierCurve({Corner(name, -1.0, 0.0, c_vmax, -0.9, y_near_c, c_near, c_conc),
                               Corner(name, -0.9, y_near_c, c_near, 0.0, 1.0, iso, c_conc),
                               Corner(name, 0.0, 1.0, iso, 0.9, y_near_e, e_near, c_ecc),
                               Corner(name, 0.9, y_near_e, e_near, 1.0, f_max, e_vmax, c_ecc)},
                              c_vmax, e_vmax);
}

SegmentedBezierCurve MillardCurve(const MillardFiberForceLength& p) {
  const double e0 = p.strain_at_zero_force, e1 = p.strain_at_one_norm_force;
  Require(std::isfinite(e0) && e0 > -1.0 && e0 <= 1e3, "strain_at_zero_force", e0,
          "must be above -1 and at most 1e3");
  Require(std::isfinite(e1) && e1 > e0 && e1 <= 1e3, "strain_at_one_norm_force", e1,
          "must exceed strain_at_zero_force and be at most 1e3");
  RequireAllOrNone({{"stiffness_at_low_force", p.stiffness_at_low_force},
                    {"stiffness_at_one_norm_force", p.stiffness_at_one_norm_force},
                    {"curviness", p.curviness}});
  const double k_iso = p.stiffness_at_one_norm_force.value_or(2.0 / (e1 - e0));
  const double k_low = p.stiffness_at_low_force.value_or(0.2);
  const double curviness = p.curviness.value_or(0.75);
  Require(std::isfinite(k_iso) && k_iso > 1.0 / (e1 - e0) && k_iso <= 1e9,
          "stiffness_at_one_norm_force", k_iso,
          "must exceed 1 / (strain_at_one_norm_force - strain_at_zero_force) and be at most 1e9");
  Require(std::isfinite(k_low) && k_low > 0.0 && k_low < 1.0 / (e1 - e0), "stiffness_at_low_force",
          k_low, "must be > 0 and below 1 / (strain_at_one_norm_force - strain_at_zero_force)");
  RequireCurviness(curviness, "curviness");
  const double c = ScaledCurviness(curviness);
  const double x_zero = 1.0 + e0, x_iso = 1.0 + e1;
  const double dx = std::min(0.1 / k_iso, 0.1 * (x_iso - x_zero));
  const double x_low = x_zero + dx;
  const double y_low = k_low * (x_low - (x_zero + 0.5 * dx));  // the foot halfway to x_low
  const char* name = "FiberForceLengthCurve";
  return SegmentedBezierCurve({Corner(name, x_zero, 0.0, 0.0, x_low, y_low, k_low, c),
                               Corner(name, x_low, y_low, k_low, x_iso, 1.0, k_iso, c)},
                              0.0, k_iso);
}

SegmentedBezierCurve MillardCurve(const MillardTendonForceLength& p) {
  const double e_iso = p.strain_at_one_norm_force;
  Require(std::isfinite(e_iso) && e_iso > 0.0 && e_iso <= 1e3, "strain_at_one_norm_force", e_iso,
          "must be > 0 and at most 1e3");
  RequireAllOrNone({{"stiffness_at_one_norm_force", p.stiffness_at_one_norm_force},
                    {"norm_force_at_toe_end", p.norm_force_at_toe_end},
                    {"curviness", p.curviness}});
  const double k_iso = p.stiffness_at_one_norm_force.value_or(1.375 / e_iso);
  const double f_toe = p.norm_force_at_toe_end.value_or(2.0 / 3.0);
  const double curviness = p.curviness.value_or(0.5);
  Require(std::isfinite(k_iso) && k_iso > 1.0 / e_iso && k_iso <= 1e9,
          "stiffness_at_one_norm_force", k_iso,
          "must exceed 1 / strain_at_one_norm_force and be at most 1e9");
  Require(std::isfinite(f_toe) && f_toe > 0.0 && f_toe < 1.0, "norm_force_at_toe_end", f_toe,
          "must be in (0, 1)");
  RequireCurviness(curviness, "curviness");
  const double c = ScaledCurviness(curviness);
  const double x_iso = 1.0 + e_iso;
  // the toe ends on the line through (x_iso, 1) of slope k_iso
  const double x_toe = (f_toe - 1.0) / k_iso + x_iso;
  // the line the toe bends from meets the axis a tenth of the way to the toe's end
  const double x_foot = 1.0 + (x_toe - 1.0) / 10.0;
  const double y_toe_mid = 0.5 * f_toe;
  const double x_toe_mid = (y_toe_mid - 1.0) / k_iso + x_iso;
  const double dydx_toe_mid = y_toe_mid / (x_toe_mid - x_foot);
  const double x_toe_ctrl = x_foot + 0.5 * (x_toe_mid - x_foot);
  const double y_toe_ctrl = dydx_toe_mid * (x_toe_ctrl - x_foot);
  const char* name = "TendonForceLengthCurve";
  return SegmentedBezierCurve(
      {Corner(name, 1.0, 0.0, 0.0, x_toe_ctrl, y_toe_ctrl, dydx_toe_mid, c),
       Corner(name, x_toe_ctrl, y_toe_ctrl, dydx_toe_mid, x_toe, f_toe, k_iso, c)},
      0.0, k_iso);
}

}  // namespace musclesim
