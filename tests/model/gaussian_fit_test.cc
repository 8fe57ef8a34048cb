#include "musclesim/model/gaussian_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlopt.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/model_yaml.h"
#include "support/numeric.h"
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
  // the cost the fit reports is the cost of the parameters it reports: the cost is ~6e-4 m,
  // so 1e-15 m allows rounding (~1e-12 relative) and nothing more
  EXPECT_NEAR(CostAt(*target, fit.gaussians), fit.cost, 1e-15);
  // Trials 0-11 move one of the 6 parameters (a_k, b_k, d_k of the two Gaussians) alone,
  // trial / 2 naming it, by +1e-4 on even trials and -1e-4 on odd ones (relative; a centre
  // by 1e-4 of the span of L_opt): a strict minimum rises both ways. Trials 12-199 move all
  // 6 at once along random directions of that size. A step h raises the cost by about
  // H h^2 / 2, 1e-8 to 1e-5 of it here, while rounding in the cost is ~1e-16 of it: the
  // 1e-13 allowance admits rounding only.
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Gaussian> moved = fit.gaussians;
    for (std::size_t k = 0; k < moved.size(); ++k) {
      double step[3];  // relative steps of a_k, b_k, d_k
      for (int j = 0; j < 3; ++j) {
        const int parameter = static_cast<int>(3 * k) + j;
        if (trial < 12) {
          step[j] = trial / 2 == parameter ? (trial % 2 == 0 ? 1e-4 : -1e-4) : 0.0;
        } else {
          step[j] = 1e-4 * normal(rng);
        }
      }
      moved[k].amplitude *= 1.0 + step[0];
      moved[k].precision *= 1.0 + step[1];
      moved[k].center += step[2] * (kL2 - kL1);
    }
    const double cost = CostAt(*target, moved);
    if (trial < 12) {
      EXPECT_GT(cost, fit.cost) << "trial " << trial;  // the parameter did move
    } else {
      EXPECT_GE(cost, fit.cost * (1.0 - 1e-13)) << "trial " << trial;
    }
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
    // Subplex stopped by xtol 1e-12 ends within ~1e-12 of an optimum in the shapes, hence
    // ~1e-20 in a quadratic cost: 1e-9 relative calls it the same optimum, with room for
    // Subplex stopping early on a flat stretch
    if (std::abs(value - fit.cost) < 1e-9 * fit.cost) ++agreeing;
  }
  EXPECT_GE(lowest, fit.cost * (1.0 - 1e-9));  // as above: nothing lower beyond convergence
  EXPECT_GE(agreeing, 5);                      // the optimum is found again from independent starts
}

TEST(GaussianFit, MoreGaussiansNeverFitWorse) {
  double previous = INFINITY;
  for (int m = 1; m <= 4; ++m) {
    const FitResult fit = FitGaussians(Indicator(m), kL1, kL2, 1.0);
    // a fit with one more Gaussian can reproduce the smaller one exactly (amplitude 0), so
    // it is no worse but for the optimiser's convergence, ~1e-12 relative
    EXPECT_LE(fit.cost, previous * (1.0 + 1e-12)) << "m = " << m;
    // N / c with c = l2 - l1 = 0.01 m: one division, rounding only (residuals 0.02 to 0.11)
    EXPECT_NEAR(fit.relative_residual, fit.cost / (kL2 - kL1), 1e-15);
    previous = fit.cost;
  }
}

TEST(GaussianFit, OnlyTheRatioOfWidthToSigmaMatters) {
  const FitResult one = FitGaussians(Indicator(2), kL1, kL2, 1.0);
  const FitResult four = FitGaussians(Indicator(2), kL1, kL2, 4.0);
  // the two problems are the same after b -> 4 b (here the results are identical), so at
  // most they differ by the optimiser's convergence: 1e-10 relative in the cost, and its
  // square root, 1e-5, in the shapes, along which the minimum is flat
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
  // a zero residual up to rounding (4e-22 here): squares of errors of 1e-16 relative
  EXPECT_LT(fit.relative_residual, 1e-16);
  std::vector<Gaussian> found = fit.gaussians;
  std::sort(found.begin(), found.end(),
            [](const Gaussian& p, const Gaussian& q) { return p.center < q.center; });
  // the cost is flat near the truth (zero residual): rounding in the cost, 1e-16 of it,
  // pins the shapes only to its square root, 1e-8 relative (1e-10 is found here); 1e-7 m
  // on centres 6 mm apart, and 1e-4 relative on b and a, leave that a margin
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
    // two solvers of one least-squares problem: QR on the design errs by cond(design)
    // eps_mach, the fit's normal equations by cond^2 eps_mach; cond(design) = 2.4 here, so
    // both are within 1e-15: 1e-12 relative admits rounding only
    EXPECT_NEAR(fit.gaussians[k].amplitude, reference(k), 1e-12 * reference.norm());
  }
}

// The Karush-Kuhn-Tucker conditions of min a^T G a - 2 r^T a over a >= 0: a >= 0, the
// gradient 2(Ga - r) zero where a > 0 and >= 0 where a = 0.
void ExpectOptimalityConditions(const Eigen::MatrixXd& gram, const Eigen::VectorXd& r,
                                const Eigen::VectorXd& a, int trial) {
  const Eigen::VectorXd gradient = gram * a - r;
  // the active-set solve is exact up to rounding in the normal equations, gradients below
  // 1e-15 of |r| in these tests (even where G is nearly singular); 1e-10 leaves a wide
  // margin, while a wrong active set leaves gradients of order |r|
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    EXPECT_GE(a(k), 0.0) << trial;
    if (a(k) > 0) {
      EXPECT_NEAR(gradient(k), 0.0, 1e-10 * (1 + r.norm())) << trial;
    } else {
      EXPECT_GE(gradient(k), -1e-10 * (1 + r.norm())) << trial;
    }
  }
}

TEST(GaussianFit, NonnegativeAmplitudesSatisfyOptimalityConditions) {
  // random Gram systems (cond(G) <= 190)
  std::mt19937 rng(8);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 1 + trial % 6;
    Eigen::MatrixXd basis(m + 4, m);
    for (Eigen::Index i = 0; i < basis.size(); ++i) basis.data()[i] = normal(rng);
    const Eigen::MatrixXd gram = basis.transpose() * basis;
    Eigen::VectorXd r(m);
    for (int k = 0; k < m; ++k) r(k) = normal(rng);
    ExpectOptimalityConditions(gram, r, SolveAmplitudes(gram, r, true), trial);
  }
}

TEST(GaussianFit, NonnegativeAmplitudesOfOverlappingGaussiansSatisfyOptimalityConditions) {
  // the systems a samples fit meets: 4 to 12 Gaussians of spread 0.2 at random centres on
  // [0, 1], sampled at 40 points, against noisy data of mean 1. Neighbours overlap, so G is
  // nearly singular and many amplitudes want to be negative: the active set changes often,
  // and an update that drops every negative amplitude at once, instead of stepping back to
  // the feasible point first, can cycle here without reaching the optimum.
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> center(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const int m = 4 + trial % 9, rows = 40;
    const double spread = 0.2;
    Eigen::MatrixXd basis(rows, m);
    for (int k = 0; k < m; ++k) {
      const double c = center(rng);
      for (int i = 0; i < rows; ++i) {
        const double x = (i + 0.5) / rows;
        basis(i, k) = std::exp(-0.5 * (x - c) * (x - c) / (spread * spread));
      }
    }
    Eigen::VectorXd y(rows);
    for (int i = 0; i < rows; ++i) y(i) = 1.0 + normal(rng);
    const Eigen::MatrixXd gram = basis.transpose() * basis;
    const Eigen::VectorXd r = basis.transpose() * y;
    ExpectOptimalityConditions(gram, r, SolveAmplitudes(gram, r, true), trial);
  }
}

TEST(GaussianFit, NonnegativeFitKeepsAmplitudesNonnegative) {
  FitSpec spec = Indicator(3);
  spec.nonnegative = true;
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  for (const Gaussian& g : fit.gaussians) EXPECT_GE(g.amplitude, 0.0);
  // a bound, not a tolerance: without the sign constraint three Gaussians reach 0.036, and
  // a failed non-negative solve (all zero) would leave the whole target, residual 1
  EXPECT_LT(fit.relative_residual, 0.1);
}

TEST(GaussianFit, PolygonFitFollowsABellShapedCurve) {
  // a trapezoid like the classic length-tension curve: 3 Gaussians fit it within 1%
  FitSpec spec;
  spec.count = 3;
  spec.target = FitTargetKind::kPolygon;
  spec.points = {{0.06, 0.0}, {0.09, 1.0}, {0.105, 1.0}, {0.14, 0.0}};
  const FitResult fit = FitGaussians(spec, kL1, kL2, 1.0);
  // a bound, not a tolerance: the trapezoid's corners keep any Gaussian sum ~1e-3 away
  EXPECT_LT(fit.relative_residual, 0.01);
}

// integral over R of (f - indicator of [kL1, kL2])^2 / (kL2 - kL1) by quadrature: the
// relative residual computed without the closed-form cost
double QuadratureResidual(const std::vector<Gaussian>& gaussians) {
  const auto squared_error = [&](double x) {
    double f = 0.0;
    for (const Gaussian& g : gaussians) {
      f += g.amplitude / std::sqrt(2 * std::numbers::pi) *
           std::exp(-g.precision * (x - g.center) * (x - g.center) / 2);
    }
    const double target = (x >= kL1 && x <= kL2) ? 1.0 : 0.0;
    return (f - target) * (f - target);
  };
  // beyond 0.2 m of L_opt the Gaussians (spreads of a few mm) are below 1e-300
  // to 1e-14 m on a cost of 6e-4 m: far below the README's last digit
  return testing::Integrate(squared_error, kL1 - 0.2, kL2 + 0.2, {kL1, kL2}, 1e-14) / (kL2 - kL1);
}

// docs/guide/model.md: on scenarios/fit_indicator.yaml the two-Gaussian fit is
// symmetric about the middle of L_opt with relative residual 0.0606, and three Gaussians
// reach 0.0360. Both are printed to 4 decimals: +-5e-5.
TEST(GaussianFit, ReadmeFiguresOfThePapersIndicatorFit) {
  const ModelSpec spec =
      LoadModelSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/fit_indicator.yaml");
  ASSERT_TRUE(spec.fit && spec.fit_result);
  const ActiveLengthParams& curve = spec.params.active_length;
  ASSERT_EQ(curve.optimal_min, kL1);
  ASSERT_EQ(curve.optimal_max, kL2);
  EXPECT_NEAR(spec.fit_result->relative_residual, 0.0606, 5e-5);
  EXPECT_NEAR(QuadratureResidual(spec.fit_result->gaussians), 0.0606, 5e-5);

  // symmetric: mirror images about 0.1 m. The optimiser stops within ~1e-8 relative of the
  // optimum in the shapes; 1e-6 (of the span, and relative) is "symmetric" to well below
  // anything the README's 3 digits could show
  std::vector<Gaussian> g = spec.fit_result->gaussians;
  ASSERT_EQ(g.size(), 2u);
  std::sort(g.begin(), g.end(),
            [](const Gaussian& p, const Gaussian& q) { return p.center < q.center; });
  EXPECT_NEAR(g[0].center + g[1].center, kL1 + kL2, 1e-6 * (kL2 - kL1));
  EXPECT_NEAR(g[0].amplitude, g[1].amplitude, 1e-6 * std::abs(g[1].amplitude));
  EXPECT_NEAR(g[0].precision, g[1].precision, 1e-6 * g[1].precision);

  FitSpec three = *spec.fit;
  three.count = 3;
  const FitResult fit3 = FitGaussians(three, kL1, kL2, curve.sigma);
  EXPECT_NEAR(fit3.relative_residual, 0.0360, 5e-5);
  EXPECT_NEAR(QuadratureResidual(fit3.gaussians), 0.0360, 5e-5);
}

std::string Rejection(const FitSpec& spec) {
  return testing::Rejection([&] { Validate(spec); });
}

TEST(GaussianFit, SamplesNeedThreePointsPerGaussianOrOneWithShapesFixed) {
  // b, d and a for each Gaussian: 2 Gaussians need 6 samples; with b and d given, 2
  FitSpec spec = Indicator(2);
  spec.target = FitTargetKind::kSamples;
  for (int i = 0; i < 5; ++i) spec.points.push_back({0.09 + 0.005 * i, 1.0});
  EXPECT_THAT(Rejection(spec), HasSubstr("points = 5 points: samples need at least 6 points"));
  spec.points.push_back({0.12, 0.5});
  EXPECT_EQ(Rejection(spec), "accepted");
  spec.precisions = {1e5, 1e5};
  spec.centers = {0.095, 0.105};
  spec.points.resize(1);
  EXPECT_THAT(Rejection(spec), HasSubstr("points = 1 points: samples need at least 2 points"));
  spec.points.push_back({0.1, 1.0});
  EXPECT_EQ(Rejection(spec), "accepted");
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

// --- target preset -----------------------------------------------------------------------

FitSpec Preset(ForceLengthPreset preset, double l_opt, int count) {
  FitSpec spec;
  spec.count = count;
  spec.target = FitTargetKind::kPreset;
  spec.preset = preset;
  spec.optimal_length = l_opt;
  return spec;
}

TEST(GaussianFit, PresetRulesRejected) {
  FitSpec spec = Preset(ForceLengthPreset::kMuJoCo, 0.1, 2);
  EXPECT_EQ(Rejection(spec), "accepted");
  spec.preset.reset();
  EXPECT_THAT(Rejection(spec), HasSubstr("name = ~: target preset needs the name of a curve: "
                                         "one of degroote2016, thelen2003, gordon1966, mujoco"));
  spec = Preset(ForceLengthPreset::kMuJoCo, 0.1, 2);
  spec.optimal_length.reset();
  EXPECT_THAT(Rejection(spec), HasSubstr("optimal_length = ~: target preset needs optimal_length"));
  for (const double bad : {0.0, -0.1, std::nan(""), HUGE_VAL}) {
    spec.optimal_length = bad;
    EXPECT_THAT(Rejection(spec), HasSubstr("must be finite and > 0 [m]")) << bad;
  }
  spec = Preset(ForceLengthPreset::kMuJoCo, 0.1, 13);
  EXPECT_THAT(Rejection(spec), HasSubstr("count = 13: must be an integer from 1 to 12"));
  spec = Preset(ForceLengthPreset::kMuJoCo, 0.1, 2);
  spec.points = {{0.1, 1.0}, {0.2, 0.0}};
  EXPECT_THAT(Rejection(spec), HasSubstr("points = 2 points: must be absent for target preset"));
  spec = Indicator(2);
  spec.preset = ForceLengthPreset::kThelen2003;
  EXPECT_THAT(Rejection(spec),
              HasSubstr("name = thelen2003: only for target preset (this target is indicator)"));
  spec = Indicator(2);
  spec.optimal_length = 0.1;
  EXPECT_THAT(Rejection(spec), HasSubstr("optimal_length = 0.1: only for target preset"));
}

// Thelen's curve exp(-(x / l_opt - 1)^2 / gamma) is the component a = sqrt(2 pi sigma),
// b = 2 sigma / (gamma l_opt^2), d = l_opt: one Gaussian reproduces it.
TEST(GaussianFit, ThelenIsOneGaussianFoundExactly) {
  const double l_opt = 0.1, sigma = 2.0, gamma = 0.45;
  const FitResult fit =
      FitGaussians(Preset(ForceLengthPreset::kThelen2003, l_opt, 1), 0.0, 0.0, sigma);
  ASSERT_EQ(fit.gaussians.size(), 1u);
  // the optimiser stops within ~1e-8 of the optimum in the shapes; the cut at 6 standard
  // deviations moves it by less
  EXPECT_NEAR(fit.gaussians[0].amplitude, std::sqrt(2.0 * std::numbers::pi * sigma), 1e-6);
  EXPECT_NEAR(fit.gaussians[0].precision, 2.0 * sigma / (gamma * l_opt * l_opt),
              1e-6 * 2.0 * sigma / (gamma * l_opt * l_opt));
  EXPECT_NEAR(fit.gaussians[0].center, l_opt, 1e-8 * l_opt);
  EXPECT_LT(fit.relative_residual, 1e-12);
}

// The fit of a preset scaled to l_opt is the normalised fit scaled: f_L(x) = f_1(x / l_opt)
// has the centres times l_opt, the widths over l_opt^2 and the same amplitudes, and the same
// relative residual. (Thelen's is left out of the shapes: one Gaussian fits it exactly, and the
// second of two can go anywhere.)
TEST(GaussianFit, PresetFitScalesWithTheOptimalLength) {
  for (const ForceLengthPreset preset : AllForceLengthPresets()) {
    const FitResult unit = FitGaussians(Preset(preset, 1.0, 2), 0.0, 0.0, 1.0);
    const FitResult scaled = FitGaussians(Preset(preset, 0.05, 2), 0.0, 0.0, 1.0);
    // the two are separate searches that stop within ~1e-8 relative of the same optimum
    EXPECT_NEAR(scaled.relative_residual, unit.relative_residual,
                1e-6 * unit.relative_residual + 1e-14)
        << ToString(preset);
    if (preset == ForceLengthPreset::kThelen2003) continue;
    std::vector<Gaussian> a = unit.gaussians, b = scaled.gaussians;
    const auto by_center = [](const Gaussian& p, const Gaussian& q) { return p.center < q.center; };
    std::sort(a.begin(), a.end(), by_center);
    std::sort(b.begin(), b.end(), by_center);
    for (std::size_t k = 0; k < a.size(); ++k) {
      // 1e-4: shapes at a minimum are known to the square root of the cost's precision
      EXPECT_NEAR(b[k].center / 0.05, a[k].center, 1e-4) << ToString(preset);
      EXPECT_NEAR(b[k].precision * 0.05 * 0.05, a[k].precision, 1e-4 * a[k].precision);
      EXPECT_NEAR(b[k].amplitude, a[k].amplitude, 1e-4 * std::abs(a[k].amplitude));
    }
  }
}

// The fitted sum f of a result, evaluated directly.
double SumOf(const std::vector<Gaussian>& gaussians, double sigma, double x) {
  double f = 0.0;
  for (const Gaussian& g : gaussians) {
    f += g.amplitude / std::sqrt(2.0 * std::numbers::pi * sigma) *
         std::exp(-g.precision * (x - g.center) * (x - g.center) / (2.0 * sigma));
  }
  return f;
}

// integral((f - preset)^2) / integral(preset^2) by adaptive Simpson, not read from the fit:
// over the preset's support widened by 12 spreads of the widest component (beyond, each is
// below e^-72 of its peak), split at the preset's kinks
double PresetQuadratureResidual(ForceLengthPreset preset, const std::vector<Gaussian>& g) {
  const std::vector<double> breaks = PiecesOf(preset).breaks;
  double spread = 0.0;
  for (const Gaussian& c : g) spread = std::max(spread, 1.0 / std::sqrt(c.precision));
  const auto curve = [&](double x) { return EvaluatePreset(preset, x); };
  // to 1e-13 absolute: the smallest residual printed (2e-5 of a norm of about 0.5) is known
  // to 1e-8 of itself
  const double error =
      testing::Integrate([&](double x) { return std::pow(SumOf(g, 1.0, x) - curve(x), 2); },
                         breaks.front() - 12 * spread, breaks.back() + 12 * spread, breaks, 1e-13);
  const double norm = testing::Integrate([&](double x) { return curve(x) * curve(x); },
                                         breaks.front(), breaks.back(), breaks, 1e-13);
  return error / norm;
}

// A README figure against the value computed here: "< 1e-12" (or any "< BOUND") holds when
// the value is below the bound; a number printed to 3 significant digits, when the value
// rounds to it (half a unit of the third digit, and 1e-9 relative for the two computations'
// own roundoff).
void ExpectReadmeFigure(const std::string& printed, double value, const std::string& what) {
  if (printed.rfind("< ", 0) == 0) {
    EXPECT_LT(value, std::stod(printed.substr(2))) << what;
    return;
  }
  const double number = std::stod(printed);
  const double unit = std::pow(10.0, std::floor(std::log10(number)) - 2);
  EXPECT_NEAR(value, number, 0.5 * unit + 1e-9 * number) << what << " printed " << printed;
}

// docs/guide/model.md "The closed-form fit": the table scripts/preset_fit_table.sh prints. Each
// row's fit is run again and its relative residual and max abs error recomputed here independently.
TEST(GaussianFit, ReadmeTableOfPresetFits) {
  std::ifstream in(std::string(MUSCLESIM_SOURCE_DIR) + "/docs/guide/model.md");
  std::string line;
  while (std::getline(in, line) &&
         line != "| preset | Gaussians | relative residual | max abs error |") {}
  ASSERT_TRUE(in) << "docs/guide/model.md has no table of preset fits";
  std::getline(in, line);  // |---|---|...
  int rows = 0;
  while (std::getline(in, line) && line.rfind("| ", 0) == 0) {
    std::vector<std::string> cells;
    std::istringstream fields(line.substr(2));
    for (std::string cell; std::getline(fields, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    ASSERT_GE(cells.size(), 4u) << line;
    const ForceLengthPreset preset = ParseForceLengthPreset(cells[0]);
    const int count = std::stoi(cells[1]);
    const FitResult fit = FitGaussians(Preset(preset, 1.0, count), 0.0, 0.0, 1.0);
    ExpectReadmeFigure(cells[2], PresetQuadratureResidual(preset, fit.gaussians),
                       line + ": relative residual");
    // the same 2001 points from 0 to 2 l_opt as the script
    double worst = 0.0;
    for (int i = 0; i <= 2000; ++i) {
      const double x = 2.0 * i / 2000;
      worst = std::max(worst, std::abs(SumOf(fit.gaussians, 1.0, x) - EvaluatePreset(preset, x)));
    }
    ExpectReadmeFigure(cells[3], worst, line + ": max abs error");
    ++rows;
  }
  EXPECT_EQ(rows, 12);  // four presets, m = 2, 3, 4
}

}  // namespace
}  // namespace musclesim
