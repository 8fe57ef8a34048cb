// Forward sensitivities of networks in the plane and in space (docs/model.md 10 with 12)
// against finite differences of full runs (support/sensitivity_reference.h): every node
// coordinate and its rate, every element's path length and tension (an actuator's parts and
// activation too), at every row, for parameters that enter each way: an element's and a
// tension model's coefficients (closed forms carried along the path's gradient), an
// activation, the initial state's coordinates, gravity, a directed load, a fixed node's
// coordinate and a mass (difference quotients of the rebuilt scenario's right-hand side).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::ExpectSensitivitiesMatchDifferences;

constexpr const char* kModel = R"(models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 30.0, slack_length: 0.05}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians:
        - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
        - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
        - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2}
)";

// In the plane, under gravity: an actuator (activation 0.3) from a wall over a fixed via point
// and over a free 0.02 kg slider, which a spring holds to an anchor, to a free 0.1 kg tip; a
// spring from the tip to a node beyond it, moved up and down, and a damper from the anchor to
// the tip; a
// 10 +- 10 N, 4 Hz load on the tip along (1, -0.5). No segment of the muscle's path gets
// shorter than 3 cm (a closing one would end a reference's run early); the path stays longer
// than its passive slack length (0.05 m) and the velocity curve is symmetric: no kink in the
// run. Both sides at rtol 1e-12, atol 1e-14; rows every 20 ms over 0.12 s.
constexpr const char* kPlane = R"(name: planar_sensitivities
dimensions: 2
gravity: [0.0, -9.81]
nodes:
  - {name: wall, fixed: [0.0, 0.0]}
  - {name: anchor, fixed: [0.08, 0.06]}
  - {name: slider, mass: 0.02, position: [0.06, 0.02], velocity: [0.0, 0.0]}
  - {name: tip, mass: 0.1, position: [0.09, -0.01], velocity: [0.05, 0.0]}
  - {name: far, prescribed: [{type: constant, value: 0.2}, {type: sine, offset: -0.04, amplitude: 0.005, frequency: 3.0}]}
elements:
  - {name: muscle, type: actuator, from: wall, to: tip, model: muscle, via: [[0.03, 0.025], slider], activation: {type: constant, value: 0.3}}
  - {name: holder, type: spring, from: anchor, to: slider, stiffness: 2000.0, rest_length: 0.035}
  - {name: spring, type: spring, from: tip, to: far, stiffness: 1000.0, rest_length: 0.08}
  - {name: damper, type: damper, from: anchor, to: tip, damping: 5.0}
loads:
  - {node: tip, type: sine, offset: 10.0, amplitude: 10.0, frequency: 4.0, phase: 0.0, direction: [1.0, -0.5]}
time: {start: 0.0, end: 0.12}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: plane.csv, interval: 0.02}
)";

// In space, under a slanted gravity: the actuator through activation dynamics (excitation 0.6
// from an activation of 0.2, which rises towards it without reaching it: no kink e = u) from
// a wall over a fixed via point and a free 0.03 kg pulley, which an exponential tendon holds
// to a hook (taut throughout), to a free 0.1 kg tip; a stiff spring from the tip to a fixed
// node beyond it, a damper from the hook and a spring load along (0, 1, 1). No segment gets
// shorter than 3 cm.
constexpr const char* kSpace = R"(name: spatial_sensitivities
dimensions: 3
gravity: [0.3, 0.0, -9.81]
nodes:
  - {name: wall, fixed: [0.0, 0.0, 0.0]}
  - {name: hook, fixed: [0.071, 0.072, 0.031]}
  - {name: pulley, mass: 0.03, position: [0.06, 0.04, 0.01], velocity: [0.0, 0.0, 0.0]}
  - {name: tip, mass: 0.1, position: [0.09, 0.0, -0.01], velocity: [0.02, 0.0, -0.03]}
  - {name: far, fixed: [0.146, -0.074, -0.047]}
elements:
  - {name: muscle, type: actuator, from: wall, to: tip, model: muscle, via: [[0.03, 0.03, 0.0], pulley], excitation: {type: constant, value: 0.6}, activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}, initial_activation: 0.2}
  - {name: holder, type: tendon, from: hook, to: pulley, slack_length: 0.01, exponential: {k: 20.0, alpha: 50.0}}
  - {name: spring, type: spring, from: tip, to: far, stiffness: 3000.0, rest_length: 0.09}
  - {name: damper, type: damper, from: hook, to: tip, damping: 20.0}
loads:
  - {node: tip, type: spring, stiffness: 100.0, anchor: 0.0, direction: [0.0, 1.0, 1.0]}
time: {start: 0.0, end: 0.12}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: space.csv, interval: 0.02}
)";

std::string Plane() { return testing::WriteTempFile("plane.yaml", std::string(kPlane) + kModel); }
std::string Space() { return testing::WriteTempFile("space.yaml", std::string(kSpace) + kModel); }

// The differentiated columns are named as the run's: a free node's coordinates, then their
// rates; then every element's as on a line.
TEST(SpatialSensitivity, ColumnsFollowTheRunsNodeColumns) {
  const SensitivityTable plane =
      RunWithSensitivities(LoadScenario(Plane(), {}), {"elements[2].stiffness"});
  const std::vector<std::string> planar = {"slider.x",
                                           "slider.y",
                                           "slider.vx",
                                           "slider.vy",
                                           "tip.x",
                                           "tip.y",
                                           "tip.vx",
                                           "tip.vy",
                                           "muscle.length",
                                           "muscle.tension",
                                           "muscle.tension_passive",
                                           "muscle.tension_active",
                                           "holder.length",
                                           "holder.tension",
                                           "spring.length",
                                           "spring.tension",
                                           "damper.length",
                                           "damper.tension"};
  EXPECT_EQ(plane.columns, planar);
  const SensitivityTable space =
      RunWithSensitivities(LoadScenario(Space(), {}), {"elements[2].stiffness"});
  ASSERT_GE(space.columns.size(), 14u);
  const std::vector<std::string> nodes(space.columns.begin(), space.columns.begin() + 12);
  EXPECT_EQ(nodes, (std::vector<std::string>{"pulley.x", "pulley.y", "pulley.z", "pulley.vx",
                                             "pulley.vy", "pulley.vz", "tip.x", "tip.y", "tip.z",
                                             "tip.vx", "tip.vy", "tip.vz"}));
  EXPECT_EQ(space.columns[14], "muscle.activation");
}

TEST(SpatialSensitivity, PlaneElementCoefficients) {
  ExpectSensitivitiesMatchDifferences(
      Plane(), {},
      {At("elements[1].stiffness", 2000.0), At("elements[2].rest_length", 0.08),
       At("elements[3].damping", 5.0)});
}

TEST(SpatialSensitivity, PlaneModelAndActivation) {
  ExpectSensitivitiesMatchDifferences(
      Plane(), {},
      {At("models.muscle.f_iso", 100.0), At("models.muscle.velocity.v_max", 1.0),
       At("elements[0].activation.value", 0.3)});
}

TEST(SpatialSensitivity, PlaneInitialCoordinates) {
  ExpectSensitivitiesMatchDifferences(
      Plane(), {},
      {At("nodes[3].position[1]", -0.01), At("nodes[2].position[0]", 0.06),
       At("nodes[3].velocity[0]", 0.05)});
}

TEST(SpatialSensitivity, PlaneGravityLoadFixedAndPrescribedNodesAndMass) {
  ExpectSensitivitiesMatchDifferences(
      Plane(), {},
      {At("gravity[1]", -9.81), At("loads[0].offset", 10.0), At("nodes[1].fixed[0]", 0.08),
       At("nodes[3].mass", 0.1), At("nodes[4].prescribed[1].amplitude", 0.005)});
}

TEST(SpatialSensitivity, SpaceElementCoefficients) {
  ExpectSensitivitiesMatchDifferences(
      Space(), {},
      {At("elements[1].exponential.k", 20.0), At("elements[1].slack_length", 0.01),
       At("elements[2].stiffness", 3000.0), At("elements[3].damping", 20.0)});
}

TEST(SpatialSensitivity, SpaceModelAndActivationDynamics) {
  ExpectSensitivitiesMatchDifferences(
      Space(), {},
      {At("models.muscle.f_iso", 100.0), At("models.muscle.passive.k_p", 1.0),
       At("elements[0].activation_dynamics.tau_activation", 0.015),
       At("elements[0].initial_activation", 0.2)});
}

TEST(SpatialSensitivity, SpaceInitialCoordinates) {
  ExpectSensitivitiesMatchDifferences(
      Space(), {},
      {At("nodes[3].position[2]", -0.01), At("nodes[2].position[1]", 0.04),
       At("nodes[3].velocity[2]", -0.03)});
}

TEST(SpatialSensitivity, SpaceGravityLoadAndFixedNode) {
  ExpectSensitivitiesMatchDifferences(
      Space(), {},
      {At("gravity[0]", 0.3), At("gravity[2]", -9.81), At("loads[0].stiffness", 100.0),
       At("nodes[1].fixed[2]", 0.031)});
}

}  // namespace
}  // namespace musclesim
