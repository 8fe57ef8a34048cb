#include "musclesim/sweep/metrics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

// x(t) = 0.1 - 0.02 t on [0, 1] every 0.1 s, shortening at 0.02 m/s under T = 50 N,
// with a tension peak of 80 N at t = 0.3: every metric has a value by hand.
std::vector<TrajectoryPoint> Straight() {
  std::vector<TrajectoryPoint> tr;
  for (int i = 0; i <= 10; ++i) {
    TrajectoryPoint p{0.1 * i, {}};
    p.sample.length = 0.1 - 0.02 * p.t;
    p.sample.shortening_velocity = 0.02;
    p.sample.tension.total = i == 3 ? 80.0 : 50.0;
    tr.push_back(p);
  }
  return tr;
}

TEST(Metrics, HandComputedValuesOnAStraightShortening) {
  const std::vector<TrajectoryPoint> tr = Straight();
  MetricOptions options;
  options.window_start = 0.25;
  options.window_end = 0.75;
  options.target_length = 0.095;
  EXPECT_NEAR(ComputeMetric(Metric::kFinalLength, tr, options), 0.08, 1e-15);
  EXPECT_NEAR(ComputeMetric(Metric::kMinLength, tr, options), 0.08, 1e-15);
  EXPECT_EQ(ComputeMetric(Metric::kMaxLength, tr, options), 0.1);
  EXPECT_EQ(ComputeMetric(Metric::kPeakTension, tr, options), 80.0);
  EXPECT_NEAR(ComputeMetric(Metric::kMeanShorteningVelocity, tr, options), 0.02, 1e-14);
  EXPECT_EQ(ComputeMetric(Metric::kFinalShorteningVelocity, tr, options), 0.02);
  // integral of T v dt: 50 * 0.02 * 1 plus the peak's trapezoids 2 * 0.5 * 0.1 * 30 * 0.02
  EXPECT_NEAR(ComputeMetric(Metric::kWork, tr, options), 1.0 + 0.06, 1e-14);
  // x = 0.095 at t = 0.25, between records
  EXPECT_NEAR(ComputeMetric(Metric::kTimeToLength, tr, options), 0.25, 1e-13);
}

TEST(Metrics, UnreachedTargetAndEmptyWindowAreNaN) {
  const std::vector<TrajectoryPoint> tr = Straight();
  MetricOptions options;
  options.target_length = 0.05;
  EXPECT_TRUE(std::isnan(ComputeMetric(Metric::kTimeToLength, tr, options)));
  options.window_start = 2.0;
  options.window_end = 3.0;
  EXPECT_TRUE(std::isnan(ComputeMetric(Metric::kMeanShorteningVelocity, tr, options)));
}

// The streaming accumulator gives the hand-computed values of the straight shortening.
TEST(Metrics, AccumulatorGivesTheHandComputedValues) {
  MetricOptions options;
  options.window_start = 0.25;
  options.window_end = 0.75;
  options.target_length = 0.095;
  MetricAccumulator acc(AllMetrics(), options);
  for (const TrajectoryPoint& p : Straight()) acc.Record(p);
  EXPECT_NEAR(acc.Value(Metric::kFinalLength), 0.08, 1e-15);  // a few ulps of 0.1 - 0.02
  EXPECT_NEAR(acc.Value(Metric::kMinLength), 0.08, 1e-15);
  EXPECT_EQ(acc.Value(Metric::kMaxLength), 0.1);
  EXPECT_EQ(acc.Value(Metric::kPeakTension), 80.0);
  // (0.095 - 0.085) / 0.5, each end interpolated between records: rounding of a few ulps
  EXPECT_NEAR(acc.Value(Metric::kMeanShorteningVelocity), 0.02, 1e-14);
  EXPECT_EQ(acc.Value(Metric::kFinalShorteningVelocity), 0.02);
  EXPECT_NEAR(acc.Value(Metric::kWork), 1.0 + 0.06, 1e-14);    // eleven trapezoids' rounding
  EXPECT_NEAR(acc.Value(Metric::kTimeToLength), 0.25, 1e-13);  // interpolated crossing
}

// A lengthening and shortening run with uneven steps and a repeated time (a restart):
// every metric of the accumulator equals the batch computation on the kept trajectory bit
// for bit (the same operations in the same order), for windows and targets inside, at the
// ends of and outside the records, and after a Reset.
TEST(Metrics, AccumulatorMatchesTheTrajectoryBitForBit) {
  std::vector<TrajectoryPoint> tr;
  double t = 0.0;
  for (int i = 0; i < 40; ++i) {
    TrajectoryPoint p{t, {}};
    p.sample.length = 0.1 + 0.01 * std::sin(7.0 * t);
    p.sample.shortening_velocity = -0.07 * std::cos(7.0 * t);
    p.sample.tension.total = 50.0 + 30.0 * std::sin(3.0 * t);
    tr.push_back(p);
    if (i != 17) t += 0.01 + 0.003 * (i % 4);  // point 18 repeats the time of point 17
  }
  const double end = tr.back().t;
  struct Case {
    std::optional<double> w0, w1, target;
  };
  const std::vector<Case> cases = {{std::nullopt, std::nullopt, 0.105},
                                   {0.05, 0.3, 0.095},
                                   {tr[17].t, tr[30].t, 0.2},
                                   {-1.0, end + 1.0, tr[5].sample.length},
                                   {0.1, std::nullopt, 0.1},
                                   {end + 1.0, end + 2.0, 0.09},
                                   {std::nullopt, 0.0, std::nullopt}};
  for (std::size_t c = 0; c < cases.size(); ++c) {
    MetricOptions options;
    options.window_start = cases[c].w0;
    options.window_end = cases[c].w1;
    options.target_length = cases[c].target;
    MetricAccumulator acc(AllMetrics(), options);
    acc.Record(tr[3]);  // forgotten by the Reset
    acc.Reset();
    for (const TrajectoryPoint& p : tr) acc.Record(p);
    for (Metric m : AllMetrics()) {
      const double batch = ComputeMetric(m, tr, options);
      const double streamed = acc.Value(m);
      if (std::isnan(batch)) {
        EXPECT_TRUE(std::isnan(streamed)) << "case " << c << ": " << ToString(m);
      } else {
        EXPECT_EQ(streamed, batch) << "case " << c << ": " << ToString(m);
      }
    }
  }
}

TEST(Metrics, NamesRoundTrip) {
  for (Metric m : AllMetrics()) EXPECT_EQ(ParseMetric(ToString(m)), m);
  EXPECT_THAT([] { ParseMetric("speed"); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("metrics = speed")));
}

}  // namespace
}  // namespace musclesim
