// Optimal control against its closed form (docs/model.md 13.3): an actuator whose tension is
// f_iso u moves a mass rest to rest against a constant load with the least integral of u^2;
// the optimal activation is linear in time with a known cost. And the shooting program's
// derivatives against central differences of its own values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/optimize/multiple_shooting.h"
#include "musclesim/optimize/optimal_control.h"
#include "optimize/derivative_check.h"
#include "optimize/flat_actuator.h"

namespace musclesim {
namespace {

using optimize_test::FlatActuatorOnALoad;
using optimize_test::kForce;
using optimize_test::kLoad;
using optimize_test::kMass;
using optimize_test::kSpan;
using optimize_test::kStart;
using optimize_test::kTravel;

OptimalControlProblem RestToRest(int intervals) {
  OptimalControlProblem problem;
  problem.scenario = FlatActuatorOnALoad();
  problem.intervals = intervals;
  problem.controls = {{"muscle", 0.0, 1.0, 1.0, 2}};
  problem.final_values = {{"mass.position", kStart - kTravel, kStart - kTravel},
                          {"mass.velocity", 0.0, 0.0}};
  return problem;
}

// u*(t) and J* of docs/model.md 13.3
double OptimalActivation(double t) {
  return (kLoad + 6.0 * kMass * kTravel / (kSpan * kSpan) * (1.0 - 2.0 * t / kSpan)) / kForce;
}
double OptimalCost() {
  return (12.0 * kMass * kMass * kTravel * kTravel / std::pow(kSpan, 3) + kLoad * kLoad * kSpan) /
         (kForce * kForce);
}

class AnalyticOptimum : public ::testing::TestWithParam<int> {};

TEST_P(AnalyticOptimum, IsTheLinearActivationOfTheClosedForm) {
  const OptimalControlResult result = SolveOptimalControl(RestToRest(GetParam()));
  ASSERT_TRUE(result.solved) << result.status;
  ASSERT_EQ(result.controls.size(), 1u);
  // the actuator is f_iso u to about 1e-7 and IPOPT stops at 1e-9 of its scaled optimality:
  // measured, u within 2.1e-7 and J within 4.3e-8 of the closed form's
  for (std::size_t i = 0; i < result.times.size(); ++i) {
    EXPECT_NEAR(result.controls[0][i], OptimalActivation(result.times[i]), 1e-6)
        << "t = " << result.times[i];
  }
  EXPECT_NEAR(result.objective, OptimalCost(), 1e-7 * OptimalCost());
  EXPECT_LT(result.constraint_violation, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(AnyGrid, AnalyticOptimum, ::testing::Values(1, 4, 10));

TEST(MultipleShooting, DerivativesMatchCentralDifferences) {
  MultipleShooting shooting(RestToRest(4));
  std::vector<double> x = shooting.StartingPoint();
  // a random point: controls within (0.15, 0.25), inner states moved off the continuous run
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int controls = 5;  // 1 control on 4 intervals
  for (int i = 0; i < controls; ++i) x[static_cast<std::size_t>(i)] = 0.15 + 0.1 * unit(random);
  for (std::size_t i = controls; i < x.size(); ++i) x[i] += 1e-3 * (unit(random) - 0.5);

  std::vector<double> steps(x.size(), 1e-7);
  std::fill(steps.begin(), steps.begin() + controls, 1e-6);
  ExpectExactDerivatives(shooting, x, steps, 1e-6);
}

}  // namespace
}  // namespace musclesim
