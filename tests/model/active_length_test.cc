#include "musclesim/model/active_length.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "musclesim/core/errors.h"
#include "support/numeric.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// psi_k written out from eq. 4 directly
double SumOfGaussians(const ActiveLengthParams& p, double x) {
  double f = 0.0;
  for (const Gaussian& g : p.gaussians) {
    f += g.amplitude / std::sqrt(2.0 * std::numbers::pi * p.sigma) *
         std::exp(-g.precision * (x - g.center) * (x - g.center) / (2.0 * p.sigma));
  }
  return f;
}

ActiveLengthParams TwoBumps() {
  // two separated components: f has two maxima inside L_opt, the right one higher
  return {0.09, 0.11, 1.0, {{1.0, 4e6, 0.095}, {1.2, 4e6, 0.104}}};
}

ActiveLengthParams RandomParams(std::mt19937& rng) {
  std::uniform_real_distribution<double> amplitude(0.2, 2.0), center(0.092, 0.108),
      log_spread(std::log(5e-4), std::log(2e-2));
  ActiveLengthParams p{0.095, 0.105, 1.0, {}};
  const int m = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < m; ++k) {
    const double spread = std::exp(log_spread(rng));
    p.gaussians.push_back({amplitude(rng), 1.0 / (spread * spread), center(rng)});
  }
  return p;
}

TEST(ActiveLength, SumMatchesDefinition) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const ActiveLengthParams p = RandomParams(rng);
    const GaussianSum sum(p.gaussians, p.sigma);
    for (double x : {0.08, 0.095, 0.1, 0.1033, 0.12}) {
      EXPECT_NEAR(sum.Value(x), SumOfGaussians(p, x), 1e-13 * (1.0 + SumOfGaussians(p, x)));
    }
  }
}

TEST(ActiveLength, UnitTermIsAComponentOverItsAmplitude) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 20; ++trial) {
    ActiveLengthParams p = RandomParams(rng);
    p.sigma = 0.5 + trial * 0.1;  // only b / sigma matters, so any sigma must agree
    for (const Gaussian& g : p.gaussians) {
      const ActiveLengthParams one{p.optimal_min, p.optimal_max, p.sigma, {g}};
      const GaussianTerm phi = GaussianTerm::Unit(g.precision, g.center, p.sigma);
      for (double x : {0.08, 0.095, 0.1, 0.1033, 0.12}) {
        // a few roundings apart: one exp, a division and products
        EXPECT_NEAR(g.amplitude * phi(x), SumOfGaussians(one, x),
                    1e-14 * (1.0 + SumOfGaussians(one, x)));
      }
    }
  }
}

TEST(ActiveLength, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const ActiveLengthParams p = RandomParams(rng);
    const GaussianSum sum(p.gaussians, p.sigma);
    // far in a tail (z = 10 spreads) the third derivative is z^2 / s^2 times the first:
    // a step of 1e-5 s keeps the truncation error near 1e-9 relative
    const double h = 1e-5 * sum.NarrowestSpread();
    for (double x : {0.09, 0.097, 0.1, 0.104, 0.11}) {
      const double slope = (sum.Value(x + h) - sum.Value(x - h)) / (2 * h);
      const double curvature =
          (sum.ValueAndSlope(x + h).slope - sum.ValueAndSlope(x - h).slope) / (2 * h);
      // O(h^2) truncation relative to the curve's own scale f / s^2
      const double scale = 1.0 + std::abs(sum.Value(x)) / sum.NarrowestSpread();
      EXPECT_NEAR(sum.ValueAndSlope(x).slope, slope, 1e-6 * scale);
      EXPECT_NEAR(sum.Curvature(x), curvature, 1e-6 * scale / sum.NarrowestSpread());
    }
  }
}

// Brute force: the largest value on a 2-million-point grid, refined by golden section in
// the two neighbouring cells. Independent of the bracketing the library does.
double BruteMaximum(const ActiveLengthParams& p) {
  const int cells = 2000000;
  const double lo = p.optimal_min, hi = p.optimal_max, step = (hi - lo) / cells;
  int best = 0;
  for (int i = 1; i <= cells; ++i) {
    if (SumOfGaussians(p, lo + i * step) > SumOfGaussians(p, lo + best * step)) best = i;
  }
  double a = std::max(lo, lo + (best - 1) * step), b = std::min(hi, lo + (best + 1) * step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200; ++it) {
    const double c = b - ratio * (b - a), d = a + ratio * (b - a);
    if (SumOfGaussians(p, c) > SumOfGaussians(p, d))
      b = d;
    else
      a = c;
  }
  return std::max(SumOfGaussians(p, 0.5 * (a + b)), SumOfGaussians(p, lo + best * step));
}

TEST(ActiveLength, NormaliserIsTheExactMaximumOverOptimalRange) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 12; ++trial) {
    const ActiveLengthParams p = RandomParams(rng);
    const ActiveLengthCurve curve(p);
    const double brute = BruteMaximum(p);
    EXPECT_NEAR(curve.peak_value(), brute, 1e-12 * brute) << "trial " << trial;
    EXPECT_GE(curve.peak_value(), brute * (1.0 - 1e-14));  // never below any grid value
    EXPECT_NEAR(curve.Evaluate(curve.optimal_length()).value, 1.0, 1e-14);
    EXPECT_GE(curve.optimal_length(), p.optimal_min);
    EXPECT_LE(curve.optimal_length(), p.optimal_max);
  }
}

TEST(ActiveLength, FindsTheHigherOfTwoInteriorMaxima) {
  const ActiveLengthCurve curve(TwoBumps());
  EXPECT_NEAR(curve.optimal_length(), 0.104, 1e-6);
  EXPECT_NEAR(curve.peak_value(), BruteMaximum(TwoBumps()), 1e-12 * curve.peak_value());
  EXPECT_LT(curve.Evaluate(0.095).value, 1.0);
}

TEST(ActiveLength, MaximumAtAnEndOfTheRange) {
  // a single Gaussian centred right of L_opt: the maximum is at l2
  const ActiveLengthParams p{0.095, 0.105, 1.0, {{1.0, 1e5, 0.11}}};
  const ActiveLengthCurve curve(p);
  EXPECT_EQ(curve.optimal_length(), 0.105);
  EXPECT_DOUBLE_EQ(curve.peak_value(), SumOfGaussians(p, 0.105));
}

TEST(ActiveLength, NormalisedSlopeIsScaledSlope) {
  const ActiveLengthCurve curve(TwoBumps());
  for (double x : {0.09, 0.1, 0.107}) {
    const double numeric =
        testing::CentralDifference([&](double y) { return curve.Evaluate(y).value; }, x, 1e-8);
    EXPECT_NEAR(curve.Evaluate(x).slope, numeric, 1e-5 * std::max(1.0, std::abs(numeric)));
  }
}

TEST(ActiveLength, NarrowestSpreadIsTheSmallestStandardDeviation) {
  // spreads sqrt(sigma / b_k) of 1.58 mm, 0.79 mm and 3.16 mm under sigma = 0.5: the second
  const double sigma = 0.5;
  const GaussianSum sum({{1.0, 2e5, 0.1}, {-0.3, 8e5, 0.098}, {2.0, 5e4, 0.103}}, sigma);
  // sqrt(sigma / b) and 1 / sqrt(2 b / (2 sigma)) differ by a few roundings: 1e-15 relative
  const double narrowest = std::sqrt(sigma / 8e5);
  EXPECT_NEAR(sum.NarrowestSpread(), narrowest, 1e-15 * narrowest);
}

std::string Rejection(const ActiveLengthParams& p) {
  return testing::Rejection([&] { ActiveLengthCurve curve(p); });
}

TEST(ActiveLength, RejectsEachRule) {
  EXPECT_THAT(Rejection({0.1, 0.1, 1.0, {{1, 1, 0.1}}}),
              HasSubstr("optimal_range[1] = 0.1: must be finite and greater than"));
  EXPECT_THAT(Rejection({0.1, 0.2, 0.0, {{1, 1, 0.1}}}), HasSubstr("sigma = 0: must be"));
  EXPECT_THAT(Rejection({0.1, 0.2, 1.0, {}}), HasSubstr("gaussians = []: needs at least one"));
  EXPECT_THAT(Rejection({0.1, 0.2, 1.0, {{1, 1, 0.1}, {1, -3, 0.1}}}),
              HasSubstr("gaussians[1].width = -3: must be finite and > 0"));
  EXPECT_THAT(Rejection({0.1, 0.2, 1.0, {{-1, 100, 0.15}}}),
              HasSubstr("must be positive somewhere on optimal_range"));
}

}  // namespace
}  // namespace musclesim
