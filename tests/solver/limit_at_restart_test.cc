// A limit reached exactly where the integration restarts: at an input's breakpoint, or at the
// end of a Stepper's piece. The last step reads the inputs a few ulps before that time and the
// restart a few ulps after it, so the crossing lies between two steps rather than in one; the
// run must still end there. The muscle's length is prescribed (a ramp from the wall), the
// network has no free node, and the time it reaches a length is known in closed form.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <utility>
#include <vector>

#include "musclesim/solver/simulation.h"
#include "musclesim/solver/stepper.h"
#include "support/canonical_networks.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr ActivationDynamics kDynamics{0.015, 0.05};

// `muscle` from a wall at 0 to `end`, moved by `motion`; its excitation drives its activation,
// the system's only state.
NetworkSystem Prescribed(Waveform motion, Waveform excitation) {
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Prescribed("end", std::move(motion))},
      {Element::Actuator("muscle", "wall", "end",
                         std::make_shared<const TensionModel>(testing::AntagonistModel()),
                         ExcitationInput{std::move(excitation), kDynamics, 0.0})});
}

// 0.11 + 0.05 t m: 0.12 m at t = 0.2 s
Waveform Stretch() { return Waveform::Ramp(-1.0, 1.0, 0.06, 0.16); }
// an excitation whose breakpoints are at 0.2 s and 0.21 s
Waveform Drop() { return Waveform::Table({{0.0, 0.9}, {0.2, 0.9}, {0.21, 0.1}, {0.5, 0.1}}); }

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-12;
  return options;
}

LengthLimit MaxLength(double level) {
  LengthLimit limit;
  limit.element = "muscle";
  limit.max_length = level;
  return limit;
}

TEST(LimitAtRestart, AMaxLengthReachedAtAnInputsBreakpointEndsTheRun) {
  NetworkRunRequest request;
  request.t_end = 0.5;
  request.output_interval = 0.005;
  request.limits = {MaxLength(0.12)};
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(Prescribed(Stretch(), Drop()), Tight(), request);
  EXPECT_EQ(run.stats.status, RunStatus::kLimit) << run.stats.message;
  EXPECT_THAT(run.stats.message, HasSubstr("max_length = 0.12 reached by muscle"));
  EXPECT_NEAR(run.stats.final_time, 0.2, 1e-12);
  ASSERT_FALSE(run.times.empty());
  EXPECT_NEAR(run.samples.back().elements[0].length, 0.12, 1e-12);
  // one row per time: the breakpoint's grid row is the limit's
  for (std::size_t k = 1; k < run.times.size(); ++k) EXPECT_LT(run.times[k - 1], run.times[k]);
}

TEST(LimitAtRestart, ALengthReachingZeroAtABreakpointIsAFailure) {
  // the end reaches the wall at 0.25 s, a point of its table, and goes on past it
  NetworkRunRequest request;
  request.t_end = 0.5;
  request.output_interval = 0.005;
  Simulation simulation;
  const NetworkRunResult run =
      simulation.Run(Prescribed(Waveform::Table({{0.0, 0.1}, {0.25, 0.0}, {0.5, -0.05}}), Drop()),
                     Tight(), request);
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("the length of muscle reached zero at t = 0.25"));
  EXPECT_NEAR(run.stats.final_time, 0.25, 1e-12);
}

TEST(LimitAtRestart, AStepperPieceEndingWhereALimitIsReachedStopsThere) {
  // no breakpoint: the pieces of 0.05 s end at 0.2 s, where the length reaches 0.12 m
  StepperStart start;
  start.limits = {MaxLength(0.12)};
  Stepper stepper(Prescribed(Stretch(), Waveform::Constant(0.5)), Tight(), start);
  RunStatus status = RunStatus::kCompleted;
  for (int k = 1; k <= 10 && status == RunStatus::kCompleted; ++k)
    status = stepper.Advance(0.05 * k);
  EXPECT_EQ(status, RunStatus::kLimit) << stepper.message();
  EXPECT_NEAR(stepper.time(), 0.2, 1e-12);
  EXPECT_NEAR(stepper.sample().elements[0].length, 0.12, 1e-12);
}

}  // namespace
}  // namespace musclesim
