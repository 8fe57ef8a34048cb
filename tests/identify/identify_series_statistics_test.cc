// Standard errors, correlations and identifiability verdicts of time-series identification
// against closed forms (linear models) and against the spread of estimates over many seeded
// noisy data sets.
#include "identify/identify_series_statistics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "musclesim/core/bounded_least_squares.h"
#include "support/normal_noise.h"

namespace musclesim::identify_series_detail {
namespace {

using testing::Noise;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The design matrix of y = p0 + p1 t at t = 0..n-1.
Eigen::MatrixXd LineJacobian(int n) {
  Eigen::MatrixXd x(n, 2);
  for (int i = 0; i < n; ++i) x.row(i) << 1.0, double(i);
  return x;
}

TEST(AnalyseJacobian, CovarianceWithNoiseIsTheInverseFisherInformation) {
  // weights 1/sigma_i, sigma growing along the line: (X^T W X)^-1 by the 2 x 2 inverse
  const int n = 12;
  const Eigen::MatrixXd x = LineJacobian(n);
  Eigen::VectorXd w(n);
  for (int i = 0; i < n; ++i) w[i] = 1.0 / (0.1 + 0.05 * i);
  double s0 = 0, s1 = 0, s2 = 0;  // sums of w^2, w^2 t, w^2 t^2
  for (int i = 0; i < n; ++i) {
    s0 += w[i] * w[i];
    s1 += w[i] * w[i] * i;
    s2 += w[i] * w[i] * i * i;
  }
  const double det = s0 * s2 - s1 * s1;
  const JacobianAnalysis a =
      AnalyseJacobian(w.asDiagonal() * x, Eigen::Vector2d(3.0, 2.0), true, 123.0, {});
  EXPECT_EQ(a.variance_factor, 1.0);  // the residuals do not enter with the noise given
  // a 2 x 2 inverse and an SVD of 12 rows: rounding, 1e-12 relative
  EXPECT_NEAR(a.covariance(0, 0), s2 / det, 1e-12 * s2 / det);
  EXPECT_NEAR(a.covariance(1, 1), s0 / det, 1e-12 * s0 / det);
  EXPECT_NEAR(a.covariance(0, 1), -s1 / det, 1e-12 * s1 / det);
  EXPECT_NEAR(a.standard_errors[1], std::sqrt(s0 / det), 1e-12 * std::sqrt(s0 / det));
  EXPECT_NEAR(a.correlation(0, 1), -s1 / std::sqrt(s0 * s2), 1e-12);
  EXPECT_NEAR(a.relative_standard_errors[1], std::sqrt(s0 / det) / 2.0, 1e-12);
  EXPECT_EQ(a.degrees_of_freedom, n - 2);
}

TEST(AnalyseJacobian, WithoutNoiseTheResidualsGiveTheVariance) {
  const int n = 10;
  const Eigen::MatrixXd x = LineJacobian(n);
  const double rss = 0.8;
  const double s2 = rss / (n - 2);
  double t = 0, tt = 0;
  for (int i = 0; i < n; ++i) {
    t += i;
    tt += double(i) * i;
  }
  const double det = n * tt - t * t;
  const JacobianAnalysis a = AnalyseJacobian(x, Eigen::Vector2d(1.0, 1.0), false, rss, {});
  EXPECT_NEAR(a.variance_factor, s2, 1e-15);                           // one division
  EXPECT_NEAR(a.standard_errors[0], std::sqrt(s2 * tt / det), 1e-13);  // rounding
  EXPECT_NEAR(a.standard_errors[1], std::sqrt(s2 * n / det), 1e-13);
}

// y = a exp(-t / tau) + c at t = 0, 0.1, ..., 2.
ModelPoint Decay(const Eigen::VectorXd& p) {
  const int n = 21;
  ModelPoint m{Eigen::VectorXd(n), Eigen::MatrixXd(n, 3)};
  for (int i = 0; i < n; ++i) {
    const double t = 0.1 * i, e = std::exp(-t / p[1]);
    m.predictions[i] = p[0] * e + p[2];
    m.jacobian.row(i) << e, p[0] * e * t / (p[1] * p[1]), 1.0;
  }
  return m;
}

TEST(AnalyseJacobian, StandardErrorsDescribeTheSpreadOfNonlinearEstimates) {
  // 400 seeded noisy data sets of a nonlinear model, each fitted: the truth lies within 1.96
  // standard errors in 95% of them when the standard errors are right
  const Eigen::Vector3d truth(2.0, 0.3, 0.5);
  const double sigma = 0.02;
  const Eigen::VectorXd exact = Decay(truth).predictions;
  int covered_known[3] = {0, 0, 0}, covered_estimated[3] = {0, 0, 0};
  const int sets = 400;
  for (int seed = 1; seed <= sets; ++seed) {
    Noise normal(static_cast<std::uint64_t>(seed));
    BoundedLeastSquaresProblem problem;
    problem.model = Decay;
    problem.data = exact;
    for (Eigen::Index i = 0; i < exact.size(); ++i) problem.data[i] += sigma * normal();
    problem.start = Eigen::Vector3d(1.5, 0.5, 0.0);
    problem.lower = Eigen::VectorXd::Constant(3, -kInf);
    problem.upper = Eigen::VectorXd::Constant(3, kInf);
    // known noise: weights 1/sigma
    problem.weights = Eigen::VectorXd::Constant(exact.size(), 1.0 / sigma);
    const LeastSquaresResult known = SolveBoundedLeastSquares(problem);
    const JacobianAnalysis a =
        AnalyseJacobian(known.at_solution.jacobian / sigma, known.parameters, true, known.cost, {});
    // unknown noise: weights 1, s^2 from the residuals
    problem.weights = Eigen::VectorXd::Ones(exact.size());
    const LeastSquaresResult unknown = SolveBoundedLeastSquares(problem);
    const JacobianAnalysis b =
        AnalyseJacobian(unknown.at_solution.jacobian, unknown.parameters, false, unknown.cost, {});
    for (int j = 0; j < 3; ++j) {
      covered_known[j] += std::abs(known.parameters[j] - truth[j]) <= 1.96 * a.standard_errors[j];
      covered_estimated[j] +=
          std::abs(unknown.parameters[j] - truth[j]) <= 1.96 * b.standard_errors[j];
    }
  }
  for (int j = 0; j < 3; ++j) {
    // binomial(400, 0.95): standard deviation 4.4; 3.5 of them either side is 380 +- 15.
    // With s estimated from 18 degrees of freedom, 1.96 s covers a little less (t(18)'s
    // 95% point is 2.10): about 93.5%, 374, so that band is 359 to 389
    EXPECT_GE(covered_known[j], 365) << j;
    EXPECT_LE(covered_known[j], 395) << j;
    EXPECT_GE(covered_estimated[j], 359) << j;
    EXPECT_LE(covered_estimated[j], 389) << j;
  }
}

TEST(AnalyseJacobian, AZeroColumnIsNegligibleAndLeavesTheOthersAsWithoutIt) {
  const Eigen::MatrixXd x = LineJacobian(8) * 100.0;  // noise 0.01: both well determined
  Eigen::MatrixXd with_zero(8, 3);
  with_zero << x, Eigen::VectorXd::Zero(8);
  const JacobianAnalysis a =
      AnalyseJacobian(with_zero, Eigen::Vector3d(1.0, 2.0, 0.105), true, 0.0, {});
  const JacobianAnalysis b = AnalyseJacobian(x, Eigen::Vector2d(1.0, 2.0), true, 0.0, {});
  EXPECT_EQ(a.verdicts[2], Identifiability::kNegligibleColumn);
  EXPECT_EQ(a.column_ratios[2], 0.0);
  EXPECT_TRUE(std::isinf(a.standard_errors[2]));
  EXPECT_TRUE(std::isnan(a.correlation(0, 2)));
  EXPECT_NEAR(a.standard_errors[1], b.standard_errors[1], 1e-14);  // the same SVD, rounding
  EXPECT_EQ(a.verdicts[0], Identifiability::kIdentifiable);
  EXPECT_TRUE(a.weak_directions.empty());  // one parameter alone: its column says it
  EXPECT_EQ(a.singular_values.size(), 3);
  EXPECT_EQ(a.singular_values[2], 0.0);
}

TEST(AnalyseJacobian, AColumnJustBelowTheRatioIsNegligibleAndJustAboveIsNot) {
  Eigen::MatrixXd j = LineJacobian(8);
  const double largest = j.col(1).norm();
  j.col(0) *= 0.5e-6 * largest / j.col(0).norm();  // 0.5e-6 of the largest at p = 1
  EXPECT_EQ(AnalyseJacobian(j, Eigen::Vector2d(1.0, 1.0), true, 0.0, {}).verdicts[0],
            Identifiability::kNegligibleColumn);
  // the same column seen through a parameter 4 times larger: scaled, 2e-6 of the largest
  EXPECT_NE(AnalyseJacobian(j, Eigen::Vector2d(4.0, 1.0), true, 0.0, {}).verdicts[0],
            Identifiability::kNegligibleColumn);
}

TEST(AnalyseJacobian, OnlyAProductIsDeterminedAndTheDirectionSaysWhich) {
  // y = a b t: dy/da = b t, dy/db = a t; scaled by a and b both columns are a b t, so the
  // relative changes d ln a = -d ln b leave y unchanged: the direction (1, -1)/sqrt(2)
  const double a = 2.0, b = 5.0;
  Eigen::MatrixXd j(6, 3);
  for (int i = 0; i < 6; ++i) j.row(i) << b * i, a * i, std::sin(i);  // a third, free one
  j *= 100.0;  // noise 0.01: the third well determined
  const JacobianAnalysis r = AnalyseJacobian(j, Eigen::Vector3d(a, b, 1.0), true, 0.0, {});
  EXPECT_EQ(r.verdicts[0], Identifiability::kDependent);
  EXPECT_EQ(r.verdicts[1], Identifiability::kDependent);
  EXPECT_EQ(r.verdicts[2], Identifiability::kIdentifiable);
  ASSERT_EQ(r.weak_directions.size(), 1u);
  const WeakDirection& w = r.weak_directions[0];
  EXPECT_LT(w.ratio, 1e-15);  // exactly dependent columns: zero to rounding
  EXPECT_NEAR(std::abs(w.components[0]), std::sqrt(0.5), 1e-12);  // rounding of the SVD
  EXPECT_NEAR(w.components[0], -w.components[1], 1e-12);
  EXPECT_NEAR(w.components[2], 0.0, 1e-12);
}

TEST(AnalyseJacobian, NoiseThatHidesAParameterMakesItPoorlyDetermined) {
  // y = p0 + p1 t, t = 0..9, noise sigma: se(p1) = sigma / sqrt(sum (t - mean)^2) = sigma /
  // sqrt(82.5); with p1 = 0.1 the relative error crosses 25% at sigma = 0.025 sqrt(82.5)
  const Eigen::MatrixXd x = LineJacobian(10);
  const double crossing = 0.025 * std::sqrt(82.5);
  for (double factor : {0.9, 1.1}) {
    const double sigma = factor * crossing;
    const JacobianAnalysis a =
        AnalyseJacobian(x / sigma, Eigen::Vector2d(10.0, 0.1), true, 0.0, {});
    EXPECT_NEAR(a.relative_standard_errors[1], 0.25 * factor, 1e-12);  // closed form, rounding
    EXPECT_EQ(a.verdicts[1],
              factor < 1 ? Identifiability::kIdentifiable : Identifiability::kPoorlyDetermined);
  }
}

TEST(AnalyseJacobian, AParameterAtABoundIsLeftOutOfTheStatistics) {
  const JacobianAnalysis a =
      AnalyseJacobian(LineJacobian(10), Eigen::Vector2d(1.0, 1.5), false, 1.0, {false, true});
  EXPECT_EQ(a.verdicts[1], Identifiability::kAtBound);
  EXPECT_TRUE(std::isinf(a.standard_errors[1]));
  EXPECT_EQ(a.degrees_of_freedom, 9);  // one parameter estimated
  // the intercept alone: s^2 / n, s^2 = 1 / 9
  EXPECT_NEAR(a.standard_errors[0], std::sqrt(1.0 / 9.0 / 10.0), 1e-14);  // rounding
}

TEST(ParameterScales, DoNotVanishWithTheEstimate) {
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::Vector4d estimate(1e-14, 250.0, 0.0, 0.0), start(0.01, 100.0, 0.0, 0.0);
  const Eigen::Vector4d lower(-1.0, 1.0, -0.5, -inf), upper(1.0, 1e3, 0.2, inf);
  const Eigen::VectorXd scales = ParameterScales(estimate, start, lower, upper);
  EXPECT_EQ(scales[0], 0.01);   // the start's size, not the estimate's
  EXPECT_EQ(scales[1], 250.0);  // the estimate's, when larger
  EXPECT_EQ(scales[2], 0.5);    // both 0: the larger bound's size
  EXPECT_EQ(scales[3], 1.0);    // nothing to go by: 1 in the parameter's unit
}

}  // namespace
}  // namespace musclesim::identify_series_detail
