// The integration session (solver/integration_session.h) that runs and the stepper are made
// of: one AdvanceTo over the whole span is Simulation::Run, row for row and counter for
// counter, to the last bit; pieces ending at sample times give the Stepper's rows; a piece
// records the grid from its own start; and a piece after the end is refused.
#include "musclesim/solver/integration_session.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/solver/stepper.h"
#include "support/canonical_networks.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

// Every row a session or a run records: its time, the state it was recorded from and the
// sample observed there.
class Rows final : public NetworkSink {
 public:
  bool RecordState(double t, const double* y) override {
    times.push_back(t);
    states.emplace_back(y, y + size);
    return false;  // and Record, with the sample
  }
  void Record(double, const NetworkSample& sample) override { samples.push_back(sample); }

  std::size_t size = 0;  // the system's states
  std::vector<double> times;
  std::vector<std::vector<double>> states;
  std::vector<NetworkSample> samples;
};

bool Same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool Same(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!Same(a[i], b[i])) return false;
  }
  return true;
}

// Whether two samples hold the same bits in every field a CSV row reads.
::testing::AssertionResult SameSample(const NetworkSample& a, const NetworkSample& b) {
  if (!Same(a.position, b.position) || !Same(a.velocity, b.velocity) || !Same(a.load, b.load)) {
    return ::testing::AssertionFailure() << "the nodes differ";
  }
  if (a.elements.size() != b.elements.size() || a.controllers.size() != b.controllers.size()) {
    return ::testing::AssertionFailure() << "the parts differ";
  }
  for (std::size_t e = 0; e < a.elements.size(); ++e) {
    const ElementSample& x = a.elements[e];
    const ElementSample& y = b.elements[e];
    if (!Same({x.length, x.lengthening_rate, x.tension, x.activation, x.excitation, x.parts.passive,
               x.parts.active, x.parts.total},
              {y.length, y.lengthening_rate, y.tension, y.activation, y.excitation, y.parts.passive,
               y.parts.active, y.parts.total})) {
      return ::testing::AssertionFailure() << "element " << e << " differs";
    }
  }
  for (std::size_t c = 0; c < a.controllers.size(); ++c) {
    const ControllerSample& x = a.controllers[c];
    const ControllerSample& y = b.controllers[c];
    if (!Same({x.reference, x.measured, x.error, x.output},
              {y.reference, y.measured, y.error, y.output})) {
      return ::testing::AssertionFailure() << "controller " << c << " differs";
    }
  }
  return ::testing::AssertionSuccess();
}

struct Case {
  const char* name;
  const char* file;               // in scenarios/
  std::vector<std::string> sets;  // --set, to keep the runs short
};

class OneAdvance : public ::testing::TestWithParam<Case> {};

TEST_P(OneAdvance, IsSimulationRunToTheLastBit) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath(GetParam().file), GetParam().sets);
  const NetworkSystem system = scenario.Build();
  const NetworkRunRequest request = scenario.Request();
  const std::size_t n = static_cast<std::size_t>(system.state_size());

  Rows run;
  run.size = n;
  Simulation simulation;
  const RunStats expected = simulation.Run(system, scenario.solver, request, run);

  Rows session_rows;
  session_rows.size = n;
  Simulation fresh;
  IntegrationSession session(fresh, system, scenario.solver, request, &session_rows);
  const RunStats stats = session.AdvanceTo(request.t_end, OutputGrid::Of(request));

  EXPECT_EQ(stats.status, expected.status);
  EXPECT_EQ(stats.message, expected.message);
  EXPECT_EQ(stats.steps, expected.steps);
  EXPECT_EQ(stats.rhs_evals, expected.rhs_evals);
  EXPECT_EQ(stats.jac_evals, expected.jac_evals);
  EXPECT_EQ(stats.linear_setups, expected.linear_setups);
  EXPECT_EQ(stats.newton_iters, expected.newton_iters);
  EXPECT_EQ(stats.error_test_fails, expected.error_test_fails);
  EXPECT_EQ(stats.linear_solver, expected.linear_solver);
  EXPECT_TRUE(Same(stats.final_time, expected.final_time));
  EXPECT_EQ(session.time(), stats.final_time);
  EXPECT_EQ(session.ended(), stats.status != RunStatus::kCompleted);
  ASSERT_EQ(session_rows.times.size(), run.times.size());
  ASSERT_GT(run.times.size(), 10u);
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    ASSERT_TRUE(Same(session_rows.times[k], run.times[k])) << k;
    ASSERT_TRUE(Same(session_rows.states[k], run.states[k])) << "t = " << run.times[k];
    ASSERT_TRUE(SameSample(session_rows.samples[k], run.samples[k])) << "t = " << run.times[k];
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, OneAdvance,
    ::testing::Values(
        // steps in the inputs (restarts), limits watched, a kink at the slack length
        Case{"concentric", "concentric.yaml", {}},
        // activation dynamics: pulse edges, the kink where e = u
        Case{"twitches", "twitches.yaml", {"time.end=0.5"}},
        Case{"mass_spring_damper", "mass_spring_damper.yaml", {"time.end=0.5"}},
        // a prescribed node's ramp: breakpoints of the motion, a tendon's slack kink
        Case{"musculotendon", "musculotendon_isokinetic.yaml", {"time.end=0.3"}},
        // a controller's integral state and its clamped output
        Case{"position_tracking", "position_tracking.yaml", {"time.end=0.5"}},
        // a row per internal step
        Case{"every_step", "concentric.yaml", {"output.interval=steps", "time.end=0.2"}}),
    [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

TEST(IntegrationSession, PiecesAtSampleTimesAreTheSteppersRows) {
  // the antagonist pair stepped at 1 kHz for 50 ms, by a Stepper and by a session advanced
  // piece by piece, each piece asking for the one row at its end
  const testing::NetworkExperiment pair = testing::AntagonistPair();
  const NetworkSystem& system = pair.system;
  const std::size_t n = static_cast<std::size_t>(system.state_size());
  Stepper stepper(system, pair.options);
  Rows rows;
  rows.size = n;
  Simulation simulation;
  NetworkRunRequest start;
  start.t_start = 0.0;
  IntegrationSession session(simulation, system, pair.options, start, &rows);
  long steps = 0;
  for (int k = 1; k <= 50; ++k) {
    const double t = 1e-3 * k;
    ASSERT_EQ(stepper.Advance(t), RunStatus::kCompleted) << stepper.message();
    const RunStats piece = session.AdvanceTo(t, OutputGrid{0.0, {t}});
    ASSERT_EQ(piece.status, RunStatus::kCompleted) << piece.message;
    steps += piece.steps;
    // one row, at the piece's end, the very row the stepper holds
    ASSERT_EQ(rows.times.size(), static_cast<std::size_t>(k));
    ASSERT_EQ(rows.times.back(), t);
    EXPECT_EQ(session.time(), t);
    EXPECT_EQ(stepper.time(), t);
    ASSERT_TRUE(Same(rows.states.back(), stepper.state())) << "t = " << t;
    ASSERT_TRUE(SameSample(rows.samples.back(), stepper.sample())) << "t = " << t;
    EXPECT_EQ(steps, stepper.stats().steps) << "t = " << t;
  }
}

TEST(IntegrationSession, PiecesGoOnWithTheirHistory) {
  // 1 ms pieces of one session against a session started afresh at every piece's end, on
  // the mass-spring-damper for 0.2 s: the history kept saves the cautious first steps of
  // every restart, and both end where the one-shot run does, to the solver's tolerance
  const testing::NetworkExperiment msd = testing::MassSpringDamper();
  const NetworkSystem& system = msd.system;
  const std::size_t n = static_cast<std::size_t>(system.state_size());
  Rows kept_rows, restarted_rows;
  kept_rows.size = restarted_rows.size = n;
  Simulation kept_simulation, restarted_simulation;
  IntegrationSession kept(kept_simulation, system, msd.options, NetworkRunRequest{}, &kept_rows);
  long kept_steps = 0, restarted_steps = 0;
  for (int k = 1; k <= 200; ++k) {
    const double from = 1e-3 * (k - 1), to = 1e-3 * k;
    kept_steps += kept.AdvanceTo(to, OutputGrid{0.0, {to}}).steps;
    NetworkRunRequest start;
    start.t_start = from;
    if (k > 1) start.initial_state = restarted_rows.states.back();
    IntegrationSession piece(restarted_simulation, system, msd.options, start, &restarted_rows);
    restarted_steps += piece.AdvanceTo(to, OutputGrid{0.0, {to}}).steps;
  }
  EXPECT_LT(kept_steps, restarted_steps);

  NetworkRunRequest request = msd.request;
  request.t_end = 0.2;
  Simulation simulation;
  const NetworkRunResult one_shot = simulation.Run(system, msd.options, request);
  ASSERT_EQ(one_shot.times.back(), 0.2);
  // rtol 1e-12 and atol 1e-14 on a 0.1 m position: the runs' global errors, a few 1e-12 m,
  // and 1e-9 m leaves room for 200 pieces' worth of them
  const double x = one_shot.samples.back().position[1];
  EXPECT_NEAR(kept_rows.samples.back().position[1], x, 1e-9);
  EXPECT_NEAR(restarted_rows.samples.back().position[1], x, 1e-9);
}

TEST(IntegrationSession, EachPieceRecordsItsGridFromItsOwnStart) {
  const testing::NetworkExperiment msd = testing::MassSpringDamper();
  Rows rows;
  rows.size = static_cast<std::size_t>(msd.system.state_size());
  Simulation simulation;
  IntegrationSession session(simulation, msd.system, msd.options, NetworkRunRequest{}, &rows);
  // an interval: a row at the piece's start, every interval from there, the last at its end
  session.AdvanceTo(0.1, OutputGrid{0.03, {}});
  session.AdvanceTo(0.2, OutputGrid{0.03, {}});
  EXPECT_THAT(rows.times,
              ::testing::ElementsAre(0.0, 0.03, 2 * 0.03, 3 * 0.03, 0.1,  //
                                     0.1, 0.1 + 0.03, 0.1 + 2 * 0.03, 0.1 + 3 * 0.03, 0.2));
  // listed times: these rows only, the piece's start among them only if listed
  rows.times.clear();
  session.AdvanceTo(0.3, OutputGrid{0.0, {0.25, 0.3}});
  session.AdvanceTo(0.4, OutputGrid{0.0, {0.3, 0.35, 0.4}});
  EXPECT_THAT(rows.times, ::testing::ElementsAre(0.25, 0.3, 0.3, 0.35, 0.4));
  // the rows at a piece's end and at the next one's start are the same state
  const std::size_t end = rows.states.size() - 4, next = end + 1;
  EXPECT_TRUE(Same(rows.states[end], rows.states[next]));
}

// x(t) of the mass-spring-damper released at rest at the spring's rest length: the
// underdamped closed form about the equilibrium 0.12 m, as network_simulation_test has it.
double MsdPosition(double t) {
  const double w = std::sqrt(testing::kMsdStiffness / testing::kMsdMass);
  const double zeta =
      testing::kMsdDamping / (2.0 * std::sqrt(testing::kMsdStiffness * testing::kMsdMass));
  const double wd = w * std::sqrt(1.0 - zeta * zeta);
  const double equilibrium = testing::kMsdRestLength + testing::kMsdLoad / testing::kMsdStiffness;
  const double amplitude = testing::kMsdStart - equilibrium;
  return equilibrium +
         amplitude * std::exp(-zeta * w * t) *
             (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
}

TEST(IntegrationSession, ALimitEndsItWhereTheClosedFormReachesIt) {
  const testing::NetworkExperiment msd = testing::MassSpringDamper();
  NetworkRunRequest start;
  start.limits = {{"spring", std::nullopt, 0.11}};
  Rows rows;
  rows.size = static_cast<std::size_t>(msd.system.state_size());
  Simulation simulation;
  IntegrationSession session(simulation, msd.system, msd.options, start, &rows);
  EXPECT_FALSE(session.ended());
  const RunStats stats = session.AdvanceTo(2.0, OutputGrid{1e-3, {}});
  EXPECT_EQ(stats.status, RunStatus::kLimit);
  EXPECT_TRUE(session.ended());
  // the first time x = 0.11 m, by bisection of the closed form on the rise (t < pi / w)
  double lo = 0.0, hi = 0.3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (MsdPosition(mid) < 0.11 ? lo : hi) = mid;
  }
  // CVODE's root is found to a few ulps of t times the step's scale; at rtol 1e-12 the
  // trajectory itself is right to ~1e-12 m, which at 0.1 m/s is 1e-11 s: 1e-9 s is ample
  EXPECT_NEAR(session.time(), lo, 1e-9);
  EXPECT_EQ(stats.final_time, session.time());
  EXPECT_EQ(rows.times.back(), session.time());  // the row where it ended
  EXPECT_NEAR(rows.samples.back().elements[0].length, 0.11, 1e-12);
  EXPECT_THROW(session.AdvanceTo(3.0, OutputGrid{1e-3, {}}), std::logic_error);
}

TEST(IntegrationSession, RefusesAPieceThatDoesNotMoveOnAndBadOptions) {
  const testing::NetworkExperiment msd = testing::MassSpringDamper();
  Rows rows;
  rows.size = static_cast<std::size_t>(msd.system.state_size());
  Simulation simulation;
  IntegrationSession session(simulation, msd.system, msd.options, NetworkRunRequest{}, &rows);
  session.AdvanceTo(0.1, OutputGrid{0.01, {}});
  EXPECT_THROW(session.AdvanceTo(0.1, OutputGrid{0.01, {}}), ParameterError);
  EXPECT_THROW(session.AdvanceTo(0.05, OutputGrid{0.01, {}}), ParameterError);
  EXPECT_THROW(session.AdvanceTo(std::nan(""), OutputGrid{0.01, {}}), ParameterError);
  EXPECT_FALSE(session.ended());
  EXPECT_EQ(session.AdvanceTo(0.2, OutputGrid{0.01, {}}).status, RunStatus::kCompleted);

  SolverOptions bad = msd.options;
  bad.rtol = 0.0;
  Simulation other;
  EXPECT_THROW(IntegrationSession(other, msd.system, bad, NetworkRunRequest{}, &rows),
               ParameterError);
  NetworkRunRequest short_state;
  short_state.initial_state = {0.1};  // the system has two states
  EXPECT_THROW(IntegrationSession(other, msd.system, msd.options, short_state, &rows),
               ParameterError);
}

}  // namespace
}  // namespace musclesim
