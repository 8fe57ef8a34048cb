// Runs that cannot finish end promptly and say why (solver/stall_watch.h, stiffness_note.h):
// a force controller at its largest gain chatters between the activation's bounds, and a
// tension-velocity curve that is nearly a step (epsilon 1e-12 with n = 50) on a mass of a
// microgram leaves CVODE no step it can take. Before, the first spent max_steps (ten million
// steps, tens of seconds) and the second named only CVODE's flag.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/solver/simulation.h"
#include "support/control_networks.h"
#include "solver/stiffness_note.h"
#include "support/canonical_networks.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

bool Says(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

TEST(StalledRun, AControllerChatteringBetweenTheBoundsIsNamedWithinAFewWindows) {
  const testing::NetworkExperiment regulation = testing::ForceRegulation();
  std::vector<Controller> controllers = regulation.system.controllers();
  controllers[0].gains.kp = kMaxGain;  // the documented limit
  const NetworkSystem system(regulation.system.nodes(), regulation.system.elements(),
                             regulation.system.loads(), controllers);
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, regulation.options, regulation.request);
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  // a few windows of 65536 steps, not max_steps (1e7)
  EXPECT_LT(run.stats.steps, 10 * 65536);
  const std::string& message = run.stats.message;
  EXPECT_TRUE(Says(message, "the integration stalled at t = ")) << message;
  EXPECT_TRUE(Says(message, "controller force drove muscle across its bound")) << message;
  EXPECT_TRUE(Says(message, "kp = 1e+09")) << message;
  // the rows before the stall are kept
  ASSERT_FALSE(run.times.empty());
  EXPECT_LE(run.times.back(), run.stats.final_time);
}

TEST(StalledRun, ATensionVelocityCurveNearAStepIsNamedAsTheStiffestPart) {
  for (const char* file : {"concentric.yaml", "eccentric.yaml"}) {
    const Scenario scenario =
        LoadScenario(testing::ScenarioPath(file),
                     {"model.velocity.epsilon=1e-12", "model.velocity.n=50", "actuator.mass=1e-9"});
    Simulation simulation;
    const NetworkRunResult run =
        simulation.Run(scenario.Build(), scenario.solver, scenario.Request());
    EXPECT_EQ(run.stats.status, RunStatus::kFailed) << file;
    const std::string& message = run.stats.message;
    EXPECT_TRUE(Says(message, "the stiffest part at t = ")) << message;
    EXPECT_TRUE(Says(message, "node tip")) << message;
    EXPECT_TRUE(Says(message, "from actuator, whose tension changes by")) << message;
    EXPECT_TRUE(Says(message, "velocity.epsilon")) << message;
  }
}

// The note names the stiffest part only when its time scale is near the step CVODE was cut
// to; far above it, stiffness explains nothing and the note says so rather than blaming the
// fastest element. The mass-spring-damper's rates are sqrt(k / m) = 10 1/s and c / m = 1 1/s.
TEST(StalledRun, StiffnessThatDoesNotExplainTheStepIsNotBlamed) {
  const testing::NetworkExperiment msd = testing::MassSpringDamper(0.5);
  std::vector<double> y(static_cast<std::size_t>(msd.system.state_size()));
  msd.system.InitialState(0.0, y.data());
  const std::string tiny_step = StiffnessNote(msd.system, 0.0, y.data(), 1e-12);
  EXPECT_TRUE(Says(tiny_step, "no rate of the system explains steps this short")) << tiny_step;
  EXPECT_TRUE(Says(tiny_step, "node load, a time scale of 0.1 s")) << tiny_step;
  const std::string near_step = StiffnessNote(msd.system, 0.0, y.data(), 0.01);
  EXPECT_TRUE(Says(near_step, "the stiffest part at t = 0 s: node load, rate 10 1/s")) << near_step;
}

}  // namespace
}  // namespace musclesim
