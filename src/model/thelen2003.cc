// OpenSim 4.6's Thelen2003Muscle: calcfal, calcfpe, calcdlceN (inverted here in closed form)
// and calcfse, term for term.
#include "musclesim/model/thelen2003.h"

#include <algorithm>
#include <cmath>

#include "musclesim/core/errors.h"

namespace musclesim {

void Validate(const ThelenCurves& c) {
  Require(
      std::isfinite(c.FmaxTendonStrain) && c.FmaxTendonStrain > 0.0 && c.FmaxTendonStrain <= 1e3,
      "FmaxTendonStrain", c.FmaxTendonStrain, "must be > 0 and at most 1e3");
  Require(
      std::isfinite(c.FmaxMuscleStrain) && c.FmaxMuscleStrain > 0.0 && c.FmaxMuscleStrain <= 1e3,
      "FmaxMuscleStrain", c.FmaxMuscleStrain, "must be > 0 and at most 1e3");
  Require(std::isfinite(c.KshapeActive) && c.KshapeActive > 0.0 && c.KshapeActive <= 1e3,
          "KshapeActive", c.KshapeActive, "must be > 0 and at most 1e3");
  Require(std::isfinite(c.KshapePassive) && c.KshapePassive > 0.0 && c.KshapePassive <= 700.0,
          "KshapePassive", c.KshapePassive,
          "must be > 0 and at most 700 (exp of it must be finite)");
  Require(std::isfinite(c.Af) && c.Af > 0.0 && c.Af <= 1e3, "Af", c.Af,
          "must be > 0 and at most 1e3");
  Require(std::isfinite(c.Flen) && c.Flen > 1.0 && c.Flen <= 1e3, "Flen", c.Flen,
          "must be above 1 and at most 1e3");
  Require(std::isfinite(c.fv_linear_extrap_threshold) &&
              c.fv_linear_extrap_threshold * c.Flen > 1.0 && c.fv_linear_extrap_threshold < 1.0,
          "fv_linear_extrap_threshold", c.fv_linear_extrap_threshold,
          "must be below 1 and above 1 / Flen (the line starts on the lengthening branch)");
}

namespace thelen2003 {

double ActiveForceLength(const ThelenCurves& c, double l) {
  return std::exp(-(l - 1.0) * (l - 1.0) / c.KshapeActive);
}

double PassiveForceLength(const ThelenCurves& c, double l) {
  if (l <= 1.0) return 0.0;
  return std::expm1(c.KshapePassive * (l - 1.0) / c.FmaxMuscleStrain) / std::expm1(c.KshapePassive);
}

double ForceVelocity(const ThelenCurves& c, double v) {
  // Thelen's v(f) at a = 1, f_al = 1: shortening v = (f - 1) / (1 + f / Af); lengthening
  // v = (f - 1) / (k (Flen - f)), k = (2 + 2 / Af) / (Flen - 1)
  if (v <= 0.0) return std::max(0.0, (1.0 + v) / (1.0 - v / c.Af));
  const double k = (2.0 + 2.0 / c.Af) / (c.Flen - 1.0);
  const double f_line = c.fv_linear_extrap_threshold * c.Flen;
  const double b = k * (c.Flen - f_line);
  const double v_line = (f_line - 1.0) / b;
  if (v < v_line) return (1.0 + k * v * c.Flen) / (1.0 + k * v);
  // beyond, v goes on along its tangent in f there: dv/df = 1 / b + k (f - 1) / b^2
  const double dv_df = 1.0 / b + k * (f_line - 1.0) / (b * b);
  return f_line + (v - v_line) / dv_df;
}

double TendonForceLength(const ThelenCurves& c, double strain) {
  const double e0 = c.FmaxTendonStrain;
  const double k_toe = 3.0, f_toe = 0.33, e3 = std::exp(3.0);
  const double e_toe = 99.0 * e0 * e3 / (166.0 * e3 - 67.0);
  const double k_lin = 0.67 / (e0 - e_toe);
  if (strain > e_toe) return k_lin * (strain - e_toe) + f_toe;
  if (strain > 0.0) return f_toe / std::expm1(k_toe) * std::expm1(k_toe * strain / e_toe);
  return 0.0;
}

}  // namespace thelen2003

}  // namespace musclesim
