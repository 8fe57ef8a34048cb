// Scalar summaries of one run, for sweeps. Each is computed from the recorded trajectory
// (the scenario's output grid, or every internal step with `interval: steps`):
//   final_length              x at the last recorded time [m]
//   min_length, max_length    extremes of x over the run [m]
//   peak_tension              largest total tension T [N]
//   mean_shortening_velocity  (x(w0) - x(w1)) / (w1 - w0) over the window [w0, w1], x linearly
//                             interpolated between records [m/s]
//   final_shortening_velocity v = -dx/dt at the last recorded time [m/s]
//   work                      integral of T v dt, the actuator's mechanical work, positive
//                             when it shortens under tension (trapezoidal rule) [J]
//   time_to_length            first time x reaches target_length from either side, linearly
//                             interpolated; NaN (an empty CSV field) if it never does [s]
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "musclesim/solver/simulation.h"

namespace musclesim {

enum class Metric {
  kFinalLength,
  kMinLength,
  kMaxLength,
  kPeakTension,
  kMeanShorteningVelocity,
  kFinalShorteningVelocity,
  kWork,
  kTimeToLength,
};
std::string_view ToString(Metric metric);
Metric ParseMetric(std::string_view text);  // ParameterError("metrics", text, ...)
const std::vector<Metric>& AllMetrics();

struct MetricOptions {
  std::optional<double> window_start;   // mean_shortening_velocity window [s]; default: the run
  std::optional<double> window_end;
  std::optional<double> target_length;  // time_to_length [m]; required for that metric
};

// The value of `metric` on `trajectory` (at least one point).
double ComputeMetric(Metric metric, const std::vector<TrajectoryPoint>& trajectory,
                     const MetricOptions& options);

}  // namespace musclesim
