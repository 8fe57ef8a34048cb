#include "musclesim/io/writers/curves_csv.h"

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/output_file.h"

namespace musclesim {

namespace {

void Validate(const UniformGrid& grid) {
  Require(std::isfinite(grid.from), "from", grid.from, "must be finite");
  Require(std::isfinite(grid.to) && grid.to > grid.from, "to", grid.to,
          "must be finite and greater than from");
  Require(grid.count >= 2, "count", grid.count, "must be an integer >= 2");
}

// A value of the table: finite, or a ParameterError naming the grid point (`axis` = `at`).
double Finite(double value, const char* axis, double at, const char* column) {
  if (!std::isfinite(value)) {
    throw ParameterError(axis, FormatNumber(at),
                         std::string(column) + " = " + FormatNumber(value) +
                             " there: the model's arithmetic overflows; choose a narrower range");
  }
  return value;
}

}  // namespace

std::string FormatLengthCurvesCsv(const TensionModel& model, const UniformGrid& lengths) {
  Validate(lengths);
  std::string csv = "length,f_L,tension_passive\n";
  for (int i = 0; i < lengths.count; ++i) {
    const double x = lengths.At(i);
    const double f_l = Finite(model.ActiveLengthFactor(x).value, "length", x, "f_L");
    const double passive = Finite(model.Passive(x, 0.0).passive, "length", x, "tension_passive");
    csv += FormatFull(x) + ',' + FormatFull(f_l) + ',' + FormatFull(passive) + '\n';
  }
  return csv;
}

std::string FormatVelocityCurveCsv(const TensionModel& model, const UniformGrid& velocities) {
  Validate(velocities);
  std::string csv = "shortening_velocity,g\n";
  for (int i = 0; i < velocities.count; ++i) {
    const double v = velocities.At(i);
    const double g = Finite(model.VelocityFactor(v).value, "shortening_velocity", v, "g");
    csv += FormatFull(v) + ',' + FormatFull(g) + '\n';
  }
  return csv;
}

std::string FormatPresetCurveCsv(ForceLengthPreset preset, double optimal_length,
                                 const UniformGrid& lengths) {
  Validate(lengths);
  Require(std::isfinite(optimal_length) && optimal_length > 0.0, "optimal_length", optimal_length,
          "must be finite and > 0 [m]");
  std::string csv = "length,normalized_length,f_L\n";
  for (int i = 0; i < lengths.count; ++i) {
    const double x = lengths.At(i);
    const double s = Finite(x / optimal_length, "length", x, "normalized_length");
    csv += FormatFull(x) + ',' + FormatFull(s) + ',' + FormatFull(EvaluatePreset(preset, s)) + '\n';
  }
  return csv;
}

}  // namespace musclesim
