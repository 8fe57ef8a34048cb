#include "musclesim/sweep/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/enum_names.h"

namespace musclesim {

const std::vector<Metric>& AllMetrics() {
  static const std::vector<Metric> all = {Metric::kFinalLength,
                                          Metric::kMinLength,
                                          Metric::kMaxLength,
                                          Metric::kPeakTension,
                                          Metric::kMeanShorteningVelocity,
                                          Metric::kFinalShorteningVelocity,
                                          Metric::kWork,
                                          Metric::kTimeToLength};
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
    case Metric::kFinalLength: return tr.back().sample.length;
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
    case Metric::kFinalShorteningVelocity: return tr.back().sample.shortening_velocity;
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

MetricAccumulator::MetricAccumulator(const std::vector<Metric>& metrics,
                                     const MetricOptions& options)
    : options_(options) {
  for (Metric m : metrics) {
    extremes_ = extremes_ || m == Metric::kMinLength || m == Metric::kMaxLength;
    peak_ = peak_ || m == Metric::kPeakTension;
    work_ = work_ || m == Metric::kWork;
    window_ = window_ || m == Metric::kMeanShorteningVelocity;
    crossing_ = crossing_ || m == Metric::kTimeToLength;
  }
  Reset();
}

void MetricAccumulator::Reset() {
  points_ = 0;
  peak_tension_ = -std::numeric_limits<double>::infinity();
  work_sum_ = 0.0;
  window_start_ = {options_.window_start.value_or(0.0), false, 0.0};
  window_end_ = {options_.window_end.value_or(0.0), false, 0.0};
  crossed_ = false;
}

void MetricAccumulator::Probe(LengthProbe& probe, const Mark& a, const Mark& b) const {
  // ComputeMetric's pair: b the first record later than `at`, a the one before it
  if (probe.found || !(a.t <= probe.at && probe.at < b.t)) return;
  probe.found = true;
  probe.length = a.length + (b.length - a.length) * (probe.at - a.t) / (b.t - a.t);
}

double MetricAccumulator::LengthAt(double t, const LengthProbe& probe) const {
  if (t <= first_.t) return first_.length;
  if (t >= last_.t) return last_.length;
  return probe.length;  // first_.t < t = probe.at < last_.t: some pair of records held it
}

void MetricAccumulator::Record(const TrajectoryPoint& point) {
  const Mark p{point.t, point.sample.length, point.sample.shortening_velocity,
               point.sample.tension.total};
  if (points_ == 0) {
    first_ = p;
    min_length_ = max_length_ = p.length;
    if (crossing_ && options_.target_length && p.length == *options_.target_length) {
      crossed_ = true;
      crossing_time_ = p.t;
    }
  } else {
    const Mark& a = last_;
    if (extremes_) {
      if (p.length < min_length_) min_length_ = p.length;
      if (!(p.length < max_length_)) max_length_ = p.length;
    }
    if (work_) {
      work_sum_ += 0.5 * (p.t - a.t) *
                   (a.tension * a.shortening_velocity + p.tension * p.shortening_velocity);
    }
    if (window_) {
      if (options_.window_start) Probe(window_start_, a, p);
      if (options_.window_end) Probe(window_end_, a, p);
    }
    if (crossing_ && !crossed_ && options_.target_length) {
      const double target = *options_.target_length;
      const double da = a.length - target;
      const double db = p.length - target;
      if (db == 0.0) {
        crossed_ = true;
        crossing_time_ = p.t;
      } else if ((da < 0.0) != (db < 0.0)) {
        crossed_ = true;
        crossing_time_ = a.t + (p.t - a.t) * da / (da - db);
      }
    }
  }
  if (peak_) peak_tension_ = std::max(peak_tension_, p.tension);
  last_ = p;
  ++points_;
}

double MetricAccumulator::Value(Metric metric) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (metric) {
    case Metric::kFinalLength: return last_.length;
    case Metric::kMinLength: return min_length_;
    case Metric::kMaxLength: return max_length_;
    case Metric::kPeakTension: return peak_tension_;
    case Metric::kMeanShorteningVelocity: {
      const double w0 = options_.window_start.value_or(first_.t);
      const double w1 = std::min(options_.window_end.value_or(last_.t), last_.t);
      if (!(w1 > w0)) return nan;
      // a probe is at w0 (w1) whenever w0 (w1) may lie strictly inside the records
      return (LengthAt(w0, window_start_) - LengthAt(w1, window_end_)) / (w1 - w0);
    }
    case Metric::kFinalShorteningVelocity: return last_.shortening_velocity;
    case Metric::kWork: return work_sum_;
    case Metric::kTimeToLength: return crossed_ ? crossing_time_ : nan;
  }
  return nan;
}

}  // namespace musclesim
