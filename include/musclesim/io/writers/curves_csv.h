// The model's curves tabulated as CSV text (`musclesim curves`): f_L and the passive
// tension over length, or g over shortening velocity, on an evenly spaced grid. Numbers carry
// 17 significant digits, enough to read back the same doubles.
#pragma once

#include <string>

#include "musclesim/model/force_length_presets.h"
#include "musclesim/model/tension.h"

namespace musclesim {

// `count` evenly spaced points from `from` to `to`, both included.
struct UniformGrid {
  double from = 0.0;  // first point [m for lengths, m/s for velocities], finite
  double to = 0.0;    // last point [same unit], finite and > from
  int count = 0;      // number of points [-], >= 2
  // The i-th point, i in [0, count) [same unit].
  double At(int i) const { return from + (to - from) * i / (count - 1); }
};

// Header "length,f_L,tension_passive", then per grid point the length [m], f_L(x) [-] and
// T_p(x) [N]. Throws ParameterError ("from", "to" or "count") for a grid breaking its rules,
// and ParameterError ("length", the grid point) where a value is not finite: a table holds
// numbers only.
std::string FormatLengthCurvesCsv(const TensionModel& model, const UniformGrid& lengths);

// Header "shortening_velocity,g", then per grid point v [m/s] and the eps-regularised
// g_eps(v) [-]. Throws ParameterError as FormatLengthCurvesCsv does ("shortening_velocity"
// for a value that is not finite).
std::string FormatVelocityCurveCsv(const TensionModel& model, const UniformGrid& velocities);

// Header "length,normalized_length,f_L", then per grid point the length l [m], l / l_opt [-]
// and the preset's value there [-] (1 at l = l_opt). Throws ParameterError as
// FormatLengthCurvesCsv does, and ParameterError("optimal_length", ...) unless l_opt is finite
// and > 0.
std::string FormatPresetCurveCsv(ForceLengthPreset preset, double optimal_length,
                                 const UniformGrid& lengths);

}  // namespace musclesim
