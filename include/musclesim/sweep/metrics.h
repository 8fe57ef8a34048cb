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
  std::optional<double> window_start;  // mean_shortening_velocity window [s]; default: the run
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

// The same metrics computed as a run records its points, without keeping them: a sweep's
// sink. Each value equals ComputeMetric's on the same points to the last bit (the same
// operations in the same order); only what the chosen metrics need is tracked.
class MetricAccumulator final : public TrajectorySink {
 public:
  MetricAccumulator(const std::vector<Metric>& metrics, const MetricOptions& options);

  void Reset();  // forgets the points, for the next run
  void Record(const TrajectoryPoint& point) override;
  long points() const { return points_; }
  // The value of `metric` (one of those given) on the points recorded since the last Reset;
  // at least one point.
  double Value(Metric metric) const;

 private:
  // x at `at` as ComputeMetric's linear interpolation between records finds it, tracked
  // while the points come (the record pair around it) and completed at the end.
  struct LengthProbe {
    double at = 0.0;      // [s]
    bool found = false;   // a pair of records around `at` was seen
    double length = 0.0;  // [m], the interpolated value when found
  };
  // What the metrics read of a recorded point.
  struct Mark {
    double t = 0.0, length = 0.0, shortening_velocity = 0.0, tension = 0.0;
  };
  void Probe(LengthProbe& probe, const Mark& a, const Mark& b) const;
  double LengthAt(double t, const LengthProbe& probe) const;

  MetricOptions options_;
  bool extremes_ = false, peak_ = false, work_ = false, window_ = false, crossing_ = false;
  long points_ = 0;
  Mark first_, last_;
  double min_length_ = 0.0, max_length_ = 0.0, peak_tension_ = 0.0, work_sum_ = 0.0;
  LengthProbe window_start_, window_end_;  // used when window_ and the window's ends are given
  bool crossed_ = false;
  double crossing_time_ = 0.0;  // [s], time_to_length once crossed_
};

}  // namespace musclesim
