// Optimal control against its closed form (docs/model.md 13.3): an actuator whose tension is
// f_iso u moves a mass rest to rest against a constant load with the least integral of u^2;
// the optimal activation is linear in time with a known cost. And the shooting program's
// derivatives against central differences of its own values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <vector>

#include "musclesim/io/scenario_yaml.h"
#include "musclesim/optimize/multiple_shooting.h"
#include "musclesim/optimize/optimal_control.h"

namespace musclesim {
namespace {

constexpr double kMass = 0.1, kTravel = 0.02, kSpan = 0.1, kLoad = 20.0, kForce = 100.0;
constexpr double kStart = 0.1;  // the mass's start [m]: the actuator's length

// f_L = 1 within 1e-8 over the travel (one Gaussian of width factor 1e-4 1/m^2), g = 1 within
// 1e-7 (n = 1, v_max = 1e7 m/s), no passive tension: T = f_iso u.
Scenario FlatActuatorOnALoad() {
  // a file of this test's own (ctest runs tests in parallel processes): its name, '/' replaced
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(test->test_suite_name()) + "_" + test->name();
  std::replace(name.begin(), name.end(), '/', '_');
  const std::string path = ::testing::TempDir() + name + "_analytic_optimum.yaml";
  std::ofstream(path) << R"(name: analytic_optimum
models:
  flat:
    f_iso: 100.0
    passive: {k_p: 0.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians: [{amplitude: 1.0, width: 1.0e-4, center: 0.09}]
    velocity: {v_max: 1.0e7, n: 1, epsilon: 1.0e-3}
nodes:
  - {name: anchor, fixed: 0.0}
  - {name: mass, mass: 0.1, position: 0.1, velocity: 0.0}
elements:
  - {name: muscle, type: actuator, from: anchor, to: mass, model: flat,
     activation: {type: constant, value: 0.2}}
loads:
  - {node: mass, type: constant, value: 20.0}
time: {start: 0.0, end: 0.1}
solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14, jacobian: analytic, linear_solver: auto}
output: {file: analytic_optimum.csv, interval: 0.001}
)";
  return LoadScenario(path);
}

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

  const int n = shooting.variable_count(), m = shooting.constraint_count();
  std::vector<double> gradient(static_cast<std::size_t>(n));
  shooting.ObjectiveGradient(x.data(), gradient.data());
  std::vector<double> values(static_cast<std::size_t>(shooting.jacobian_nonzeros()));
  ASSERT_TRUE(shooting.ConstraintJacobian(x.data(), values.data()));
  std::vector<int> rows(values.size()), columns(values.size());
  shooting.JacobianStructure(rows.data(), columns.data());
  std::vector<double> jacobian(static_cast<std::size_t>(n * m), 0.0);  // dense, row-major
  for (std::size_t k = 0; k < values.size(); ++k) {
    jacobian[static_cast<std::size_t>(rows[k] * n + columns[k])] += values[k];
  }
  for (int c = 0; c < n; ++c) {
    const double h = c < controls ? 1e-6 : 1e-7;
    std::vector<double> plus = x, minus = x;
    plus[static_cast<std::size_t>(c)] += h;
    minus[static_cast<std::size_t>(c)] -= h;
    const double objective =
        (shooting.Objective(plus.data()) - shooting.Objective(minus.data())) / (2.0 * h);
    EXPECT_NEAR(gradient[static_cast<std::size_t>(c)], objective, 1e-8) << "variable " << c;
    std::vector<double> g_plus(static_cast<std::size_t>(m)), g_minus(static_cast<std::size_t>(m));
    ASSERT_TRUE(shooting.Constraints(plus.data(), g_plus.data()));
    ASSERT_TRUE(shooting.Constraints(minus.data(), g_minus.data()));
    for (int r = 0; r < m; ++r) {
      const double difference =
          (g_plus[static_cast<std::size_t>(r)] - g_minus[static_cast<std::size_t>(r)]) / (2.0 * h);
      const double exact = jacobian[static_cast<std::size_t>(r * n + c)];
      EXPECT_NEAR(exact, difference, 1e-6 * std::max(1.0, std::abs(difference)))
          << "row " << r << ", variable " << c;
    }
  }
}

}  // namespace
}  // namespace musclesim
