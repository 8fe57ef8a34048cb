#include "musclesim/studies/metrics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/errors.h"

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

TEST(Metrics, NamesRoundTrip) {
  for (Metric m : AllMetrics()) EXPECT_EQ(ParseMetric(ToString(m)), m);
  EXPECT_THAT([] { ParseMetric("speed"); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("metrics = speed")));
}

}  // namespace
}  // namespace musclesim
