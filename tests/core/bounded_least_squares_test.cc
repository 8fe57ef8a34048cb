// The bounded Levenberg-Marquardt fit (core/bounded_least_squares.h) that time-series
// identification runs, on closed-form models whose optimum is known independently.
#include "musclesim/core/bounded_least_squares.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// y(t) = a exp(-t / tau) + c at t = 0, 0.1, ..., 2, with its exact Jacobian.
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

BoundedLeastSquaresProblem DecayProblem(const Eigen::Vector3d& truth,
                                        const Eigen::Vector3d& start) {
  BoundedLeastSquaresProblem problem;
  problem.model = Decay;
  problem.data = Decay(truth).predictions;
  problem.weights = Eigen::VectorXd::Ones(problem.data.size());
  problem.start = start;
  problem.lower = Eigen::VectorXd::Constant(3, -kInf);
  problem.upper = Eigen::VectorXd::Constant(3, kInf);
  return problem;
}

TEST(BoundedLeastSquares, RecoversExactDataFromAFarStart) {
  const Eigen::Vector3d truth(2.0, 0.3, 0.5);
  const LeastSquaresResult r = SolveBoundedLeastSquares(DecayProblem(truth, {0.5, 1.5, -1.0}));
  EXPECT_TRUE(r.converged) << r.stop_reason;
  // exact data: the minimum is the truth with cost 0; the iteration stops when the
  // Gauss-Newton step, about the remaining error, is below 1e-10 relative
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.parameters[j], truth[j], 1e-9 * std::abs(truth[j]));
  EXPECT_LT(r.cost, 1e-20);
  EXPECT_GT(r.iterations, 2);  // the start is far: not a one-step problem
}

TEST(BoundedLeastSquares, ParametersOfVeryDifferentSizesConverge) {
  // a 1e6 amplitude beside a 1e-4 time constant: Moré's column scaling makes the steps
  // invariant to such units
  const Eigen::Vector3d truth(1e6, 0.2, 1e-3);
  const LeastSquaresResult r = SolveBoundedLeastSquares(DecayProblem(truth, {5e5, 0.35, 0.0}));
  EXPECT_TRUE(r.converged) << r.stop_reason;
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(r.parameters[j], truth[j], 1e-9 * std::abs(truth[j]));
  EXPECT_NEAR(r.parameters[2], truth[2], 1e-6);  // 1e-12 of the 1e6 amplitude's scale
}

// y = p0 + p1 t on t = 0..9: linear, so the bounded optimum has a closed form.
ModelPoint Line(const Eigen::VectorXd& p) {
  ModelPoint m{Eigen::VectorXd(10), Eigen::MatrixXd(10, 2)};
  for (int i = 0; i < 10; ++i) {
    m.predictions[i] = p[0] + p[1] * i;
    m.jacobian.row(i) << 1.0, double(i);
  }
  return m;
}

TEST(BoundedLeastSquares, StopsOnABoundWhereTheFreeOptimumLiesBeyondIt) {
  BoundedLeastSquaresProblem problem;
  problem.model = Line;
  problem.data.resize(10);
  for (int i = 0; i < 10; ++i) problem.data[i] = 1.0 + 2.0 * i + (i % 2 ? 0.1 : -0.1);
  problem.weights = Eigen::VectorXd::Ones(10);
  problem.start = Eigen::Vector2d(0.0, 0.5);
  problem.lower = Eigen::Vector2d(-kInf, 0.0);
  problem.upper = Eigen::Vector2d(kInf, 1.5);  // the slope's free optimum is near 2
  // the cost at the bound is far from zero, so the improvement rule would stop within
  // sqrt(1e-8 cost / n) = 3e-4 of the intercept: off here, to test the projection alone
  LeastSquaresOptions options;
  options.improvement_tolerance = 0.0;
  const LeastSquaresResult r = SolveBoundedLeastSquares(problem, options);
  EXPECT_TRUE(r.converged) << r.stop_reason << " " << r.iterations << " " << r.evaluations;
  EXPECT_EQ(r.parameters[1], 1.5);  // the projection puts it exactly on the bound
  // with the slope held at 1.5 the best intercept is the mean of y - 1.5 t
  double mean = 0.0;
  for (int i = 0; i < 10; ++i) mean += (problem.data[i] - 1.5 * i) / 10.0;
  // linear: the last Gauss-Newton step is the remaining error, below 1e-10 relative (3.25)
  EXPECT_NEAR(r.parameters[0], mean, 4e-10);
  EXPECT_FALSE(r.at_bound[0]);
  EXPECT_TRUE(r.at_bound[1]);
}

TEST(BoundedLeastSquares, StepsWhereTheModelFailsAreRejectedNotFatal) {
  // the model refuses time constants above 0.5, as a simulation refuses a value outside its
  // rules; the first steps from 0.45 overshoot into that region
  BoundedLeastSquaresProblem problem = DecayProblem({2.0, 0.3, 0.5}, {0.2, 0.45, 2.0});
  problem.model = [](const Eigen::VectorXd& p) {
    if (p[1] > 0.5) throw InputError("model.tau = " + std::to_string(p[1]) + ": must be <= 0.5");
    if (p[1] <= 0.0) throw EvaluationFailure("tau <= 0");
    return Decay(p);
  };
  const LeastSquaresResult r = SolveBoundedLeastSquares(problem);
  EXPECT_TRUE(r.converged) << r.stop_reason;
  EXPECT_NEAR(r.parameters[1], 0.3, 1e-9);  // exact data; room for the stopping rules
}

TEST(BoundedLeastSquares, AZeroColumnKeepsItsParameterAtTheStart) {
  BoundedLeastSquaresProblem problem = DecayProblem({2.0, 0.3, 0.5}, {1.0, 0.5, 0.0});
  // a fourth parameter the outputs do not depend on
  problem.model = [](const Eigen::VectorXd& p) {
    ModelPoint m = Decay(p.head(3));
    m.jacobian.conservativeResize(Eigen::NoChange, 4);
    m.jacobian.col(3).setZero();
    return m;
  };
  problem.start = Eigen::Vector4d(1.0, 0.5, 0.0, 7.0);
  problem.lower = Eigen::VectorXd::Constant(4, -kInf);
  problem.upper = Eigen::VectorXd::Constant(4, kInf);
  const LeastSquaresResult r = SolveBoundedLeastSquares(problem);
  EXPECT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.parameters[3], 7.0);
  EXPECT_NEAR(r.parameters[1], 0.3, 1e-9);  // exact data; room for the stopping rules
}

TEST(BoundedLeastSquares, ABudgetTooSmallIsReportedAsNotConverged) {
  LeastSquaresOptions options;
  options.max_evaluations = 2;
  const LeastSquaresResult r =
      SolveBoundedLeastSquares(DecayProblem({2.0, 0.3, 0.5}, {0.5, 1.5, -1.0}), options);
  EXPECT_FALSE(r.converged);
  EXPECT_THAT(r.stop_reason, ::testing::HasSubstr("budget of 2 model evaluations"));
  EXPECT_EQ(r.evaluations, 2);
}

TEST(BoundedLeastSquares, AStartOutsideTheBoundsIsRefused) {
  BoundedLeastSquaresProblem problem = DecayProblem({2.0, 0.3, 0.5}, {0.5, 1.5, -1.0});
  problem.upper[1] = 1.0;
  EXPECT_THROW(SolveBoundedLeastSquares(problem), std::invalid_argument);
}

}  // namespace
}  // namespace musclesim
