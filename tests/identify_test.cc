#include "musclesim/studies/identify.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "musclesim/errors.h"
#include "musclesim/studies/identify_report.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// Standard normal draws (Box-Muller on mt19937_64): reproducible on every platform.
class Noise {
 public:
  explicit Noise(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(rng_() >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 rng_;
};

constexpr double kKp = 1.0, kAlpha = 100.0, kSlack = 0.1043;

std::vector<DataPoint> PassiveData(double noise, std::uint64_t seed) {
  Noise normal(seed);
  std::vector<DataPoint> data;
  for (int i = 0; i < 29; ++i) {
    const double x = 0.09 + 0.0025 * i;
    const double t = x > kSlack ? kKp * std::expm1(kAlpha * (x - kSlack)) : 0.0;
    data.push_back({x, t + noise * normal()});
  }
  return data;
}

TEST(IdentifyPassive, RecoversExactDataToNearMachinePrecision) {
  const PassiveIdentification fit = IdentifyPassive(PassiveData(0.0, 1));
  EXPECT_NEAR(fit.k_p.value, kKp, 1e-8 * kKp);
  EXPECT_NEAR(fit.alpha.value, kAlpha, 1e-8 * kAlpha);
  EXPECT_NEAR(fit.slack_length.value, kSlack, 1e-10);
  EXPECT_LT(fit.rmse, 1e-9);
}

// |estimate - truth| <= 3 standard errors: true for 99.7% of fits when the standard errors
// are right; asked here of at least 18 fits in 20 at each noise level.
int WithinThreeErrors(const Estimate& e, double truth) {
  return std::abs(e.value - truth) <= 3.0 * e.standard_error;
}

TEST(IdentifyPassive, RecoversParametersWithinTheirStandardErrors) {
  for (double noise : {0.01, 0.1, 0.5}) {  // N, against tensions up to 170 N
    int covered[3] = {0, 0, 0};
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const PassiveIdentification fit = IdentifyPassive(PassiveData(noise, seed));
      covered[0] += WithinThreeErrors(fit.k_p, kKp);
      covered[1] += WithinThreeErrors(fit.alpha, kAlpha);
      covered[2] += WithinThreeErrors(fit.slack_length, kSlack);
    }
    for (int c : covered) EXPECT_GE(c, 18) << "noise " << noise;
  }
}

std::vector<DataPoint> VelocityData(double noise, std::uint64_t seed, double f_iso, double v_max,
                                    int n) {
  Noise normal(seed);
  std::vector<DataPoint> data;
  for (int i = 0; i < 31; ++i) {
    const double v = -0.5 + 0.05 * i;
    const double s = ((v > 0) - (v < 0)) * std::pow(std::abs(v) / v_max, 1.0 / n);
    data.push_back({v, f_iso * (1.0 - s) + noise * normal()});
  }
  return data;
}

TEST(IdentifyVelocity, RecoversExactDataAndTheExponent) {
  for (int n : {1, 2, 3, 5}) {
    const VelocityIdentification fit = IdentifyVelocity(VelocityData(0.0, 1, 100.0, 0.8, n), std::nullopt);
    EXPECT_EQ(fit.best.n, n);
    EXPECT_NEAR(fit.best.v_max.value, 0.8, 1e-10);
    EXPECT_NEAR(fit.best.f_iso.value, 100.0, 1e-10);
    EXPECT_EQ(fit.candidates.size(), 10u);
  }
}

TEST(IdentifyVelocity, RecoversParametersWithinTheirStandardErrors) {
  for (double noise : {0.1, 1.0, 3.0}) {
    int covered_v = 0, covered_f = 0, right_n = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const VelocityIdentification fit =
          IdentifyVelocity(VelocityData(noise, seed, 100.0, 1.0, 3), std::nullopt);
      if (fit.best.n != 3) continue;
      ++right_n;
      covered_v += WithinThreeErrors(fit.best.v_max, 1.0);
      covered_f += WithinThreeErrors(fit.best.f_iso, 100.0);
    }
    EXPECT_GE(right_n, 18) << "noise " << noise;
    EXPECT_GE(covered_v, right_n - 2) << "noise " << noise;
    EXPECT_GE(covered_f, right_n - 2) << "noise " << noise;
  }
}

TEST(IdentifyVelocity, HoldsAGivenIsometricTension) {
  const VelocityIdentification fit = IdentifyVelocity(VelocityData(0.0, 1, 100.0, 1.2, 2), 100.0);
  EXPECT_EQ(fit.best.f_iso.value, 100.0);
  EXPECT_EQ(fit.best.f_iso.standard_error, 0.0);
  EXPECT_NEAR(fit.best.v_max.value, 1.2, 1e-10);
}

std::vector<DataPoint> ActiveData(double noise, std::uint64_t seed) {
  Noise normal(seed);
  std::vector<DataPoint> data;
  for (int i = 0; i < 41; ++i) {
    const double x = 0.06 + 0.002 * i;
    const double f = 0.02 / std::sqrt(2 * std::numbers::pi) * std::exp(-2e4 * std::pow(x - 0.095, 2) / 2) +
                     0.015 / std::sqrt(2 * std::numbers::pi) * std::exp(-1e4 * std::pow(x - 0.11, 2) / 2);
    data.push_back({x, 2000.0 * f + noise * normal()});
  }
  return data;
}

TEST(IdentifyActive, RecoversExactDataAndItsMaximum) {
  const std::vector<DataPoint> data = ActiveData(0.0, 1);
  const ActiveIdentification fit = IdentifyActive(data, 2, true);
  EXPECT_LT(fit.rmse, 1e-8);
  // f_iso is the curve's maximum: brute force over a fine grid of the true curve
  double peak = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double x = 0.06 + 0.08 * i / 100000;
    const double f = 0.02 / std::sqrt(2 * std::numbers::pi) * std::exp(-2e4 * std::pow(x - 0.095, 2) / 2) +
                     0.015 / std::sqrt(2 * std::numbers::pi) * std::exp(-1e4 * std::pow(x - 0.11, 2) / 2);
    peak = std::max(peak, 2000.0 * f);
  }
  EXPECT_NEAR(fit.f_iso.value, peak, 1e-7 * peak);
  for (const DataPoint& p : data) EXPECT_NEAR(fit.Evaluate(p.x), p.y, 1e-7 * peak);
}

TEST(IdentifyActive, IsometricTensionWithinItsStandardError) {
  // the Gaussians themselves trade off against each other; their maximum is identifiable
  const double truth = IdentifyActive(ActiveData(0.0, 1), 2, true).f_iso.value;
  for (double noise : {0.1, 0.5, 2.0}) {  // N, against a peak near 400 N
    int covered = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      covered += WithinThreeErrors(IdentifyActive(ActiveData(noise, seed), 2, true).f_iso, truth);
    }
    EXPECT_GE(covered, 18) << "noise " << noise;
  }
}

TEST(ReferenceFits, SplineAndPolynomialsReproduceWhatTheyCan) {
  std::vector<DataPoint> line, cubic;
  for (int i = 0; i < 9; ++i) {
    const double x = 0.3 * i * i;  // uneven knots
    line.push_back({x, 2.0 - 3.0 * x});
    cubic.push_back({x, 1.0 + x - 0.5 * x * x + 0.01 * x * x * x});
  }
  const NaturalCubicSpline spline(line);
  const PolynomialFit poly3(cubic, 3), poly4(cubic, 4);
  for (double x : {-1.0, 0.1, 2.5, 7.0, 30.0}) {
    EXPECT_NEAR(spline(x), 2.0 - 3.0 * x, 1e-12 * (1 + std::abs(x)));  // linear, even outside
    const double truth = 1.0 + x - 0.5 * x * x + 0.01 * x * x * x;
    EXPECT_NEAR(poly3(x), truth, 1e-8 * (1 + std::abs(truth)));
    EXPECT_NEAR(poly4(x), truth, 1e-8 * (1 + std::abs(truth)));
  }
  const NaturalCubicSpline through(cubic);
  for (const DataPoint& p : cubic) EXPECT_NEAR(through(p.x), p.y, 1e-12 * (1 + std::abs(p.y)));
}

TEST(IdentifyReport, GaussiansCrossValidateBetterThanAQuarticOnTheClassicCurve) {
  // Gordon, Huxley and Julian (1966), sampled every 0.05 um (data/ghj1966_sampled.csv)
  const std::vector<DataPoint> data = ReadCurveCsv(
      std::string(MUSCLESIM_SOURCE_DIR) + "/data/ghj1966_sampled.csv", "length", "tension", 10);
  auto models = ReferenceFitters();
  models.insert(models.begin(), {"gaussians", [](const std::vector<DataPoint>& d) {
    const ActiveIdentification fit = IdentifyActive(d, 3, true);
    return std::function<double(double)>([fit](double x) { return fit.Evaluate(x); });
  }});
  const CurveComparison c = Compare("active", "um", data, models);
  ASSERT_EQ(c.models.size(), 4u);
  EXPECT_LT(c.models[0].loocv_rmse, c.models[3].loocv_rmse);  // against degree 4
  EXPECT_LT(c.models[0].loocv_rmse, c.models[2].loocv_rmse);  // and degree 3
  EXPECT_TRUE(c.models[0].nonnegative);
  EXPECT_TRUE(c.models[0].bounded);
  EXPECT_FALSE(c.models[3].nonnegative);  // the quartic dips below zero outside the data
  EXPECT_THAT(FormatReport({c}), HasSubstr("| gaussians | "));
}

std::string DataError(const std::string& text, std::size_t min_points = 4) {
  const std::string path = testing::WriteTempFile("curve.csv", text);
  return testing::InputErrorOf(path, [&] { ReadCurveCsv(path, "length", "tension", min_points); });
}

TEST(IdentifyData, RejectsEveryBadDataRule) {
  EXPECT_EQ(DataError("length,tension\n0.1,1\n0.2,2\n"), "FILE: too few points: 2, need at least 4");
  EXPECT_EQ(DataError("# source\nlength,tension\n0.1,1\n0.2,nan\n0.3,1\n0.4,1\n"),
            "FILE:4: length = 0.2, tension = nan: values must be finite");
  EXPECT_EQ(DataError("length,tension\n0.1,1\n0.3,2\n0.2,1\n0.4,1\n"),
            "FILE:4: length = 0.2 is not greater than the row before (0.3): rows must be sorted "
            "by length, without duplicates");
  EXPECT_THAT(DataError("length,tension\n0.1,1\n0.1,2\n0.2,1\n0.4,1\n"),
              HasSubstr("FILE:3: length = 0.1 is not greater than the row before (0.1)"));
  EXPECT_EQ(DataError("length,tension\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n"),
            "FILE: every tension is zero: nothing to fit");
  EXPECT_EQ(DataError("length,force\n0.1,0\n"),
            "FILE: missing columns: tension (columns length,tension)");
  EXPECT_EQ(DataError("length,tension\n0.1,1\n0.2,heavy\n0.3,1\n0.4,1\n"),
            "FILE:3: column tension = 'heavy': must be a number");
  EXPECT_EQ(DataError("length,tension\n0.1,1,3\n"), "FILE:2: 3 fields where the header has 2");
}

}  // namespace
}  // namespace musclesim
