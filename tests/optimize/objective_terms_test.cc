// The objective's tracking, terminal and final-time terms, path bounds and free parameters:
// their derivatives against central differences, the tracking integral against a quadrature
// of a dense run, an optimum against perturbations of each control evaluated that way, and
// the minimum time against the bang-bang time of the closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "musclesim/optimize/multiple_shooting.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/solver/simulation.h"
#include "optimize/derivative_check.h"
#include "optimize/flat_actuator.h"

namespace musclesim {
namespace {

using optimize_test::FlatActuatorOnALoad;
using optimize_test::kForce;
using optimize_test::kLoad;
using optimize_test::kMass;
using optimize_test::kStart;
using optimize_test::kTravel;

// A reference the mass cannot follow exactly: a dip and back, its kinks off the grid.
std::vector<TablePoint> Dip() { return {{0.0, 0.1}, {0.033, 0.094}, {0.061, 0.09}, {0.1, 0.097}}; }

double Interpolate(const std::vector<TablePoint>& r, double t) {
  for (std::size_t i = 1; i < r.size(); ++i) {
    if (t <= r[i].t) {
      return r[i - 1].value +
             (r[i].value - r[i - 1].value) * (t - r[i - 1].t) / (r[i].t - r[i - 1].t);
    }
  }
  return r.back().value;
}

// The mass's position every 1e-5 s of `scenario`'s run (the mass is node 1).
std::vector<double> DensePositions(const Scenario& scenario, double step) {
  const NetworkSystem system = scenario.Build();
  NetworkRunRequest request;
  request.t_start = scenario.t_start;
  request.t_end = scenario.t_end;
  request.output_interval = step;
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, scenario.solver, request);
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  std::vector<double> positions;
  for (const NetworkSample& sample : run.samples) positions.push_back(sample.position[1]);
  return positions;
}

// weight * integral of (position - r)^2 by composite Simpson on the dense run (step 1e-5 s;
// the reference's kinks cost O(step^2) relative there, 1e-10 of the integral)
double TrackingByQuadrature(const Scenario& scenario, const std::vector<TablePoint>& r,
                            double weight) {
  const double step = 1e-5;
  const std::vector<double> x = DensePositions(scenario, step);
  const std::size_t m = x.size() - 1;  // even: 0.1 s / 1e-5 s
  EXPECT_EQ(m % 2, 0u);
  double sum = 0.0;
  for (std::size_t i = 0; i <= m; ++i) {
    const double miss = x[i] - Interpolate(r, scenario.t_start + step * static_cast<double>(i));
    const double coefficient = (i == 0 || i == m) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += coefficient * miss * miss;
  }
  return weight * sum * step / 3.0;
}

// integral of u^2 of a table linear between its points, exactly
double Effort(const Waveform& table) {
  double sum = 0.0;
  for (std::size_t i = 1; i < table.points.size(); ++i) {
    const double a = table.points[i - 1].value, b = table.points[i].value;
    sum += (table.points[i].t - table.points[i - 1].t) * (a * a + a * b + b * b) / 3.0;
  }
  return sum;
}

OptimalControlProblem Tracking(int intervals) {
  OptimalControlProblem problem;
  problem.scenario = FlatActuatorOnALoad();
  problem.intervals = intervals;
  problem.controls = {{"muscle", 0.0, 1.0, 1e-3, 2}};
  problem.tracking = {{"mass.position", Dip(), 1e3}};
  return problem;
}

// A point off the optimum and off continuity: the controls within (0.15, 0.25), the inner
// states moved by up to 5e-4.
std::vector<double> RandomPoint(MultipleShooting& shooting, int controls) {
  std::vector<double> x = shooting.StartingPoint();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < controls; ++i) x[static_cast<std::size_t>(i)] = 0.15 + 0.1 * unit(random);
  for (std::size_t i = static_cast<std::size_t>(controls); i < x.size(); ++i) {
    x[i] += 1e-3 * (unit(random) - 0.5);
  }
  return x;
}

TEST(ObjectiveTerms, DerivativesOfEveryTermAndParameterMatchCentralDifferences) {
  OptimalControlProblem problem = Tracking(4);
  problem.terminal = {{"mass.velocity", 0.0, 10.0}};
  problem.final_values = {{"muscle.length", 0.07, 0.11}};
  problem.path_bounds = {{"muscle.tension", 0.0, 100.0}, {"mass.velocity", -1.0, 1.0}};
  // a closed-form parameter (f_iso) and one by difference quotient (the load)
  problem.parameters = {{"models.flat.f_iso", 50.0, 200.0}, {"loads[0].value", 0.0, 40.0}};
  MultipleShooting shooting(problem);
  const std::vector<double> x = RandomPoint(shooting, 5);
  std::vector<double> steps(x.size(), 1e-7);
  std::fill(steps.begin(), steps.begin() + 5, 1e-6);
  steps[steps.size() - 2] = 1e-4;  // f_iso [N]
  steps.back() = 1e-5;             // the load [N]
  ExpectExactDerivatives(shooting, x, steps, 2e-6);
}

TEST(ObjectiveTerms, DerivativesInAFreeFinalTimeMatchCentralDifferences) {
  OptimalControlProblem problem;
  problem.scenario = FlatActuatorOnALoad();
  problem.intervals = 4;
  problem.controls = {{"muscle", 0.0, 1.0, 1.0, 2}};
  problem.final_values = {{"mass.position", 0.08, 0.08}, {"mass.velocity", 0.0, 0.0}};
  problem.path_bounds = {{"mass.velocity", -1.0, 1.0}};
  problem.terminal = {{"mass.position", 0.08, 100.0}};
  problem.final_time = FreeFinalTime{0.05, 0.2, 1.0};
  MultipleShooting shooting(problem);
  std::vector<double> x = RandomPoint(shooting, 5);
  x.back() = 0.13;  // T
  std::vector<double> steps(x.size(), 1e-7);
  std::fill(steps.begin(), steps.begin() + 5, 1e-6);
  ExpectExactDerivatives(shooting, x, steps, 2e-6);
}

// x's inner states set to where the intervals before them end: continuous, one run through
// (each pass makes one more interval start right).
void MakeContinuous(MultipleShooting& shooting, std::vector<double>& x, int first_state) {
  std::vector<double> g(static_cast<std::size_t>(shooting.constraint_count()));
  const std::size_t states = x.size() - static_cast<std::size_t>(first_state);
  for (int pass = 0; pass < 50; ++pass) {
    ASSERT_TRUE(shooting.Constraints(x.data(), g.data()));
    for (std::size_t k = 0; k < states; ++k) x[static_cast<std::size_t>(first_state) + k] += g[k];
  }
  ASSERT_TRUE(shooting.Constraints(x.data(), g.data()));
  for (std::size_t k = 0; k < states; ++k) ASSERT_EQ(g[k], 0.0) << k;
}

// The comparison's derivatives: forward differences by colour approximate the exact ones to
// about sqrt(rtol), every term and a free final time included, and reach the same optimum.
TEST(ObjectiveTerms, DifferenceQuotientsApproximateTheSensitivities) {
  OptimalControlProblem problem = Tracking(4);
  problem.terminal = {{"mass.velocity", 0.0, 10.0}};
  problem.path_bounds = {{"muscle.tension", 0.0, 100.0}};
  problem.parameters = {{"models.flat.f_iso", 50.0, 200.0}};
  for (const bool timed : {false, true}) {
    if (timed) {
      problem.tracking.clear();
      problem.path_bounds = {{"mass.velocity", -1.0, 1.0}};
      problem.final_time = FreeFinalTime{0.05, 0.2, 1.0};
    }
    MultipleShooting exact(problem);
    MultipleShooting differenced(problem, ShootingDerivatives::kDifferenceQuotients);
    std::vector<double> x = RandomPoint(exact, 5);
    if (timed) x.back() = 0.12;
    std::vector<double> a(x.size()), b(x.size());
    ASSERT_TRUE(exact.ObjectiveGradient(x.data(), a.data()));
    ASSERT_TRUE(differenced.ObjectiveGradient(x.data(), b.data()));
    for (std::size_t k = 0; k < x.size(); ++k) {
      EXPECT_NEAR(b[k], a[k], 1e-3 * std::max(1.0, std::abs(a[k]))) << "gradient " << k;
    }
    std::vector<double> ja(static_cast<std::size_t>(exact.jacobian_nonzeros())), jb(ja.size());
    ASSERT_TRUE(exact.ConstraintJacobian(x.data(), ja.data()));
    ASSERT_TRUE(differenced.ConstraintJacobian(x.data(), jb.data()));
    for (std::size_t k = 0; k < ja.size(); ++k) {
      EXPECT_NEAR(jb[k], ja[k], 1e-3 * std::max(1.0, std::abs(ja[k]))) << "entry " << k;
    }
  }
  OptimizeOptions options;
  options.derivatives = ShootingDerivatives::kDifferenceQuotients;
  problem = OptimalControlProblem{};
  problem.scenario = FlatActuatorOnALoad();
  problem.intervals = 4;
  problem.controls = {{"muscle", 0.0, 1.0, 1.0, 2}};
  problem.final_values = {{"mass.position", kStart - kTravel, kStart - kTravel},
                          {"mass.velocity", 0.0, 0.0}};
  const OptimalControlResult by_quotients = SolveOptimalControl(problem, options);
  const OptimalControlResult by_sensitivities = SolveOptimalControl(problem);
  ASSERT_TRUE(by_sensitivities.solved) << by_sensitivities.status;
  EXPECT_NEAR(by_quotients.objective, by_sensitivities.objective,
              1e-4 * by_sensitivities.objective);
}

// The excitation of an actuator with activation dynamics as the control: its first value sets
// the activation's start as well (no initial_activation given), and the final time is free.
TEST(ObjectiveTerms, DerivativesInAnExcitationMatchCentralDifferences) {
  OptimalControlProblem problem;
  problem.scenario = FlatActuatorOnALoad(
      "excitation: {type: constant, value: 0.2}, "
      "activation_dynamics: {tau_activation: 0.01, tau_deactivation: 0.04}");
  problem.intervals = 4;
  problem.controls = {{"muscle", 0.0, 1.0, 1.0, 2}};
  problem.final_values = {{"mass.position", 0.08, 0.08}, {"muscle.activation", 0.0, 1.0}};
  problem.tracking = {{"muscle.tension", {{0.0, 20.0}, {0.1, 25.0}}, 1e-2}};
  problem.parameters = {{"elements[0].activation_dynamics.tau_activation", 0.005, 0.05}};
  MultipleShooting shooting(problem);
  const std::vector<double> x = RandomPoint(shooting, 5);
  std::vector<double> steps(x.size(), 1e-5);
  std::fill(steps.begin(), steps.begin() + 5, 1e-5);
  steps.back() = 1e-6;  // tau_act [s]
  ExpectExactDerivatives(shooting, x, steps, 2e-6);

  problem.tracking.clear();
  problem.final_time = FreeFinalTime{0.05, 0.2, 1.0};
  MultipleShooting timed(problem);
  std::vector<double> y = RandomPoint(timed, 5);
  y.back() = 0.12;
  steps.push_back(1e-6);
  ExpectExactDerivatives(timed, y, steps, 2e-6);
}

// With activation dynamics the optimum's excitation is written as the table a run follows: it
// re-simulates to the final values.
TEST(ObjectiveTerms, AnExcitationOptimumReSimulatesToItsFinalValues) {
  OptimalControlProblem problem;
  problem.scenario = FlatActuatorOnALoad(
      "excitation: {type: constant, value: 0.2}, "
      "activation_dynamics: {tau_activation: 0.01, tau_deactivation: 0.04}");
  problem.intervals = 10;
  problem.controls = {{"muscle", 0.0, 1.0, 1.0, 2}};
  problem.final_values = {{"mass.position", kStart - kTravel, kStart - kTravel},
                          {"mass.velocity", 0.0, 0.0}};
  const OptimalControlResult result = SolveOptimalControl(problem);
  ASSERT_TRUE(result.solved) << result.status;
  EXPECT_LT(result.resimulation_deviation, 1e-8);
  const Element& muscle = result.scenario.elements[0];
  ASSERT_TRUE(muscle.excitation.has_value());
  EXPECT_EQ(muscle.excitation->signal.points.size(), 11u);
  const NetworkSystem system = result.scenario.Build();
  NetworkRunRequest request;
  request.t_start = 0.0;
  request.t_end = result.final_time;
  request.output_times = {result.final_time};
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, result.scenario.solver, request);
  ASSERT_EQ(run.samples.size(), 1u);
  EXPECT_NEAR(run.samples[0].position[1], kStart - kTravel, 1e-8);
  EXPECT_NEAR(run.samples[0].velocity[1], 0.0, 1e-7);
}

TEST(ObjectiveTerms, TrackingIsTheIntegralOfTheSquaredMiss) {
  const OptimalControlProblem problem = Tracking(5);
  MultipleShooting shooting(problem);
  std::vector<double> x = RandomPoint(shooting, 6);
  MakeContinuous(shooting, x, 6);
  ObjectiveTerms terms;
  ASSERT_TRUE(shooting.Terms(x.data(), terms));
  const double quadrature = TrackingByQuadrature(shooting.ScenarioAt(x.data()), Dip(), 1e3);
  EXPECT_NEAR(terms.tracking, quadrature, 1e-7 * quadrature);
  EXPECT_GT(quadrature, 1e-6);  // a real miss
}

TEST(ObjectiveTerms, NoControlPerturbationLowersATrackingOptimum) {
  const OptimalControlProblem problem = Tracking(8);
  OptimizeOptions options;
  options.tolerance = 1e-8;
  const OptimalControlResult result = SolveOptimalControl(problem, options);
  ASSERT_TRUE(result.solved) << result.status;
  EXPECT_LT(result.dual_infeasibility, 1e-8);
  EXPECT_LT(result.gradient_check, 1e-5);
  EXPECT_LT(result.resimulation_deviation, 1e-9);
  // the objective of a control table evaluated independently: the quadrature of a dense run
  // and the exact effort
  const auto objective = [&](const Scenario& scenario) {
    return TrackingByQuadrature(scenario, Dip(), 1e3) +
           1e-3 * Effort(scenario.elements[0].activation);
  };
  const double optimum = objective(result.scenario);
  EXPECT_NEAR(optimum, result.objective, 1e-7 * optimum);
  int at_bounds = 0;
  for (std::size_t i = 0; i < result.times.size(); ++i) {
    for (const double delta : {-1e-3, 1e-3}) {
      Scenario moved = result.scenario;
      std::vector<TablePoint> points = moved.elements[0].activation.points;
      const double u = points[i].value + delta;
      if (u < 0.0 || u > 1.0) {
        ++at_bounds;
        continue;  // outside the bounds
      }
      points[i].value = u;
      moved.elements[0].activation = Waveform::Table(points);
      EXPECT_GE(objective(moved), optimum * (1.0 - 1e-9))
          << "u(" << result.times[i] << ") " << delta;
    }
  }
  EXPECT_LT(at_bounds, static_cast<int>(result.times.size()));
}

// Rest to rest over kTravel toward the anchor in the least time, 0 <= u <= 1: the net force
// toward the anchor f_iso u - F0 lies within [-F0, f_iso - F0], so the fastest move
// accelerates at a1 = (f_iso - F0) / m, then brakes at a2 = F0 / m, switching at
// t1 = sqrt(2 D a2 / (a1 (a1 + a2))), and takes T* = t1 (1 + a1 / a2). Piecewise-linear
// controls cannot jump: their optimum is slower, and approaches T* as the grid refines.
TEST(ObjectiveTerms, MinimumTimeApproachesTheBangBangTime) {
  const double a1 = (kForce - kLoad) / kMass, a2 = kLoad / kMass;
  const double t1 = std::sqrt(2.0 * kTravel * a2 / (a1 * (a1 + a2)));
  const double fastest = t1 * (1.0 + a1 / a2);
  std::vector<double> times;
  for (const int intervals : {10, 20, 40}) {
    OptimalControlProblem problem;
    problem.scenario = FlatActuatorOnALoad();
    problem.intervals = intervals;
    problem.controls = {{"muscle", 0.0, 1.0, 0.0, 2}};
    problem.final_values = {{"mass.position", kStart - kTravel, kStart - kTravel},
                            {"mass.velocity", 0.0, 0.0}};
    problem.final_time = FreeFinalTime{0.005, 0.1, 1.0};
    const OptimalControlResult result = SolveOptimalControl(problem);
    ASSERT_TRUE(result.solved) << result.status << " at N = " << intervals;
    EXPECT_LT(result.constraint_violation, 1e-9);
    EXPECT_LT(result.resimulation_deviation, 1e-8);
    EXPECT_GE(result.final_time, fastest * (1.0 - 1e-9)) << intervals;
    times.push_back(result.final_time);
  }
  EXPECT_LT(times[1], times[0]);
  EXPECT_LT(times[2], times[1]);
  // measured: 1.7e-4, 4.1e-5 and 1.0e-5 s above T*, second order in the grid's step
  EXPECT_LT(times[2] - fastest, 0.1 * (times[0] - fastest));
}

}  // namespace
}  // namespace musclesim
