#include "musclesim/io/curves_csv.h"

#include <cmath>

#include "musclesim/errors.h"
#include "musclesim/io/output_file.h"

namespace musclesim {

namespace {

void Validate(const UniformGrid& grid) {
  Require(std::isfinite(grid.from), "from", grid.from, "must be finite");
  Require(std::isfinite(grid.to) && grid.to > grid.from, "to", grid.to,
          "must be finite and greater than from");
  Require(grid.count >= 2, "count", grid.count, "must be an integer >= 2");
}

}  // namespace

std::string FormatLengthCurvesCsv(const TensionModel& model, const UniformGrid& lengths) {
  Validate(lengths);
  std::string csv = "length,f_L,tension_passive\n";
  for (int i = 0; i < lengths.count; ++i) {
    const double x = lengths.At(i);
    csv += FormatFull(x) + ',' + FormatFull(model.active_length().Evaluate(x).value) + ',' +
           FormatFull(PassiveTension(model.params().passive, x).value) + '\n';
  }
  return csv;
}

std::string FormatVelocityCurveCsv(const TensionModel& model, const UniformGrid& velocities) {
  Validate(velocities);
  std::string csv = "shortening_velocity,g\n";
  for (int i = 0; i < velocities.count; ++i) {
    const double v = velocities.At(i);
    csv += FormatFull(v) + ',' + FormatFull(model.velocity().Evaluate(v).value) + '\n';
  }
  return csv;
}

}  // namespace musclesim
