// Forward sensitivities to the values of the loads (difference quotients of the rebuilt
// scenario's right-hand side) against finite differences of full runs
// (support/sensitivity_reference.h): one test per load kind the scenario reader accepts
// (io/readers/scenario_fields.cc ReadLoad: constant, step, ramp, sine, pulses, table, spring,
// mass), each differentiated by its values, not by its times; in a single actuator and on a
// network's node.
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::ExpectSensitivitiesMatchDifferences;

// One load of every kind on the half-active canonical actuator (eps = 1e-2 m/s), summed to
// 28 N at the start against its 50 N: it shortens throughout (0.1 m to 0.095 m, never at
// rest, below the slack length), so no kink lies near a row. The step, the ramp's ends, the
// pulses' edges and the table's points are breakpoints where the integrator restarts with
// the sensitivities carried over: 12 of them in 0.25 s. Both sides at rtol 1e-12, atol 1e-14;
// rows every 25 ms.
constexpr const char* kScenario = R"(name: load_sensitivities
model:
  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians:
      - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
      - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
      - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2, eccentric: {v_max: 0.5, n: 2, limit: 1.8}}
actuator: {mass: 0.1}
initial: {length: 0.1}
activation: {type: constant, value: 0.5}
load:
  - {type: constant, value: 10.0}
  - {type: step, time: 0.1, before: 2.0, after: 8.0}
  - {type: ramp, start: 0.05, end: 0.15, from: 1.0, to: 6.0}
  - {type: sine, offset: 5.0, amplitude: 10.0, frequency: 4.0, phase: 0.2}
  - {type: pulses, start: 0.02, period: 0.08, width: 0.03, low: 1.0, high: 6.0}
  - {type: table, points: [[0.0, 2.0], [0.1, 8.0], [0.2, 3.0]]}
  - {type: spring, stiffness: 500.0, anchor: 0.1}
  - {type: mass, mass: 0.5, gravity: 9.81}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: loads.csv, interval: 0.025}
)";

std::string Scenario() { return testing::WriteTempFile("loads.yaml", kScenario); }

TEST(SensitivityLoads, Constant) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {}, {At("load[0].value", 10.0)});
}

TEST(SensitivityLoads, StepLevels) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[1].before", 2.0), At("load[1].after", 8.0)});
}

TEST(SensitivityLoads, RampLevels) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[2].from", 1.0), At("load[2].to", 6.0)});
}

TEST(SensitivityLoads, Sine) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[3].offset", 5.0), At("load[3].amplitude", 10.0),
                                       At("load[3].frequency", 4.0), At("load[3].phase", 0.2)});
}

TEST(SensitivityLoads, PulseLevels) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[4].low", 1.0), At("load[4].high", 6.0)});
}

TEST(SensitivityLoads, TableValues) {
  ExpectSensitivitiesMatchDifferences(
      Scenario(), {},
      {At("load[5].points[0][1]", 2.0), At("load[5].points[1][1]", 8.0),
       At("load[5].points[2][1]", 3.0)});
}

TEST(SensitivityLoads, Spring) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[6].stiffness", 500.0), At("load[6].anchor", 0.1)});
}

TEST(SensitivityLoads, Mass) {
  ExpectSensitivitiesMatchDifferences(Scenario(), {},
                                      {At("load[7].mass", 0.5), At("load[7].gravity", 9.81)});
}

// The same loads on a network's node: two of them (a sine and a hanging mass) on the free
// end of a spring and damper, the reader and the stencil being the network's own.
constexpr const char* kNetwork = R"(name: network_load_sensitivities
nodes:
  - {name: wall, fixed: 0.0}
  - {name: load, mass: 0.5, position: 0.1, velocity: 0.0}
elements:
  - {name: spring, type: spring, from: wall, to: load, stiffness: 50.0, rest_length: 0.1}
  - {name: damper, type: damper, from: wall, to: load, damping: 2.0}
loads:
  - {node: load, type: sine, offset: 1.0, amplitude: 2.0, frequency: 2.0, phase: 0.0}
  - {node: load, type: mass, mass: 0.2, gravity: 9.81}
time: {start: 0.0, end: 0.5}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: network_loads.csv, interval: 0.05}
)";

TEST(SensitivityLoads, OnANetworkNode) {
  ExpectSensitivitiesMatchDifferences(
      testing::WriteTempFile("network.yaml", kNetwork), {},
      {At("loads[0].offset", 1.0), At("loads[0].amplitude", 2.0), At("loads[1].mass", 0.2)});
}

}  // namespace
}  // namespace musclesim
