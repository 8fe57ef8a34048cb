#include "musclesim/model/gaussian_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlopt.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>

#include "musclesim/errors.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr double kL1 = 0.095, kL2 = 0.105;

FitSpec Indicator(int count) {
  FitSpec spec;
  spec.count = count;
  return spec;
}

double CostAt(const FitTarget& target, const std::vector<Gaussian>& gaussians) {
  const Eigen::Index m = static_cast<Eigen::Index>(gaussians.size());
  Eigen::VectorXd a(m);
  GaussianShapes shapes{Eigen::VectorXd(m), Eigen::VectorXd(m)};
  for (Eigen::Index k = 0; k < m; ++k) {
    a(k) = gaussians[k].amplitude;
    shapes.precisions(k) = gaussians[k].precision;
    shapes.centers(k) = gaussians[k].center;
  }
  return target.Cost(a, shapes, nullptr);
}

TEST(GaussianFit, IndicatorFitIsALocalMinimumInEveryDirection) {
  const FitResult fit = FitGaussians(Indicator(2), kL1, kL2, 1.0);
  const auto target = MakeFitTarget(Indicator(2), kL1, kL2, 1.0);
  ASSERT_EQ(fit.gaussians.size(), 2u);
  EXPECT_NEAR(CostAt(*target, fit.gaussians), fit.cost, 1e-15);
  // perturb each of the 6 parameters by +-1e-4 relative, and all of them along random
  // directions: a minimum rises by ~H h^2 (about 1e-9 N here), rounding is ~1e-16 N
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Gaussian> moved = fit.gaussians;
    for (Gaussian& g : moved) {
      const bool all = trial >= 6;
      g.amplitude *= 1.0 + (all || trial == 0 ? 1e-4 * normal(rng) : 0.0);
      g.precision *= 1.0 + (all || trial == 1 ? 1e-4 * normal(rng) : 0.0);
      g.center += (all || trial == 2 ? 1e-4 * (kL2 - kL1) * normal(rng) : 0.0);
    }
    EXPECT_GE(CostAt(*target, moved), fit.cost * (1.0 - 1e-13)) << "trial " << trial;
  }
}

// The reduced cost N(b, d) with optimal amplitudes, for the independent minimiser below.
struct Reduced {
  const FitTarget* target;
  int m;
};

double ReducedCost(unsigned n, const double* x, double* grad, void* data) {
  (void)n;
  (void)grad;
  const auto* r = static_cast<const Reduced*>(data);
  GaussianShapes shapes{Eigen::VectorXd(r->m), Eigen::VectorXd(r->m)};
  for (int k = 0; k < r->m; ++k) {
    shapes.precisions(k) = std::exp(x[k]);
    shapes.centers(k) = x[r->m + k];
  }
  Eigen::MatrixXd gram;
  Eigen::VectorXd projection;
  r->target->NormalEquations(shapes, gram, projection);
  const Eigen::VectorXd a = gram.completeOrthogonalDecomposition().solve(projection);
  return r->target->Cost(a, shapes, nullptr);
}

TEST(GaussianFit, IndependentRandomStartsFindNoLowerCost) {
  // a derivative-free minimiser (Subplex) from 40 random starts: none may beat the fit
  const FitResult fit = FitGaussians(Indicator(2), kL1, kL2, 1.0);
  const auto target = MakeFitTarget(Indicator(2), kL1, kL2, 1.0);
  Reduced reduced{target.get(), 2};
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> log_precision(std::log(1e4), std::log(1e7)),
      center(0.09, 0.11);
  double lowest = INFINITY;
  int agreeing = 0;
  for (int start = 0; start < 40; ++start) {
    nlopt_opt opt = nlopt_create(NLOPT_LN_SBPLX, 4);
    nlopt_set_min_objective(opt, ReducedCost, &reduced);
    nlopt_set_xtol_rel(opt, 1e-12);
    nlopt_set_maxeval(opt, 20000);
    double x[4] = {log_precision(rng), log_precision(rng), center(rng), center(rng)};
    double value = INFINITY;
    nlopt_optimize(opt, x, &value);
    nlopt_destroy(opt);
    lowest = std::min(lowest, value);
    if (std::abs(value - fit.cost) < 1e-9 * fit.cost) ++agreeing;
  }
  EXPECT_GE(lowest, fit.cost * (1.0 - 1e-9));
  EXPECT_GE(agreeing, 5);  // the optimum is found again from independent starts
}

TEST(GaussianFit, MoreGaussiansNeverFitWorse) {
  double previous = INFINITY;
  for (int m = 1; m <= 4; ++m) {
    const FitResult fit = FitGaussians(Indicator(m), kL1, kL2, 1.0);
    EXPECT_LE(fit.cost, previous * (1.0 + 1e-12)) << "m = " << m;
    EXPECT_NEAR(fit.relative_residual, fit.cost / (kL2 - kL1), 1e-15);
    previous = fit.cost;
  }
}

TEST(GaussianFit, OnlyTheRatioOfWidthToSigmaMatters) {
  const FitResult one = FitGaussians(Indicator(2), kL1, kL2, 1.0);
  const FitResult four = FitGaussians(Indicator(2), kL1, kL2, 4.0);
  EXPECT_NEAR(one.cost, four.cost, 1e-10 * one.cost);
  EXPECT_NEAR(4.0 * one.gaussians[0].precision, four.gaussians[0].precision,
              1e-5 * four.gaussians[0].precision);
}

TEST(GaussianFit, IsDeterministic) {
  const FitResult a = FitGaussians(Indicator(3), kL1, kL2, 1.0);
  const FitResult b = FitGaussians(Indicator(3), kL1, kL2, 1.0);
  ASSERT_EQ(a.gaussians.size(), b.gaussians.size());
  for (std::size_t k = 0; k < a.gaussians.size(); ++k) {
    EXPECT_EQ(a.gaussians[k].precision, b.gaussians[k].precision);
    EXPECT_EQ(a.gaussians[k].center, b.gaussians[k].center);
    EXPECT_EQ(a.gaussians[k].amplitude, b.gaussians[k].amplitude);
  }
}

TEST(GaussianFit, SamplesFromKnownGaussiansAreRecovered) {
  // noise-free samples of a known 2-Gaussian curve: the fit reproduces it exactly
  const std::vector<Gaussian> truth{{0.02, 2e5, 0.097}, {0.015, 5e5, 0.103}};
  FitSpec spec;
  spec.count = 2;
  spec.target = FitTargetKind::kSamples;
  for (int i = 0; i <= 40; ++i) {
    const double x = 0.09 + 0.0005 * i;
    double y = 0.0;
    for (const Gaussian& g : truth) {
      y += g.amplitude / std::sqrt(2 * std::numbers::pi) *
           std::exp(-g.precision * (x - g.center) * (x - g.center) / 2);
    }
    spec.points.push_back({x, y});
  }
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  EXPECT_LT(fit.relative_residual, 1e-16);
  std::vector<Gaussian> found = fit.gaussians;
  std::sort(found.begin(), found.end(),
            [](const Gaussian& p, const Gaussian& q) { return p.center < q.center; });
  for (std::size_t k = 0; k < truth.size(); ++k) {
    EXPECT_NEAR(found[k].center, truth[k].center, 1e-7);
    EXPECT_NEAR(found[k].precision, truth[k].precision, 1e-4 * truth[k].precision);
    EXPECT_NEAR(found[k].amplitude, truth[k].amplitude, 1e-4 * truth[k].amplitude);
  }
}

TEST(GaussianFit, FixedShapesGiveTheLinearLeastSquaresAmplitudes) {
  FitSpec spec;
  spec.count = 3;
  spec.target = FitTargetKind::kSamples;
  spec.precisions = {1e5, 3e5, 1e5};
  spec.centers = {0.096, 0.1, 0.104};
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int i = 0; i < 30; ++i) {
    const double x = 0.09 + 0.0007 * i;
    spec.points.push_back({x, std::exp(-std::pow((x - 0.1) / 0.006, 2)) + noise(rng)});
  }
  // independent reference: QR least squares on the design matrix
  Eigen::MatrixXd design(30, 3);
  Eigen::VectorXd y(30);
  for (int i = 0; i < 30; ++i) {
    y(i) = spec.points[i].y;
    for (int k = 0; k < 3; ++k) {
      const double dx = spec.points[i].x - spec.centers[k];
      design(i, k) = std::exp(-spec.precisions[k] * dx * dx / 2) / std::sqrt(2 * std::numbers::pi);
    }
  }
  const Eigen::VectorXd reference = design.householderQr().solve(y);
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  EXPECT_EQ(fit.iterations, 0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(fit.gaussians[k].precision, spec.precisions[k]);
    EXPECT_NEAR(fit.gaussians[k].amplitude, reference(k), 1e-8 * reference.norm());
  }
}

TEST(GaussianFit, NonnegativeAmplitudesSatisfyOptimalityConditions) {
  // random Gram systems: a >= 0, gradient 2(Ga - r) zero where a > 0 and >= 0 where a = 0
  std::mt19937 rng(8);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 1 + trial % 6;
    Eigen::MatrixXd basis(m + 4, m);
    for (Eigen::Index i = 0; i < basis.size(); ++i) basis.data()[i] = normal(rng);
    const Eigen::MatrixXd gram = basis.transpose() * basis;
    Eigen::VectorXd r(m);
    for (int k = 0; k < m; ++k) r(k) = normal(rng);
    const Eigen::VectorXd a = SolveAmplitudes(gram, r, true);
    const Eigen::VectorXd gradient = gram * a - r;
    for (int k = 0; k < m; ++k) {
      EXPECT_GE(a(k), 0.0);
      if (a(k) > 0) {
        EXPECT_NEAR(gradient(k), 0.0, 1e-10 * (1 + r.norm())) << trial;
      } else {
        EXPECT_GE(gradient(k), -1e-10 * (1 + r.norm())) << trial;
      }
    }
  }
}

TEST(GaussianFit, NonnegativeFitKeepsAmplitudesNonnegative) {
  FitSpec spec = Indicator(3);
  spec.nonnegative = true;
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  for (const Gaussian& g : fit.gaussians) EXPECT_GE(g.amplitude, 0.0);
  EXPECT_LT(fit.relative_residual, 0.1);
}

TEST(GaussianFit, PolygonFitFollowsABellShapedCurve) {
  // a trapezoid like the classic length-tension curve: 3 Gaussians fit it within 1%
  FitSpec spec;
  spec.count = 3;
  spec.target = FitTargetKind::kPolygon;
  spec.points = {{0.06, 0.0}, {0.09, 1.0}, {0.105, 1.0}, {0.14, 0.0}};
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  EXPECT_LT(fit.relative_residual, 0.01);
}

std::string Rejection(const FitSpec& spec) {
  return testing::Rejection([&] { Validate(spec); });
}

TEST(GaussianFit, RejectsEachRule) {
  FitSpec spec = Indicator(0);
  EXPECT_THAT(Rejection(spec), HasSubstr("count = 0: must be an integer from 1 to 12"));
  spec = Indicator(2);
  spec.target = FitTargetKind::kPolygon;
  spec.points = {{0.1, 1.0}};
  EXPECT_THAT(Rejection(spec), HasSubstr("points = 1 points: a polygon needs at least 2"));
  spec.points = {{0.1, 1.0}, {0.09, 1.0}};
  EXPECT_THAT(Rejection(spec), HasSubstr("points[1][0] = 0.09: polygon x must be strictly"));
  spec = Indicator(2);
  spec.precisions = {1.0, 2.0};
  EXPECT_THAT(Rejection(spec), HasSubstr("give both or neither"));
  spec.centers = {0.1};
  EXPECT_THAT(Rejection(spec), HasSubstr("centers = 1 values: must have count = 2"));
  spec.centers = {0.1, 0.1};
  spec.precisions = {1.0, 0.0};
  EXPECT_THAT(Rejection(spec), HasSubstr("widths[1] = 0: must be finite and > 0"));
  EXPECT_THAT([] { ParseFitTargetKind("square"); },
              ::testing::ThrowsMessage<ParameterError>(HasSubstr("target = square: must be")));
}

}  // namespace
}  // namespace musclesim
