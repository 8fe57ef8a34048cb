// The asymmetric tension-velocity curve (docs/model.md section 9) against independent
// evaluations of its formulas, central differences, and the paper's symmetric eq. 12.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/model/velocity.h"
#include "support/numeric.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

VelocityParams Asymmetric(double v_max_e, int n_e, std::optional<double> limit, double v_max = 1.0,
                          int n = 3, double eps = 1e-3) {
  VelocityParams p{v_max, n, eps};
  p.eccentric = {v_max_e, n_e, limit};
  return p;
}

// g of section 9 written out again, in long double: (v^2 + eps^2)^((a - 1)/2) v is phi_eps.
long double Phi(long double v, int n, long double eps) {
  const long double a = 1.0L / n;
  return v * std::pow(v * v + eps * eps, (a - 1.0L) / 2.0L);
}
long double IndependentGLong(const VelocityParams& p, double v) {
  if (v >= 0) {
    return 1.0L - Phi(v, p.n, p.epsilon) / std::pow(static_cast<long double>(p.v_max), 1.0L / p.n);
  }
  const int n_e = p.eccentric.n.value_or(p.n);
  const long double v_max_e = p.eccentric.v_max.value_or(p.v_max);
  const long double psi = -Phi(v, n_e, p.epsilon) / std::pow(v_max_e, 1.0L / n_e);
  if (!p.eccentric.limit) return 1.0L + psi;
  const long double headroom = *p.eccentric.limit - 1.0L;
  return 1.0L + headroom * std::tanh(psi / headroom);
}
double IndependentG(const VelocityParams& p, double v) {
  return static_cast<double>(IndependentGLong(p, v));
}

const std::vector<VelocityParams>& Cases() {
  static const std::vector<VelocityParams> cases = {Asymmetric(0.5, 2, 1.8),
                                                    Asymmetric(0.5, 2, std::nullopt),
                                                    Asymmetric(2.0, 1, 1.3),
                                                    Asymmetric(1.0, 3, 1.5),  // a limit only
                                                    Asymmetric(0.3, 5, 1e6),
                                                    Asymmetric(1.5, 1, std::nullopt, 0.7, 1, 1e-2),
                                                    Asymmetric(0.5, 4, 1.05, 1.0, 2, 1e-4)};
  return cases;
}

TEST(EccentricVelocity, MatchesTheFormulasOfSection9) {
  for (const VelocityParams& p : Cases()) {
    const VelocityCurve curve(p);
    for (double v : {-1e3, -10.0, -1.0, -0.3, -0.02, -1e-3, -1e-5, 0.0, 1e-4, 0.1, 0.8, 2.0}) {
      const double expected = IndependentG(p, v);
      // double against long double: a few ulps of the pow and tanh in double, 1e-14 of g or
      // of its value at rest, 1, whichever is larger (g passes through 0 at v_max)
      EXPECT_NEAR(curve.Evaluate(v).value, expected, 1e-14 * std::max(1.0, std::abs(expected)))
          << "v_max_e " << *p.eccentric.v_max << " n_e " << *p.eccentric.n << " v " << v;
    }
  }
}

TEST(EccentricVelocity, SlopeMatchesCentralDifferencesOnBothSides) {
  for (const VelocityParams& p : Cases()) {
    const VelocityCurve curve(p);
    for (double v : {-5.0, -1.0, -0.4, -0.05, -0.004, -5e-4, 5e-4, 0.004, 0.05, 0.6, 1.5}) {
      // a step of 1e-3 |v| stays on v's side of the kink at 0; the O(h^2) error of the
      // difference is then ~1e-6 of the slope, and rounding 1e-16 / 1e-3 of g: 1e-5 relative
      // (with a floor of 1e-9 where a saturated limit flattens the curve) is their sum,
      // with margin
      const double h = 1e-3 * std::abs(v);
      const double numeric =
          (curve.Evaluate(v + h).value - curve.Evaluate(v - h).value) / (2.0 * h);
      EXPECT_NEAR(curve.Evaluate(v).slope, numeric, 1e-5 * std::abs(numeric) + 1e-9)
          << "v_max_e " << *p.eccentric.v_max << " n_e " << *p.eccentric.n << " v " << v;
    }
  }
}

// The one-sided slopes at v = 0 of section 9, written out: -eps^(a-1) / v_max^a.
double SlopeAtRest(double eps, double v_max, int n) {
  return -std::pow(eps, 1.0 / n - 1.0) / std::pow(v_max, 1.0 / n);
}

TEST(EccentricVelocity, ContinuousAtRestWithEachSidesSlope) {
  for (const VelocityParams& p : Cases()) {
    const VelocityCurve curve(p);
    EXPECT_EQ(curve.Evaluate(0.0).value, 1.0);
    EXPECT_EQ(curve.Evaluate(-0.0).value, 1.0);
    const double right = SlopeAtRest(p.epsilon, p.v_max, p.n);
    const double left = SlopeAtRest(p.epsilon, *p.eccentric.v_max, *p.eccentric.n);
    // within 1e-6 eps of 0 the curve is its tangent to (1e-6)^2 relative (phi_eps is odd: no
    // quadratic term), plus the rounding of g near 1, 4e-16; the slopes are each side's, the
    // two pow evaluations agreeing to 1e-13
    const double h = 1e-6 * p.epsilon;
    EXPECT_NEAR(curve.Evaluate(h).value, 1.0 + right * h, 1e-10 * std::abs(right) * h + 4e-16);
    EXPECT_NEAR(curve.Evaluate(-h).value, 1.0 - left * h, 1e-10 * std::abs(left) * h + 4e-16);
    EXPECT_NEAR(curve.Evaluate(0.0).slope, right, 1e-13 * std::abs(right));
    EXPECT_NEAR(curve.Evaluate(-h).slope, left, 1e-10 * std::abs(left));
  }
}

TEST(EccentricVelocity, ApproachesItsLimitFromBelow) {
  for (const VelocityParams& p : Cases()) {
    if (!p.eccentric.limit) continue;
    const double limit = *p.eccentric.limit;
    const VelocityCurve curve(p);
    double previous = 1.0;
    for (double v = -1e-4; v > -1e4; v *= 1.5) {
      const double g = curve.Evaluate(v).value;
      // rising towards L (to rounding, 1e-15) and never above it; strictly below it while the
      // exact g is more than 1e-13 L away, beyond which tanh rounds to 1 and g to L itself
      EXPECT_GT(g, previous - 1e-15) << v;
      EXPECT_LE(g, limit) << v;
      if (limit - IndependentGLong(p, v) > 1e-13L * limit) {
        EXPECT_LT(g, limit) << v;
      }
      previous = g;
    }
    // at -1e40 m/s psi / (L - 1) exceeds 100 in every case here (psi ~ |v|^(1/n_e) with
    // n_e <= 5), so tanh is 1 in double and g is L to its last bit or two
    EXPECT_NEAR(curve.Evaluate(-1e40).value, limit, 4e-16 * limit);
  }
  // with the unbounded form g passes any bound
  EXPECT_GT(VelocityCurve(Asymmetric(0.5, 2, std::nullopt)).Evaluate(-1e6).value, 1e3);
}

TEST(EccentricVelocity, TheLimitOnlyBendsTheCurveWhereItApproachesIt) {
  // g - 1 = (L - 1) tanh(psi / (L - 1)) = psi - psi^3 / (3 (L - 1)^2) + ...: near v = 0 the
  // bounded and unbounded branches agree to third order in psi
  const VelocityCurve bounded(Asymmetric(0.5, 2, 1.8)), unbounded(Asymmetric(0.5, 2, std::nullopt));
  for (double v : {-1e-4, -1e-3, -1e-2}) {
    const double psi = unbounded.Evaluate(v).value - 1.0;
    const double cubic = psi * psi * psi / (3.0 * 0.8 * 0.8);
    EXPECT_NEAR(unbounded.Evaluate(v).value - bounded.Evaluate(v).value, cubic, 0.1 * cubic) << v;
  }
}

// eq. 12 as the code computed it before the eccentric branch existed: the same operations
// in the same order, so the comparison can ask for equality.
double Eq12AsBefore(double v, double v_max, int n, double eps) {
  const double alpha = 1.0 / n;
  const double w = v * v + eps * eps;
  const double p = n == 1 ? 1.0 : std::pow(w, 0.5 * (alpha - 1.0));
  return 1.0 - v * p * std::pow(v_max, -alpha);
}

TEST(EccentricVelocity, SymmetricCurveIsEq12BitForBit) {
  for (int n : {1, 2, 3, 7}) {
    const VelocityParams plain{0.8, n, 1e-3};
    VelocityParams spelled_out = plain;  // eccentric keys equal to the concentric ones
    spelled_out.eccentric = {0.8, n, std::nullopt};
    const VelocityCurve a(plain), b(spelled_out);
    EXPECT_FALSE(a.has_kink());
    EXPECT_FALSE(b.has_kink());
    for (double v : {-3.0, -0.8, -0.1, -1e-3, -1e-7, 0.0, 1e-7, 1e-3, 0.1, 0.8, 3.0}) {
      EXPECT_EQ(a.Evaluate(v).value, Eq12AsBefore(v, 0.8, n, 1e-3)) << n << " " << v;
      EXPECT_EQ(b.Evaluate(v).value, a.Evaluate(v).value) << n << " " << v;
      EXPECT_EQ(b.Evaluate(v).slope, a.Evaluate(v).slope) << n << " " << v;
      // and eq. 12 itself, evaluated independently in long double (tolerance as in
      // MatchesTheFormulasOfSection9)
      const double expected = IndependentG(plain, v);
      EXPECT_NEAR(a.Evaluate(v).value, expected, 1e-14 * std::max(1.0, std::abs(expected)));
    }
  }
}

TEST(EccentricVelocity, KinkFlaggedExactlyWhenTheSlopesDiffer) {
  const double eps = 1e-3;
  // n_e = 2 and v_max_e chosen so that eps^(a_e - 1) / v_max_e^a_e = eps^(a - 1) / v_max^a
  // (n = 3, v_max = 1): v_max_e = (eps^(a_e - 1) / eps^(a - 1))^n_e
  const double matching = std::pow(std::pow(eps, 0.5 - 1.0) / std::pow(eps, 1.0 / 3.0 - 1.0), 2.0);
  struct Row {
    VelocityParams params;
    bool kink;
  };
  const std::vector<Row> rows = {
      {VelocityParams{1.0, 3, eps}, false},
      {Asymmetric(1.0, 3, 1.5), false},                        // a limit leaves the slope
      {Asymmetric(0.5, 3, std::nullopt), true},                // v_max_e differs
      {Asymmetric(1.0, 2, std::nullopt), true},                // n_e differs
      {Asymmetric(matching, 2, 1.8), false},                   // both differ, slopes equal
      {Asymmetric(matching * (1 + 1e-9), 2, 1.8), true},       // and a hair off
      {Asymmetric(1.0, 2, std::nullopt, 1.0, 3, 1.0), false},  // eps = v_max = v_max_e = 1
  };
  for (const Row& row : rows) {
    const VelocityParams& p = row.params;
    const double right = SlopeAtRest(p.epsilon, p.v_max, p.n);
    const double left =
        SlopeAtRest(p.epsilon, p.eccentric.v_max.value_or(p.v_max), p.eccentric.n.value_or(p.n));
    // the condition of section 9, evaluated here (1e-12: rounding of the pows above)
    const bool differ = std::abs(left - right) > 1e-12 * std::abs(right);
    EXPECT_EQ(differ, row.kink) << "the table row is wrong";
    EXPECT_EQ(VelocityCurve(p).has_kink(), row.kink)
        << "v_max_e " << p.eccentric.v_max.value_or(p.v_max) << " n_e "
        << p.eccentric.n.value_or(p.n);
  }
}

TEST(EccentricVelocity, ExtremeAllowedValuesGiveFiniteValuesAndSlopes) {
  // the corners of the accepted ranges, at the speeds `curves --velocity` reaches (1e3 m/s)
  for (double eps : {1e-12, 1.0}) {
    for (double v_max_e : {eps, 1e12 * eps}) {
      for (int n_e : {1, kMaxVelocityExponent}) {
        for (std::optional<double> limit :
             {std::optional<double>{}, std::optional<double>{std::nextafter(1.0, 2.0)},
              std::optional<double>{kMaxEccentricLimit}}) {
          const VelocityCurve curve(Asymmetric(v_max_e, n_e, limit, 1.0, 3, eps));
          for (double v : {-1e3, -1.0, -eps, -1e-300, 0.0}) {
            const CurvePoint g = curve.Evaluate(v);
            EXPECT_TRUE(std::isfinite(g.value) && std::isfinite(g.slope))
                << "eps " << eps << " v_max_e " << v_max_e << " n_e " << n_e << " v " << v;
            EXPECT_GE(g.value, 1.0);  // the lengthening side never pulls less than at rest
          }
        }
      }
    }
  }
}

TEST(EccentricVelocity, ValidateRejectsEachRule) {
  auto broken = [](VelocityParams p) { return testing::Rejection([&] { Validate(p); }); };
  EXPECT_THAT(broken(Asymmetric(0.0, 2, 1.5)),
              HasSubstr("eccentric.v_max = 0: must be > 0 and <= 1e+12 [m/s]"));
  EXPECT_THAT(broken(Asymmetric(INFINITY, 2, 1.5)),
              HasSubstr("eccentric.v_max = inf: must be > 0 and <= 1e+12"));
  EXPECT_THAT(
      broken(Asymmetric(1e-4, 2, 1.5)),
      HasSubstr("eccentric.v_max = 1e-04: must be between epsilon = 0.001 and 1e12 epsilon"));
  EXPECT_THAT(broken(Asymmetric(2e9, 2, 1.5)),
              HasSubstr("eccentric.v_max = 2e+09: must be between"));
  EXPECT_THAT(broken(Asymmetric(0.5, 0, 1.5)),
              HasSubstr("eccentric.n = 0: must be an integer from 1 to 1000"));
  EXPECT_THAT(broken(Asymmetric(0.5, 1001, 1.5)),
              HasSubstr("eccentric.n = 1001: must be an integer"));
  EXPECT_THAT(broken(Asymmetric(0.5, 2, 1.0)),
              HasSubstr("eccentric.limit = 1: must be > 1 and <= 1e+06 [-]"));
  EXPECT_THAT(broken(Asymmetric(0.5, 2, 0.5)), HasSubstr("eccentric.limit = 0.5: must be > 1"));
  EXPECT_THAT(broken(Asymmetric(0.5, 2, 2e6)), HasSubstr("eccentric.limit = 2e+06: must be > 1"));
  EXPECT_THAT(broken(Asymmetric(0.5, 2, NAN)), HasSubstr("eccentric.limit = nan: must be > 1"));
  EXPECT_EQ(broken(Asymmetric(0.5, 2, kMaxEccentricLimit)), "accepted");
  EXPECT_THROW(VelocityCurve(Asymmetric(0.5, 2, 1.0)), ParameterError);
  // each key on its own is enough
  VelocityParams only_limit{1.0, 3, 1e-3};
  only_limit.eccentric.limit = 1.5;
  EXPECT_EQ(broken(only_limit), "accepted");
}

}  // namespace
}  // namespace musclesim
