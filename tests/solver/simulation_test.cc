#include "musclesim/solver/simulation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <thread>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "support/canonical_actuator.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using testing::Experiment;
using ::testing::HasSubstr;
using testing::Outcome;
using testing::ScenarioPath;
using testing::Simulate;

using testing::FlatModel;

// The flat model, fully active, mass 0.01 kg, under a constant `load` from rest at
// `length`, for 0.2 s recorded every 1 ms at rtol 1e-10.
Experiment FlatIsotonic(double load, double length = 0.1) {
  ActuatorParams actuator;
  actuator.mass = 0.01;
  RunRequest request;
  request.t_end = 0.2;
  request.length = length;
  request.output_interval = 1e-3;
  SolverOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-13;
  return {ActuatorSystem(FlatModel(), actuator, Waveform::Constant(1.0), {Load::Constant(load)}),
          request, options};
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
  const Experiment experiment = FlatIsotonic(load);
  const RunResult run = experiment.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const TensionModel& model = experiment.system.model();
  int checked = 0;
  for (const TrajectoryPoint& p : run.trajectory) {
    if (p.t < 0.05) continue;  // the transient lasts a few m / (dT/dv) ~ 1e-4 s
    const double expected = SteadyVelocity(model, p.sample.length, 1.0, load);
    // what is left is inertia: m dv/dt / (dT/dv) ~ 1e-7 relative with m = 0.01 kg, and the
    // solver's error at rtol 1e-10; 1e-5 relative leaves a margin of a hundred
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

// The subject here is the canonical scenario file, so it is read from scenarios/.
TEST(Simulation, IsometricTransducerReadsTheIsometricTension) {
  // run long enough for the transducer to settle (time constant (dT/dv) / k_t = 0.1 s)
  const Outcome run = Simulate(ScenarioPath("isometric.yaml"), {"time.end=3"});
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const TensionModel model(run.scenario.models.at("model").spec.params);
  const double x = run.trajectory.back().sample.length;
  const double transducer = 1.0e5 * (0.1 - x);
  const double isometric = PassiveTension(model.params().passive, x).value +
                           100.0 * model.active_length().Evaluate(x).value;
  // after 30 time constants the transient is e^-30 of its start, and the solver's error,
  // decaying towards a stable rest point, leaves 1e-10 relative here: 1e-8 gives a margin
  // of a hundred, while a wrong T_p or f_L would be per cents off
  EXPECT_NEAR(transducer, isometric, 1e-8 * isometric);
  // settled: 1e-12 m/s here; 1e-9 m/s is ten times atol, still at rest
  EXPECT_NEAR(run.trajectory.back().sample.shortening_velocity, 0.0, 1e-9);
  // docs/guide/scenarios.md: "holds while the length moves 1 mm" (printed to
  // the millimetre: within half of one)
  EXPECT_NEAR(0.1 - x, 1e-3, 0.5e-3);
}

// Largest difference of length over the common output grid, relative to the length.
double LengthError(const RunResult& a, const RunResult& b) {
  EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
  double error = 0.0;
  for (std::size_t i = 0; i < std::min(a.trajectory.size(), b.trajectory.size()); ++i) {
    EXPECT_EQ(a.trajectory[i].t, b.trajectory[i].t);
    error =
        std::max(error, std::abs(a.trajectory[i].sample.length - b.trajectory[i].sample.length) /
                            std::abs(b.trajectory[i].sample.length));
  }
  return error;
}

// `experiment` run with other solver settings.
RunResult RunWith(Experiment experiment, double rtol, double atol,
                  IntegrationMethod method = IntegrationMethod::kBdf,
                  JacobianKind jacobian = JacobianKind::kAnalytic) {
  experiment.options.rtol = rtol;
  experiment.options.atol = atol;
  experiment.options.method = method;
  experiment.options.jacobian = jacobian;
  return experiment.Run();
}

TEST(Simulation, ErrorFallsWithTheTolerance) {
  const Experiment concentric = testing::Concentric();
  const RunResult reference = RunWith(concentric, 1e-11, 1e-14);
  double previous = INFINITY;
  for (double rtol : {1e-4, 1e-6, 1e-8}) {
    const double error = LengthError(RunWith(concentric, rtol, 1e-3 * rtol), reference);
    EXPECT_LT(error, previous) << "rtol " << rtol;
    // CVODE controls the local error; the global error it leaves is a modest multiple of
    // rtol (0.2 to 0.4 rtol in this run). 100 rtol bounds it with room for other step
    // sequences; the reference's own error, 2e-11, is below every rtol tried
    EXPECT_LT(error, 100 * rtol) << "rtol " << rtol;
    previous = error;
  }
}

TEST(Simulation, BdfAndAdamsAgree) {
  const Experiment concentric = testing::Concentric();
  const RunResult bdf = RunWith(concentric, 1e-9, 1e-12);
  const RunResult adams = RunWith(concentric, 1e-9, 1e-12, IntegrationMethod::kAdams);
  // two methods, each within a modest multiple of rtol = 1e-9 of the truth (3e-9 apart
  // here); 100 rtol bounds their difference as in ErrorFallsWithTheTolerance
  EXPECT_LT(LengthError(adams, bdf), 1e-7);
}

TEST(Simulation, AnalyticAndDifferenceQuotientJacobiansGiveOneTrajectory) {
  for (const Experiment& experiment : {testing::Concentric(), testing::Isometric()}) {
    const RunResult analytic = RunWith(experiment, 1e-8, 1e-11);
    const RunResult quotient = RunWith(experiment, 1e-8, 1e-11, IntegrationMethod::kBdf,
                                       JacobianKind::kDifferenceQuotient);
    // the Jacobian only steers Newton's iteration: both runs meet rtol 1e-8, so they agree
    // to their global errors (3e-9 and 2e-10 apart here), bounded by 100 rtol = 1e-6
    EXPECT_LT(LengthError(analytic, quotient), 1e-6);
  }
}

TEST(Simulation, AnalyticJacobianNeedsFewerRightHandSides) {
  // with two states a difference-quotient Jacobian costs only two extra right-hand sides,
  // and single runs differ by more than that through their step sequences; summed over
  // a tolerance sweep the analytic Jacobian needs fewer (docs/performance.md)
  for (const Experiment& experiment : {testing::Concentric(), testing::Eccentric()}) {
    long analytic_total = 0, quotient_total = 0;
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
      analytic_total += RunWith(experiment, rtol, 1e-12).stats.rhs_evals;
      const RunResult quotient = RunWith(experiment, rtol, 1e-12, IntegrationMethod::kBdf,
                                         JacobianKind::kDifferenceQuotient);
      quotient_total += quotient.stats.rhs_evals;
      EXPECT_GT(quotient.stats.jac_evals, 0);
    }
    EXPECT_LT(analytic_total, quotient_total) << experiment.request.max_length.value_or(0.0);
  }
}

TEST(Simulation, NothingMovesWithoutActivationOrLoadBelowSlack) {
  // the concentric experiment with both steps going to zero: below the slack length with
  // u = 0 and no load, the acceleration is exactly zero, through both breakpoints
  const Experiment concentric = testing::Concentric();
  const Experiment still{
      ActuatorSystem(concentric.system.shared_model(), concentric.system.actuator(),
                     Waveform::Step(0.05, 0.0, 0.0), {Load::Force(Waveform::Step(0.05, 0.0, 0.0))}),
      concentric.request, concentric.options};
  const RunResult run = still.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted);
  for (const TrajectoryPoint& p : run.trajectory) {
    EXPECT_EQ(p.sample.length, 0.1) << p.t;
    EXPECT_EQ(p.sample.shortening_velocity, 0.0) << p.t;
    EXPECT_EQ(p.sample.tension.total, 0.0) << p.t;
  }
}

TEST(Simulation, LengthLimitEndsTheRunNormally) {
  Experiment concentric = testing::Concentric();
  concentric.request.min_length = 0.09;
  const RunResult run = concentric.Run();
  EXPECT_EQ(run.stats.status, RunStatus::kLimit);
  EXPECT_THAT(run.stats.message, HasSubstr("min_length = 0.09 reached"));
  // CVODE locates the root of x - 0.09 on its own solution to ~100 ulps of t (~1e-14 s);
  // at the 0.15 m/s of that moment the recorded length misses 0.09 m by ~1e-15 m: 1e-12 m
  EXPECT_NEAR(run.trajectory.back().sample.length, 0.09, 1e-12);
  EXPECT_LT(run.stats.final_time, 0.5);
  EXPECT_EQ(run.trajectory.back().t, run.stats.final_time);
}

TEST(Simulation, ReachingZeroLengthIsAFailure) {
  // no load: the active actuator pulls itself shut from 1 cm
  const RunResult run = FlatIsotonic(0.0, 0.01).Run();
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("the length of actuator reached zero"));
  // the root of x itself, located to ~1e-14 s at a speed below 1 m/s (atol 1e-13 m)
  EXPECT_NEAR(run.trajectory.back().sample.length, 0.0, 1e-12);
}

TEST(Simulation, TooManyStepsIsAFailureNamingCvodesFlag) {
  Experiment isometric = testing::Isometric();
  isometric.options.max_steps = 20;
  const RunResult run = isometric.Run();
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("CV_TOO_MUCH_WORK"));
  EXPECT_THAT(run.stats.message, HasSubstr("CVODE failed at t = "));
  EXPECT_FALSE(run.trajectory.empty());  // the rows before the failure are kept
}

TEST(Simulation, StepsStopAtMaxSteps) {
  // the guard allows exactly max_steps steps, and the last row is where the last step ended
  Experiment concentric = testing::Concentric();
  concentric.request.output_interval = 0.0;  // every internal step a row
  concentric.options.max_steps = 50;
  const RunResult run = concentric.Run();
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_EQ(run.stats.steps, 50);
  EXPECT_EQ(run.trajectory.back().t, run.stats.final_time);
}

// Times strictly increasing, and the grid's last time the run's end.
void ExpectIncreasingTimes(const RunResult& run) {
  for (std::size_t i = 1; i < run.trajectory.size(); ++i) {
    ASSERT_LT(run.trajectory[i - 1].t, run.trajectory[i].t) << "row " << i;
  }
}

TEST(Simulation, ALimitReachedOnAnOutputTimeEndsWithOneRow) {
  // the limit set to the length the free run records at t = 0.1 s (and at its end): the run
  // stops there, a rounding error either side of the grid time, with one last row
  Experiment concentric = testing::Concentric();
  concentric.request.max_length.reset();
  const RunResult free_run = concentric.Run();
  ASSERT_EQ(free_run.stats.status, RunStatus::kCompleted);
  for (const std::size_t row : {std::size_t{100}, free_run.trajectory.size() - 1}) {
    const double level = free_run.trajectory[row].sample.length;
    ASSERT_LT(level, concentric.request.length);  // shortening: a minimum length
    Experiment limited = concentric;
    limited.request.min_length = level;
    const RunResult run = limited.Run();
    SCOPED_TRACE("row " + std::to_string(row));
    EXPECT_EQ(run.stats.status, RunStatus::kLimit);
    ExpectIncreasingTimes(run);
    EXPECT_NEAR(run.trajectory.back().t, free_run.trajectory[row].t, 1e-12);
    EXPECT_NEAR(run.trajectory.back().sample.length, level, 1e-12);
    EXPECT_LE(run.trajectory.size(), row + 1);
  }
}

TEST(Simulation, AGridFarFromZeroHasOneRowPerIntervalAndEndsAtTheEnd) {
  // 0.3 s from t = 1e6 s at 0.01 s: 30 intervals, though the span's rounding makes
  // span / interval 30.000000005
  Experiment concentric = testing::Concentric();
  concentric.request.t_start = 1000000.1;
  concentric.request.t_end = 1000000.4;
  concentric.request.output_interval = 0.01;
  const RunResult run = concentric.Run();
  ASSERT_EQ(run.trajectory.size(), 31u);
  ExpectIncreasingTimes(run);
  EXPECT_EQ(run.trajectory.back().t, 1000000.4);
}

TEST(Simulation, EveryStepModeStopsExactlyAtBreakpoints) {
  Experiment concentric = testing::Concentric();
  concentric.request.output_interval = 0.0;  // every internal step
  const RunResult run = concentric.Run();
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
  const Experiment concentric = testing::Concentric();
  const Experiment eccentric = testing::Eccentric();
  const auto run = [](Simulation& sim, const Experiment& e) {
    std::vector<TrajectoryPoint> trajectory;
    sim.Run(e.system, e.options, e.request, trajectory);
    return trajectory;
  };
  Simulation sim;
  const auto first = run(sim, concentric);
  run(sim, eccentric);
  const std::vector<TrajectoryPoint> again = run(sim, concentric);  // CVodeReInit, same memory
  std::vector<TrajectoryPoint> threaded[2];
  std::thread a([&] {
    Simulation s;
    threaded[0] = run(s, concentric);
  });
  std::thread b([&] {
    Simulation s;
    threaded[1] = run(s, concentric);
  });
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
  const Experiment concentric = testing::Concentric();
  Simulation simulation;
  try {
    simulation.Run(concentric.system, concentric.options, request);
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
  const Experiment concentric = testing::Concentric();
  Simulation simulation;
  std::vector<TrajectoryPoint> buffered;
  const RunStats stats =
      simulation.Run(concentric.system, concentric.options, concentric.request, buffered);
  const RunResult result =
      simulation.Run(concentric.system, concentric.options, concentric.request);
  ASSERT_EQ(result.trajectory.size(), buffered.size());
  EXPECT_EQ(result.stats.steps, stats.steps);
  for (std::size_t i = 0; i < result.trajectory.size(); ++i) {
    ASSERT_EQ(result.trajectory[i].sample.length, buffered[i].sample.length) << i;
  }
}

// Every scenario shipped in scenarios/ runs to ten times its end time. Pulse edges and
// output times drift apart by rounding errors as runs get longer (twitches.yaml once failed
// with CV_TOO_CLOSE at t = 4.11 s): this is the guard against that class of failure. The
// sanitizer build, there to find memory and undefined-behaviour errors on the same code
// paths rather than the drift, runs them to twice their end: ten times cost it 11 minutes.
TEST(Simulation, EveryShippedScenarioRunsToTenTimesItsEnd) {
  const double runs_of_its_end = MUSCLESIM_SANITIZED ? 2.0 : 10.0;
  int checked = 0;
  const std::string scenarios = std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios";
  for (const auto& entry : std::filesystem::directory_iterator(scenarios)) {
    const std::string path = entry.path().string();
    if (testing::ReadFile(path).find("\ntime:") == std::string::npos) continue;  // sweeps, fits
    // either form: a single actuator runs as its network (docs/model.md 7.4)
    const Scenario scenario = LoadScenario(path);
    const std::string end =
        FormatNumber(scenario.t_start + runs_of_its_end * (scenario.t_end - scenario.t_start));
    const RecordedRun run = RunScenario(LoadScenario(path, {"time.end=" + end}));
    EXPECT_NE(run.stats.status, RunStatus::kFailed) << path << ": " << run.stats.message;
    ++checked;
  }
  EXPECT_GE(checked, 12);  // the seven single-actuator scenarios and the five networks
}

}  // namespace
}  // namespace musclesim
