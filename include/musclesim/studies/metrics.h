// Scalar summaries of one run, for sweeps. Each is computed from the recorded trajectory
// (the scenario's output grid, or every internal step with `interval: steps`) of one element:
// the actuator of the single-actuator form, or the element of a network that
// metric_options.element names (by default its only actuator). x is that element's length,
// v = -dx/dt its shortening velocity and T its tension:
//   final_length              x at the last recorded time [m]
//   min_length, max_length    extremes of x over the run [m]
//   peak_tension              largest total tension T [N]
//   mean_shortening_velocity  (x(w0) - x(w1)) / (w1 - w0) over the window [w0, w1], x linearly
//                             interpolated between records [m/s]
//   final_shortening_velocity v = -dx/dt at the last recorded time [m/s]
//   work                      integral of T v dt, the element's mechanical work, positive
//                             when it shortens under tension (trapezoidal rule) [J]
//   time_to_length            first time x reaches target_length from either side, linearly
//                             interpolated; NaN (an empty CSV field) if it never does [s]
// For an element of another kind (docs/model.md 7.1) the same formulas read its own length
// and tension: a spring's T is negative while it is compressed, so its peak_tension may be
// negative; `work` is the work its tension does on its two nodes, which for a spring or an
// elastic tendon is the elastic energy it gave up (E_el at the start minus at the end), and
// for a damper -integral of c (dx/dt)^2 dt <= 0, the energy it dissipated.
#pragma once

#include <optional>
#include <string>
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
  // The element whose trajectory the metrics read: a network's element name, or `actuator`
  // for the single-actuator form [-]. Sweeps resolve it (LoadSweep); ComputeMetric does not
  // read it: its caller passes that element's trajectory.
  std::string element;
};

// One element of a network's sample as the metrics read it: its length, shortening velocity
// -dl/dt, activation and tension parts (for an element that is not an actuator, its tension
// in tension.total, passive and active 0); load 0.
TrajectoryPoint ElementPoint(double t, const ElementSample& element);

// The value of `metric` on `trajectory` (at least one point).
double ComputeMetric(Metric metric, const std::vector<TrajectoryPoint>& trajectory,
                     const MetricOptions& options);

}  // namespace musclesim
