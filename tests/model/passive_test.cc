#include "musclesim/model/passive.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "support/numeric.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

const PassiveParams kParams{2.0, 30.0, 0.105};

TEST(Passive, ZeroAtAndBelowSlackLength) {
  for (double x : {-1.0, 0.0, 0.05, 0.1049, 0.105}) {
    EXPECT_EQ(PassiveTension(kParams, x).value, 0.0) << x;
    EXPECT_EQ(PassiveTension(kParams, x).slope, 0.0) << x;
  }
}

TEST(Passive, ContinuousAtSlackLength) {
  // 0 < exp(y) - 1 <= y exp(y): T_p(x0 + h) <= k_p alpha h exp(alpha h), tends to 0
  for (double h : {1e-3, 1e-6, 1e-9}) {
    const double bound = kParams.k_p * kParams.alpha * h * std::exp(kParams.alpha * h);
    EXPECT_GT(PassiveTension(kParams, kParams.slack_length + h).value, 0.0);
    EXPECT_LE(PassiveTension(kParams, kParams.slack_length + h).value, bound);
  }
}

TEST(Passive, IncreasingAndConvexAboveSlack) {
  double previous_value = 0.0, previous_slope = 0.0;
  for (int i = 1; i <= 200; ++i) {
    const double x = kParams.slack_length + 1e-4 * i;
    const CurvePoint p = PassiveTension(kParams, x);
    EXPECT_GT(p.value, previous_value) << x;
    EXPECT_GT(p.slope, previous_slope) << x;  // slope increasing: convex
    previous_value = p.value;
    previous_slope = p.slope;
  }
}

TEST(Passive, SlopeMatchesFiniteDifference) {
  for (double x : {0.106, 0.11, 0.13, 0.2}) {
    const double numeric = testing::CentralDifference(
        [](double y) { return PassiveTension(kParams, y).value; }, x, 1e-7);
    // central difference error ~ h^2 f''' / 6, far below 1e-6 relative here
    EXPECT_NEAR(PassiveTension(kParams, x).slope, numeric, 1e-6 * std::abs(numeric)) << x;
  }
}

TEST(Passive, ValidateRejectsEachRule) {
  auto broken = [](PassiveParams p) { return testing::Rejection([&] { Validate(p); }); };
  EXPECT_THAT(broken({-1.0, 30.0, 0.1}), HasSubstr("k_p = -1: must be from 0 to 1e+09 [N]"));
  EXPECT_THAT(broken({2e9, 30.0, 0.1}), HasSubstr("k_p = 2e+09: must be from 0 to 1e+09 [N]"));
  EXPECT_THAT(broken({1.0, 0.0, 0.1}), HasSubstr("alpha = 0: must be > 0 and <= 1e+09 [1/m]"));
  EXPECT_THAT(broken({1.0, 2e9, 0.1}), HasSubstr("alpha = 2e+09: must be > 0 and <= 1e+09"));
  EXPECT_THAT(broken({1.0, 30.0, std::numeric_limits<double>::quiet_NaN()}),
              HasSubstr("slack_length = nan: must be from -1000 to 1000 [m]"));
  EXPECT_THAT(broken({1.0, 30.0, -2e3}), HasSubstr("slack_length = -2000: must be from -1000"));
  // each bound itself is accepted: no passive tension, the steepest rate, the farthest slack
  EXPECT_EQ(broken({0.0, 30.0, 0.1}), "accepted");
  EXPECT_EQ(broken({1e9, 1e9, -1e3}), "accepted");
  EXPECT_THAT(broken({std::numeric_limits<double>::infinity(), 30.0, 0.1}), HasSubstr("k_p = inf"));
  EXPECT_EQ(broken(kParams), "accepted");
}

}  // namespace
}  // namespace musclesim
