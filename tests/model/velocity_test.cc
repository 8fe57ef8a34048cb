#include "musclesim/model/velocity.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/core/errors.h"
#include "support/numeric.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// the unregularised power law of eq. 12, written independently
double ExactG(double v, double v_max, int n) {
  const double sign = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return 1.0 - sign * std::pow(std::abs(v) / v_max, 1.0 / n);
}

TEST(Velocity, IsometricValueIsOne) {
  for (int n : {1, 2, 3, 5}) {
    const VelocityCurve curve({1.0, n, 1e-3});
    EXPECT_EQ(curve.Evaluate(0.0).value, 1.0) << n;
  }
}

TEST(Velocity, StrictlyDecreasing) {
  for (int n : {1, 2, 3, 5}) {
    const VelocityCurve curve({0.8, n, 1e-3});
    double previous = curve.Evaluate(-2.0).value;
    for (int i = 1; i <= 4000; ++i) {
      const double v = -2.0 + 1e-3 * i;
      const CurvePoint g = curve.Evaluate(v);
      EXPECT_LT(g.value, previous) << "n=" << n << " v=" << v;
      EXPECT_LT(g.slope, 0.0) << "n=" << n << " v=" << v;
      previous = g.value;
    }
  }
}

TEST(Velocity, ZeroAtMaxVelocityAsEpsilonVanishes) {
  // g_eps(v_max) ~ (1 - alpha)/2 (eps / v_max)^2: it falls by 100 per decade of eps
  for (int n : {2, 3, 5}) {
    double previous = 1.0;
    for (double eps : {1e-2, 1e-3, 1e-4, 1e-5}) {
      const double g = std::abs(VelocityCurve({0.5, n, eps}).Evaluate(0.5).value);
      EXPECT_LT(g, 0.5 * (eps / 0.5) * (eps / 0.5)) << "n=" << n << " eps=" << eps;
      EXPECT_LT(g, previous);
      previous = g;
    }
  }
  EXPECT_NEAR(VelocityCurve({0.5, 1, 1e-3}).Evaluate(0.5).value, 0.0, 1e-15);
}

TEST(Velocity, RegularisedPowerApproachesSignedPowerAwayFromZero) {
  // phi_eps / (sgn |v|^alpha) = (1 + eps^2/v^2)^((alpha-1)/2): within eps^2/v^2 of one
  const double eps = 1e-4;
  for (int n : {2, 3, 5}) {
    const VelocityCurve curve({1.0, n, eps});
    for (double v : {-0.9, -0.1, -1e-2, 1e-2, 0.1, 0.5, 1.7}) {
      const double exact = (v > 0 ? 1.0 : -1.0) * std::pow(std::abs(v), 1.0 / n);
      EXPECT_NEAR(curve.Phi(v).value / exact, 1.0, eps * eps / (v * v)) << n << " " << v;
      EXPECT_NEAR(curve.Evaluate(v).value, ExactG(v, 1.0, n), 2.0 * eps * eps / (v * v));
    }
  }
}

TEST(Velocity, SlopeAtZeroIsEpsilonPower) {
  for (int n : {1, 2, 3, 5}) {
    for (double eps : {1e-2, 1e-4, 1e-6}) {
      const VelocityCurve curve({1.0, n, eps});
      const double expected = std::pow(eps, 1.0 / n - 1.0);
      EXPECT_NEAR(curve.Phi(0.0).slope, expected, 1e-13 * expected) << n << " " << eps;
    }
  }
}

TEST(Velocity, SlopeMatchesFiniteDifference) {
  for (int n : {1, 2, 3, 5}) {
    const VelocityCurve curve({0.7, n, 1e-2});
    for (double v : {-1.0, -0.05, -0.003, 0.0, 0.002, 0.01, 0.3, 0.7, 1.4}) {
      const double numeric =
          testing::CentralDifference([&](double w) { return curve.Evaluate(w).value; }, v, 1e-7);
      EXPECT_NEAR(curve.Evaluate(v).slope, numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
          << "n=" << n << " v=" << v;
    }
  }
}

TEST(Velocity, ValidateRejectsEachRule) {
  auto broken = [](VelocityParams p) { return testing::Rejection([&] { Validate(p); }); };
  EXPECT_THAT(broken({0.0, 3, 1e-3}), HasSubstr("v_max = 0: must be > 0 and <= 1e+12 [m/s]"));
  EXPECT_THAT(broken({2e12, 3, 1.0}), HasSubstr("v_max = 2e+12: must be > 0 and <= 1e+12"));
  EXPECT_THAT(broken({1.0, 0, 1e-3}), HasSubstr("n = 0: must be an integer from 1 to 1000"));
  EXPECT_THAT(broken({1.0, 1001, 1e-3}), HasSubstr("n = 1001: must be an integer from 1 to 1000"));
  // the bounds themselves: the flattest curve, the steepest power
  EXPECT_EQ(broken({1e12, 1000, 1.0}), "accepted");
  EXPECT_EQ(broken({1.0, 1, 1e-3}), "accepted");
  EXPECT_THAT(broken({1.0, 3, -1e-3}), HasSubstr("epsilon = -0.001: must be between 1e-12 v_max"));
  EXPECT_THROW(VelocityCurve({1.0, -2, 1e-3}), ParameterError);
}

}  // namespace
}  // namespace musclesim
