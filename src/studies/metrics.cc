#include "musclesim/studies/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "musclesim/errors.h"
#include "musclesim/model/enum_names.h"

namespace musclesim {

const std::vector<Metric>& AllMetrics() {
  static const std::vector<Metric> all = {
      Metric::kFinalLength, Metric::kMinLength, Metric::kMaxLength,
      Metric::kPeakTension, Metric::kMeanShorteningVelocity, Metric::kFinalShorteningVelocity,
      Metric::kWork, Metric::kTimeToLength};
  return all;
}

constexpr EnumName<Metric> kMetricNames[] = {
    {Metric::kFinalLength, "final_length"},
    {Metric::kMinLength, "min_length"},
    {Metric::kMaxLength, "max_length"},
    {Metric::kPeakTension, "peak_tension"},
    {Metric::kMeanShorteningVelocity, "mean_shortening_velocity"},
    {Metric::kFinalShorteningVelocity, "final_shortening_velocity"},
    {Metric::kWork, "work"},
    {Metric::kTimeToLength, "time_to_length"},
};

std::string_view ToString(Metric metric) { return ToString(kMetricNames, metric); }

Metric ParseMetric(std::string_view text) { return Parse(kMetricNames, "metrics", text); }

namespace {

// x at time t, linear between records, held at the ends.
double LengthAt(const std::vector<TrajectoryPoint>& tr, double t) {
  if (t <= tr.front().t) return tr.front().sample.length;
  if (t >= tr.back().t) return tr.back().sample.length;
  const auto right = std::upper_bound(tr.begin(), tr.end(), t,
                                      [](double s, const TrajectoryPoint& p) { return s < p.t; });
  const TrajectoryPoint& a = *(right - 1);
  const TrajectoryPoint& b = *right;
  return a.sample.length + (b.sample.length - a.sample.length) * (t - a.t) / (b.t - a.t);
}

}  // namespace

TrajectoryPoint ElementPoint(double t, const ElementSample& element) {
  TrajectoryPoint point{t, {}};
  point.sample.length = element.length;
  point.sample.shortening_velocity = -element.lengthening_rate;
  point.sample.activation = element.activation;
  point.sample.excitation = element.excitation;
  point.sample.tension = element.parts;  // all zero but for an actuator
  point.sample.tension.total = element.tension;
  return point;
}

double ComputeMetric(Metric metric, const std::vector<TrajectoryPoint>& tr,
                     const MetricOptions& options) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (metric) {
    case Metric::kFinalLength:
      return tr.back().sample.length;
    case Metric::kMinLength:
    case Metric::kMaxLength: {
      const auto [lo, hi] = std::minmax_element(
          tr.begin(), tr.end(), [](const TrajectoryPoint& a, const TrajectoryPoint& b) {
            return a.sample.length < b.sample.length;
          });
      return metric == Metric::kMinLength ? lo->sample.length : hi->sample.length;
    }
    case Metric::kPeakTension: {
      double peak = -std::numeric_limits<double>::infinity();
      for (const TrajectoryPoint& p : tr) peak = std::max(peak, p.sample.tension.total);
      return peak;
    }
    case Metric::kMeanShorteningVelocity: {
      const double w0 = options.window_start.value_or(tr.front().t);
      const double w1 = std::min(options.window_end.value_or(tr.back().t), tr.back().t);
      if (!(w1 > w0)) return nan;  // the run ended before the window
      return (LengthAt(tr, w0) - LengthAt(tr, w1)) / (w1 - w0);
    }
    case Metric::kFinalShorteningVelocity:
      return tr.back().sample.shortening_velocity;
    case Metric::kWork: {
      double work = 0.0;
      for (std::size_t i = 1; i < tr.size(); ++i) {
        const ActuatorSample& a = tr[i - 1].sample;
        const ActuatorSample& b = tr[i].sample;
        work += 0.5 * (tr[i].t - tr[i - 1].t) *
                (a.tension.total * a.shortening_velocity + b.tension.total * b.shortening_velocity);
      }
      return work;
    }
    case Metric::kTimeToLength: {
      if (!options.target_length) return nan;
      const double target = *options.target_length;
      if (tr.front().sample.length == target) return tr.front().t;
      for (std::size_t i = 1; i < tr.size(); ++i) {
        const double a = tr[i - 1].sample.length - target;
        const double b = tr[i].sample.length - target;
        if (b == 0.0) return tr[i].t;
        if ((a < 0.0) != (b < 0.0)) {
          return tr[i - 1].t + (tr[i].t - tr[i - 1].t) * a / (a - b);
        }
      }
      return nan;
    }
  }
  return nan;
}

}  // namespace musclesim
