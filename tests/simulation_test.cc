#include "musclesim/solver/simulation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <thread>

#include "musclesim/errors.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using testing::Outcome;
using testing::ScenarioPath;
using testing::Simulate;
using ::testing::HasSubstr;

// A model whose f_L is almost flat over the motion (one Gaussian 1 m wide) and with no
// passive tension, so that an isotonic run reaches a true steady velocity.
std::string FlatModelScenario(double load, double mass) {
  return R"(model:
  f_iso: 100.0
  passive: {k_p: 0.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians: [{amplitude: 1.0, width: 1.0, center: 0.1}]
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
actuator: {mass: )" + std::to_string(mass) + R"(}
initial: {length: 0.1}
activation: {type: constant, value: 1.0}
load: {type: constant, value: )" + std::to_string(load) + R"(}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-10, atol: 1.0e-13}
output: {interval: 0.001}
)";
}

// The shortening velocity at which T(x, v, u) = load: bisection on the model functions,
// T being strictly decreasing in v.
double SteadyVelocity(const TensionModel& model, double x, double u, double load) {
  double lo = -10.0, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (model.Evaluate(x, mid, u).total > load ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void ExpectSteadyVelocity(double load) {
  const Outcome run = Simulate(
      testing::WriteTempFile("steady_" + std::to_string(load) + ".yaml", FlatModelScenario(load, 0.01)));
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const TensionModel model(run.spec.model.params);
  int checked = 0;
  for (const TrajectoryPoint& p : run.trajectory) {
    if (p.t < 0.05) continue;  // the transient lasts a few m / (dT/dv) ~ 1e-4 s
    const double expected = SteadyVelocity(model, p.sample.length, 1.0, load);
    // what is left is inertia: m dv/dt / (dT/dv) ~ 1e-7 relative with m = 0.01 kg
    EXPECT_NEAR(p.sample.shortening_velocity, expected, 1e-5 * std::abs(expected)) << p.t;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(Simulation, ConcentricSteadyVelocitySolvesTheTensionBalance) {
  ExpectSteadyVelocity(40.0);  // g = 0.4: v = 0.216 m/s, shortening
}

TEST(Simulation, EccentricSteadyVelocitySolvesTheTensionBalance) {
  ExpectSteadyVelocity(130.0);  // g = 1.3: v = -0.027 m/s, lengthening
}

TEST(Simulation, IsometricTransducerReadsTheIsometricTension) {
  // run long enough for the transducer to settle (time constant (dT/dv) / k_t = 0.1 s)
  const Outcome run = Simulate(ScenarioPath("isometric.yaml"), {"time.end=3"});
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const TensionModel model(run.spec.model.params);
  const double x = run.trajectory.back().sample.length;
  const double transducer = 1.0e5 * (0.1 - x);
  const double isometric = PassiveTension(model.params().passive, x).value +
                           100.0 * model.active_length().Evaluate(x).value;
  EXPECT_NEAR(transducer, isometric, 1e-6 * isometric);
  EXPECT_NEAR(run.trajectory.back().sample.shortening_velocity, 0.0, 1e-9);
}

// Largest difference of length over the common output grid, relative to the length.
double LengthError(const Outcome& a, const Outcome& b) {
  EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
  double error = 0.0;
  for (std::size_t i = 0; i < std::min(a.trajectory.size(), b.trajectory.size()); ++i) {
    EXPECT_EQ(a.trajectory[i].t, b.trajectory[i].t);
    error = std::max(error, std::abs(a.trajectory[i].sample.length - b.trajectory[i].sample.length) /
                                std::abs(b.trajectory[i].sample.length));
  }
  return error;
}

TEST(Simulation, ErrorFallsWithTheTolerance) {
  const std::string path = ScenarioPath("concentric.yaml");
  const Outcome reference = Simulate(path, {"solver.rtol=1e-11", "solver.atol=1e-14"});
  double previous = INFINITY;
  for (const char* rtol : {"1e-4", "1e-6", "1e-8"}) {
    const double atol = std::stod(rtol) * 1e-3;
    const Outcome run =
        Simulate(path, {std::string("solver.rtol=") + rtol, "solver.atol=" + FormatNumber(atol)});
    const double error = LengthError(run, reference);
    EXPECT_LT(error, previous) << "rtol " << rtol;
    EXPECT_LT(error, 100 * std::stod(rtol)) << "rtol " << rtol;  // CVODE's global error
    previous = error;
  }
}

TEST(Simulation, BdfAndAdamsAgree) {
  const std::string path = ScenarioPath("concentric.yaml");
  const Outcome bdf = Simulate(path, {"solver.rtol=1e-9", "solver.atol=1e-12"});
  const Outcome adams =
      Simulate(path, {"solver.method=adams", "solver.rtol=1e-9", "solver.atol=1e-12"});
  EXPECT_LT(LengthError(adams, bdf), 1e-7);
}

TEST(Simulation, AnalyticAndDifferenceQuotientJacobiansGiveOneTrajectory) {
  for (const char* scenario : {"concentric.yaml", "isometric.yaml"}) {
    const std::string path = ScenarioPath(scenario);
    const Outcome analytic = Simulate(path, {"solver.rtol=1e-8", "solver.atol=1e-11"});
    const Outcome quotient =
        Simulate(path, {"solver.jacobian=difference_quotient", "solver.rtol=1e-8", "solver.atol=1e-11"});
    EXPECT_LT(LengthError(analytic, quotient), 1e-6) << scenario;
  }
}

TEST(Simulation, AnalyticJacobianNeedsFewerRightHandSides) {
  // with two states a difference-quotient Jacobian costs only two extra right-hand sides,
  // and single runs differ by more than that through their step sequences; summed over
  // a tolerance sweep the analytic Jacobian needs fewer
  for (const char* scenario : {"concentric.yaml", "eccentric.yaml"}) {
    long analytic_total = 0, quotient_total = 0;
    for (const char* rtol : {"1e-4", "1e-6", "1e-8", "1e-10"}) {
      const std::vector<std::string> sets = {std::string("solver.rtol=") + rtol,
                                             "solver.atol=1e-12"};
      std::vector<std::string> dq = sets;
      dq.push_back("solver.jacobian=difference_quotient");
      analytic_total += Simulate(ScenarioPath(scenario), sets).stats.rhs_evals;
      const Outcome quotient = Simulate(ScenarioPath(scenario), dq);
      quotient_total += quotient.stats.rhs_evals;
      EXPECT_GT(quotient.stats.jac_evals, 0);
    }
    EXPECT_LT(analytic_total, quotient_total) << scenario;
  }
}

TEST(Simulation, NothingMovesWithoutActivationOrLoadBelowSlack) {
  const Outcome run = Simulate(ScenarioPath("concentric.yaml"),
                               {"activation.after=0", "load[0].after=0"});
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted);
  for (const TrajectoryPoint& p : run.trajectory) {
    EXPECT_EQ(p.sample.length, 0.1) << p.t;
    EXPECT_EQ(p.sample.shortening_velocity, 0.0) << p.t;
    EXPECT_EQ(p.sample.tension.total, 0.0) << p.t;
  }
}

TEST(Simulation, LengthLimitEndsTheRunNormally) {
  const Outcome run = Simulate(ScenarioPath("concentric.yaml"), {"limits.min_length=0.09"});
  EXPECT_EQ(run.stats.status, RunStatus::kLimit);
  EXPECT_THAT(run.stats.message, HasSubstr("min_length = 0.09 reached"));
  EXPECT_NEAR(run.trajectory.back().sample.length, 0.09, 1e-9);
  EXPECT_LT(run.stats.final_time, 0.5);
  EXPECT_EQ(run.trajectory.back().t, run.stats.final_time);
}

TEST(Simulation, ReachingZeroLengthIsAFailure) {
  std::string text = FlatModelScenario(0.0, 0.01);
  text.replace(text.find("initial: {length: 0.1}"), 22, "initial: {length: 0.01}");
  const Outcome run = Simulate(testing::WriteTempFile("collapse.yaml", text));
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("the length reached zero"));
  EXPECT_NEAR(run.trajectory.back().sample.length, 0.0, 1e-12);
}

TEST(Simulation, TooManyStepsIsAFailureNamingCvodesFlag) {
  const Outcome run = Simulate(ScenarioPath("isometric.yaml"), {"solver.max_steps=20"});
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("CV_TOO_MUCH_WORK"));
  EXPECT_THAT(run.stats.message, HasSubstr("CVODE failed at t = "));
  EXPECT_FALSE(run.trajectory.empty());  // the rows before the failure are kept
}

TEST(Simulation, EveryStepModeStopsExactlyAtBreakpoints) {
  const Outcome run = Simulate(ScenarioPath("concentric.yaml"), {"output.interval=steps"});
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted);
  EXPECT_GE(static_cast<long>(run.trajectory.size()), run.stats.steps);
  bool hit_step = false;
  for (std::size_t i = 1; i < run.trajectory.size(); ++i) {
    EXPECT_GT(run.trajectory[i].t, run.trajectory[i - 1].t);
    hit_step = hit_step || run.trajectory[i].t == 0.05;
  }
  EXPECT_TRUE(hit_step);  // the activation and load step at 0.05 s is a stop time
  EXPECT_EQ(run.trajectory.back().t, 0.5);
}

TEST(Simulation, ReuseAndThreadsGiveIdenticalRuns) {
  const ScenarioSpec concentric = LoadScenario(ScenarioPath("concentric.yaml"));
  const ScenarioSpec eccentric = LoadScenario(ScenarioPath("eccentric.yaml"));
  const auto run = [](Simulation& sim, const ScenarioSpec& s) {
    const ActuatorSystem system(s.model.params, s.actuator, s.activation, s.loads);
    std::vector<TrajectoryPoint> trajectory;
    sim.Run(system, s.solver, s.Request(), trajectory);
    return trajectory;
  };
  Simulation sim;
  const auto first = run(sim, concentric);
  run(sim, eccentric);
  const std::vector<TrajectoryPoint> again = run(sim, concentric);  // CVodeReInit, same memory
  std::vector<TrajectoryPoint> threaded[2];
  std::thread a([&] { Simulation s; threaded[0] = run(s, concentric); });
  std::thread b([&] { Simulation s; threaded[1] = run(s, concentric); });
  a.join();
  b.join();
  const std::vector<TrajectoryPoint>* others[] = {&again, &threaded[0], &threaded[1]};
  for (const std::vector<TrajectoryPoint>* other : others) {
    ASSERT_EQ(other->size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ((*other)[i].sample.length, first[i].sample.length);
    }
  }
}

// The path of the ParameterError that running `request` throws, or "accepted".
std::string RequestErrorPath(const RunRequest& request) {
  const Outcome concentric = Simulate(ScenarioPath("concentric.yaml"));
  Simulation simulation;
  const ActuatorSystem system(concentric.spec.model.params, concentric.spec.actuator,
                              concentric.spec.activation, concentric.spec.loads);
  try {
    simulation.Run(system, concentric.spec.solver, request);
  } catch (const ParameterError& e) {
    return e.path();
  }
  return "accepted";
}

TEST(Simulation, RunValidatesItsRequest) {
  RunRequest good;
  good.t_end = 0.01;
  EXPECT_EQ(RequestErrorPath(good), "accepted");
  RunRequest r = good;
  r.t_end = -1.0;  // ends before it starts
  EXPECT_EQ(RequestErrorPath(r), "t_end");
  r = good;
  r.output_interval = -1e-3;
  EXPECT_EQ(RequestErrorPath(r), "output_interval");
  r = good;
  r.output_interval = 1e-12;  // 1e10 rows
  EXPECT_EQ(RequestErrorPath(r), "output_interval");
  r = good;
  r.min_length = 0.2;  // above the initial length 0.1: would report "limit" at once
  EXPECT_EQ(RequestErrorPath(r), "min_length");
  r = good;
  r.max_length = 0.05;
  EXPECT_EQ(RequestErrorPath(r), "max_length");
  r = good;
  r.length = std::nan("");
  EXPECT_EQ(RequestErrorPath(r), "length");
}

TEST(Simulation, RunResultHoldsWhatTheBufferedRunRecords) {
  const Outcome buffered = Simulate(ScenarioPath("concentric.yaml"));
  Simulation simulation;
  const ActuatorSystem system(buffered.spec.model.params, buffered.spec.actuator,
                              buffered.spec.activation, buffered.spec.loads);
  const RunResult result = simulation.Run(system, buffered.spec.solver, buffered.spec.Request());
  ASSERT_EQ(result.trajectory.size(), buffered.trajectory.size());
  EXPECT_EQ(result.stats.steps, buffered.stats.steps);
  for (std::size_t i = 0; i < result.trajectory.size(); ++i) {
    ASSERT_EQ(result.trajectory[i].sample.length, buffered.trajectory[i].sample.length) << i;
  }
}

// Every scenario shipped in scenarios/ runs to ten times its end time. Pulse edges and
// output times drift apart by rounding errors as runs get longer (twitches.yaml once failed
// with CV_TOO_CLOSE at t = 4.11 s): this is the guard against that class of failure.
TEST(Simulation, EveryShippedScenarioRunsToTenTimesItsEnd) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios")) {
    const std::string path = entry.path().string();
    if (testing::ReadFile(path).find("\ntime:") == std::string::npos) continue;  // sweeps, fits
    const ScenarioSpec spec = LoadScenario(path);
    const std::string end = FormatNumber(spec.t_start + 10.0 * (spec.t_end - spec.t_start));
    const Outcome run = Simulate(path, {"time.end=" + end});
    EXPECT_NE(run.stats.status, RunStatus::kFailed) << path << ": " << run.stats.message;
    ++checked;
  }
  EXPECT_GE(checked, 7);
}

}  // namespace
}  // namespace musclesim
