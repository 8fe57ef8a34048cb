// The slack length's profile-likelihood interval (IdentifyPassive's slack_length_interval):
// the F quantile it thresholds with, the interval against a brute-force profile, and its
// coverage of the truth over simulated data sets like data/synthetic_passive.csv.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/identify/identify.h"
#include "musclesim/identify/identify_report.h"
#include "musclesim/core/student_t.h"
#include "support/normal_noise.h"
#include "support/numeric.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// --- Student's t: the F(1, dof) quantile is its square ---------------------------------

// P(|T| <= t) by quadrature of the density Gamma((v+1)/2) / (sqrt(v pi) Gamma(v/2))
// (1 + t^2/v)^(-(v+1)/2)
double CentralProbabilityByQuadrature(double t, int dof) {
  const double v = dof;
  const double scale =
      std::exp(std::lgamma(0.5 * (v + 1)) - std::lgamma(0.5 * v)) / std::sqrt(v * std::numbers::pi);
  const auto density = [&](double s) { return scale * std::pow(1 + s * s / v, -0.5 * (v + 1)); };
  return 2.0 * testing::Integrate(density, 0.0, t, {}, 1e-14);
}

TEST(StudentT, CentralProbabilityMatchesQuadratureOfTheDensity) {
  for (int dof : {1, 2, 3, 4, 7, 26, 27}) {
    for (double t : {0.3, 1.0, 2.0555, 6.0}) {
      // adaptive Simpson to 1e-14 of a smooth density, and a finite sum: both ~1e-14
      EXPECT_NEAR(StudentTCentralProbability(t, dof), CentralProbabilityByQuadrature(t, dof), 1e-11)
          << "dof " << dof << ", t " << t;
    }
  }
}

TEST(StudentT, QuantileInvertsTheClosedForms) {
  for (double p : {0.5, 0.9, 0.95, 0.99}) {
    // dof 1 (Cauchy): P = 2 atan(t) / pi; dof 2: P = t / sqrt(2 + t^2). Bisection to
    // rounding: 1e-12 relative is the quantile's condition at p = 0.99 times eps, with room
    EXPECT_NEAR(StudentTCentralQuantile(p, 1), std::tan(0.5 * std::numbers::pi * p),
                1e-12 * std::tan(0.5 * std::numbers::pi * p));
    const double two = std::sqrt(2 * p * p / (1 - p * p));
    EXPECT_NEAR(StudentTCentralQuantile(p, 2), two, 1e-12 * two);
  }
  // the 97.5% point of t(26), as printed in tables to 10 digits: 2.055529439
  EXPECT_NEAR(StudentTCentralQuantile(0.95, 26), 2.055529439, 1e-9);
}

// --- data like data/synthetic_passive.csv ------------------------------------------------

using testing::Noise;

// scripts/make_synthetic_data.py: k_p 1 N, alpha 100 /m, slack 0.105 m at 29 lengths
// 0.09..0.16 m, noise of standard deviation 2% of the largest tension
constexpr double kKp = 1.0, kAlpha = 100.0, kSlack = 0.105;

std::vector<DataPoint> SyntheticPassive(std::uint64_t seed, double noise_fraction = 0.02) {
  Noise normal(seed);
  const double sd = noise_fraction * kKp * std::expm1(kAlpha * (0.16 - kSlack));
  std::vector<DataPoint> data;
  for (int i = 0; i < 29; ++i) {
    const double x = 0.09 + 0.0025 * i;
    const double t = x > kSlack ? kKp * std::expm1(kAlpha * (x - kSlack)) : 0.0;
    data.push_back({x, t + sd * normal()});
  }
  return data;
}

bool Covers(const ProfileInterval& in, double truth) {
  return (!in.low_bounded || in.low <= truth) && (!in.high_bounded || truth <= in.high);
}

// --- a brute-force profile -----------------------------------------------------------------

// The minimum of f on [a, b] by golden sections, to (b - a) 0.618^iterations; {x, f(x)}.
template <typename F>
std::pair<double, double> GoldenMinimum(F f, double a, double b, int iterations) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - ratio * (b - a), d = a + ratio * (b - a), fc = f(c), fd = f(d);
  for (int i = 0; i < iterations; ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = f(d);
    }
  }
  return fc < fd ? std::pair{c, fc} : std::pair{d, fd};
}

// RSS(x0) = min over k >= 0, alpha of sum (k (e^(alpha (x - x0)) - 1)_+ - y)^2: for each
// alpha k is a one-parameter least-squares solution; alpha from a grid of 100 in ln(alpha)
// over [0.1, 1e4] 1/m, the best refined by 50 golden sections (to 1e-11 in ln(alpha)).
// x0 = -infinity: the limit curve k e^(alpha (x - x_n)).
double BruteForceRss(const std::vector<DataPoint>& data, double x0) {
  const auto shape = [&](double x, double alpha) {
    if (x <= x0) return 0.0;
    return std::isinf(x0) ? std::exp(alpha * (x - data.back().x)) : std::expm1(alpha * (x - x0));
  };
  const auto rss_at = [&](double log_alpha) {
    const double alpha = std::exp(log_alpha);
    double gg = 0, gy = 0;
    for (const DataPoint& d : data) {
      gg += shape(d.x, alpha) * shape(d.x, alpha);
      gy += shape(d.x, alpha) * d.y;
    }
    if (!std::isfinite(gg)) return kInfinity;  // alpha too large for this x0
    const double k = gg > 0 && gy > 0 ? gy / gg : 0.0;
    double rss = 0;
    for (const DataPoint& d : data) rss += std::pow(k * shape(d.x, alpha) - d.y, 2);
    return rss;
  };
  const double low = std::log(0.1), high = std::log(1e4), step = (high - low) / 99;
  double best = low, least = rss_at(low);
  for (int i = 1; i < 100; ++i) {
    const double rss = rss_at(low + step * i);
    if (rss < least) {
      least = rss;
      best = low + step * i;
    }
  }
  return std::min(least, GoldenMinimum(rss_at, best - step, best + step, 50).second);
}

// The brute-force profile on a scan of every slack length: the limit -infinity, below the
// first data point at distances growing by 1.5 from an eighth of a spacing to 1 m, and every
// eighth of a spacing up to the second-to-last point (where 2 points are left above).
std::vector<std::pair<double, double>> BruteForceScan(const std::vector<DataPoint>& data) {
  const double first = data.front().x, gap = data[1].x - data[0].x;
  std::vector<double> slack = {-kInfinity};
  for (double d = 1.0; d > gap / 8; d /= 1.5) slack.push_back(first - d);
  for (double x = first; x < data[data.size() - 2].x - 1e-12; x += gap / 8) slack.push_back(x);
  std::vector<std::pair<double, double>> scan;
  for (double x : slack) scan.emplace_back(x, BruteForceRss(data, x));
  return scan;
}

// The least brute-force RSS: the scan's least, refined by golden sections over the stretch
// to its neighbours either side (RSS(x0) is smooth between data points, and a kink at one
// is a scan point).
double BruteForceMinimum(const std::vector<DataPoint>& data,
                         const std::vector<std::pair<double, double>>& scan) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (scan[i].second < scan[best].second) best = i;
  }
  double least = scan[best].second;
  const auto rss = [&](double x) { return BruteForceRss(data, x); };
  if (best > 1)
    least = std::min(least, GoldenMinimum(rss, scan[best - 1].first, scan[best].first, 50).second);
  if (best + 1 < scan.size()) {
    least = std::min(least, GoldenMinimum(rss, scan[best].first, scan[best + 1].first, 50).second);
  }
  return least;
}

// The interval's defining property checked with the brute-force profile: just inside each
// bounded end RSS(x0) is below the threshold, just outside above it, and nowhere on a scan of
// every slack length (data range, below it, the limit) outside the interval below it.
void ExpectIntervalOfBruteForceProfile(const std::vector<DataPoint>& data,
                                       const PassiveIdentification& fit) {
  const std::vector<std::pair<double, double>> scan = BruteForceScan(data);
  const double least = BruteForceMinimum(data, scan);
  // the fit's RMSE is its least RSS: both minimise to ~1e-10 relative (the golden sections
  // and Brent's method both stop far below that)
  EXPECT_NEAR(fit.rmse * fit.rmse * data.size(), least, 1e-7 * least);
  ASSERT_EQ(data.size(), 29u);
  const double t = 2.055529439;  // t(26) 97.5%, from tables: F(1, 26; 0.95) = t^2
  const double threshold = least * (1 + t * t / 26);
  const ProfileInterval& in = fit.slack_length_interval;
  // 2e-6 m: RSS(x0) moves by ~1e-4 of itself over it near the ends here (slopes of ~2e4
  // N^2/m against 500 N^2), far more than either profile's error
  const double delta = 2e-6;
  if (in.low_bounded) {
    EXPECT_LE(BruteForceRss(data, in.low + delta), threshold);
    EXPECT_GT(BruteForceRss(data, in.low - delta), threshold);
  } else {
    EXPECT_LE(BruteForceRss(data, -kInfinity), threshold);
  }
  ASSERT_TRUE(in.high_bounded);  // both data sets here: 2 large tensions end the data
  EXPECT_LE(BruteForceRss(data, in.high - delta), threshold);
  EXPECT_GT(BruteForceRss(data, in.high + delta), threshold);
  for (const auto& [x, rss] : scan) {
    if ((!in.low_bounded || x > in.low - delta) && x < in.high + delta) continue;
    EXPECT_GT(rss, threshold) << "x0 = " << x;
  }
}

std::vector<DataPoint> ShippedPassive() {
  return ReadCurveCsv(std::string(MUSCLESIM_SOURCE_DIR) + "/data/synthetic_passive.csv", "length",
                      "tension", 4);
}

TEST(SlackLengthInterval, MatchesABruteForceProfileOnTheShippedData) {
  const std::vector<DataPoint> data = ShippedPassive();
  const PassiveIdentification fit = IdentifyPassive(data);
  EXPECT_TRUE(fit.slack_length_interval.low_bounded);
  EXPECT_TRUE(fit.slack_length_interval.wide);  // ~14 mm against a 70 mm span
  EXPECT_EQ(fit.slack_length_interval.level, 0.95);
  ExpectIntervalOfBruteForceProfile(data, fit);
  // README: the truth, 0.105 m, is rejected with "p = 0.015": the F statistic's two-sided
  // t(26) tail, by brute force and quadrature
  const double least = BruteForceMinimum(data, BruteForceScan(data));
  const double f = (BruteForceRss(data, kSlack) - least) / (least / 26);
  const double p = 1.0 - CentralProbabilityByQuadrature(std::sqrt(f), 26);
  EXPECT_NEAR(p, 0.015, 0.0005) << p;  // as printed
}

TEST(SlackLengthInterval, UnboundedBelowWhenTheNoiseHidesTheToe) {
  // most data sets of this design (the shipped one is an exception): the curve's toe is
  // under the noise, and a pure exponential fits as well
  const std::vector<DataPoint> data = SyntheticPassive(1);
  const PassiveIdentification fit = IdentifyPassive(data);
  const ProfileInterval& in = fit.slack_length_interval;
  EXPECT_FALSE(in.low_bounded);
  EXPECT_EQ(in.low, -kInfinity);
  EXPECT_TRUE(in.wide);
  EXPECT_EQ(fit.k_p_over_interval.low, 0.0);  // k_p -> 0 as the slack length goes down
  ExpectIntervalOfBruteForceProfile(data, fit);
  const std::vector<std::string> notes =
      PassiveUncertaintyNotes(fit, [](double x) { return std::to_string(x); });
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("95% profile-likelihood interval (-inf, "));
  EXPECT_THAT(notes[0], HasSubstr("not bounded below"));
  EXPECT_THAT(notes[0], HasSubstr("wide"));
  EXPECT_THAT(notes[1], HasSubstr("k_p from 0.000000 to "));
}

TEST(SlackLengthInterval, AgreesWithTheStandardErrorWhenTheDataDetermineIt) {
  // noise of 0.02% of the largest tension: the fit is nearly linear in its parameters, and
  // the profile interval is the estimate +- t(26) standard errors, to second order in them
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const PassiveIdentification fit = IdentifyPassive(SyntheticPassive(seed, 2e-4));
    const ProfileInterval& in = fit.slack_length_interval;
    ASSERT_TRUE(in.low_bounded && in.high_bounded);
    EXPECT_FALSE(in.wide);
    const double half = 2.055529439 * fit.slack_length.standard_error;
    // the interval (~0.8 mm) holds the data point 0.105 m, where RSS(x0) has a kink, so its
    // halves are t SE only to ~10% (0.87 to 1.12 of it for seeds 1 to 10); 0.75 to 1.33
    // fails a profile or a threshold off by a factor of 2 in RSS
    EXPECT_GT(in.high - fit.slack_length.value, 0.75 * half) << "seed " << seed;
    EXPECT_LT(in.high - fit.slack_length.value, 1.33 * half) << "seed " << seed;
    EXPECT_GT(fit.slack_length.value - in.low, 0.75 * half) << "seed " << seed;
    EXPECT_LT(fit.slack_length.value - in.low, 1.33 * half) << "seed " << seed;
  }
}

TEST(SlackLengthInterval, CoversTheTruthAtItsLevel) {
  // 200 data sets drawn as data/synthetic_passive.csv was. At 95% the count covered is
  // binomial(200, 0.95): 190 +- 3; 180..198 (90-99%) allows for the F threshold being exact
  // only for a regular model, and fails an interval that ignores the weak slack length
  int covered = 0, by_standard_error = 0, unbounded_below = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const PassiveIdentification fit = IdentifyPassive(SyntheticPassive(seed));
    covered += Covers(fit.slack_length_interval, kSlack);
    unbounded_below += !fit.slack_length_interval.low_bounded;
    by_standard_error +=
        std::abs(fit.slack_length.value - kSlack) <= 2.055529439 * fit.slack_length.standard_error;
  }
  EXPECT_GE(covered, 180);
  EXPECT_LE(covered, 198);
  // docs/guide/identification.md quotes these three counts
  EXPECT_EQ(covered, 195);
  EXPECT_EQ(unbounded_below, 185);
  EXPECT_EQ(by_standard_error, 130);
  // the estimate +- t(26) standard errors, what the profile interval replaces, covers far
  // less often (65% here)
  EXPECT_LT(by_standard_error, 180);
  // both kinds of interval occur (most are unbounded below), so both ends' code runs
  EXPECT_GT(unbounded_below, 0);
  EXPECT_LT(unbounded_below, 200);
}

TEST(SlackLengthInterval, RejectsALevelOutsideZeroToOne) {
  for (double level : {0.0, 1.0, -0.5, std::nan("")}) {
    EXPECT_THROW(IdentifyPassive(ShippedPassive(), level), std::invalid_argument) << level;
  }
}

// Lengths 1e-8 m apart near 0.1 m: the bisection's tolerance (1e-10 of the span) is below the
// spacing of doubles there, and the interval's ends must still be found (this looped forever).
TEST(SlackLengthInterval, EndsFoundWhenTheToleranceIsBelowTheSpacingOfDoubles) {
  const std::vector<DataPoint> data = {
      {0.1, 0.0}, {0.10000001, 1.0}, {0.10000002, 3.0}, {0.10000003, 8.0}, {0.10000004, 20.0}};
  const PassiveIdentification fit = IdentifyPassive(data);
  const ProfileInterval& in = fit.slack_length_interval;
  EXPECT_LE(in.low, fit.slack_length.value);
  EXPECT_GE(in.high, fit.slack_length.value);
}

// Finite data whose fit overflows is an input error, never a model of NaN or infinity.
TEST(SlackLengthInterval, AFitThatOverflowsIsRefused) {
  const std::vector<DataPoint> subnormal = {
      {1e-320, 0.0}, {2e-320, 1.0}, {3e-320, 3.0}, {4e-320, 8.0}};
  const std::vector<DataPoint> huge_tension = {
      {0.1, 0.0}, {0.11, 1e308}, {0.12, 1e308}, {0.13, 1e308}};
  for (const auto& data : {subnormal, huge_tension}) {
    try {
      const PassiveIdentification fit = IdentifyPassive(data);
      // accepted: then every number is finite
      EXPECT_TRUE(std::isfinite(fit.k_p.value) && std::isfinite(fit.alpha.value) &&
                  std::isfinite(fit.slack_length.value));
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("passive data"));
    }
  }
}

}  // namespace
}  // namespace musclesim
