// Forward sensitivities to the parameters of a network's elements (difference quotients of
// the rebuilt scenario's right-hand side) against finite differences of full runs
// (support/sensitivity_reference.h): one test per element kind.
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::ExpectSensitivitiesMatchDifferences;

// Every kind of element in one network: an actuator (the canonical curves with eps =
// 1e-2 m/s and an asymmetric velocity curve, activation 0.3) from a wall to a 0.02 kg
// junction with a spring in parallel; from the junction to a 0.1 kg tip a linear tendon and
// an exponential one (a sheath) side by side; a damper from the wall to the tip. A 15 +- 30 N,
// 4 Hz load on the tip: the muscle's velocity changes sign (at 0.034 s and 0.118 s), the
// sheath goes slack at 0.142 s and the tendon at 0.185 s.
//
// Both sides at rtol 1e-12, atol 1e-14 (lengths ~0.1 m): the reference's share of the
// integrator's error, ~ rtol |C| / h, stays below 1e-6 of a column's derivative. Rows every
// 25 ms lie 7 ms or more from those crossings, so that the reference's smaller steps move no
// kink across a row (there a column is not differentiable in p).
constexpr const char* kNetwork = R"(name: element_sensitivities
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians:
        - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
        - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
        - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2, eccentric: {v_max: 0.5, n: 2, limit: 1.8}}
nodes:
  - {name: wall, fixed: 0.0}
  - {name: junction, mass: 0.02, position: 0.1, velocity: 0.0}
  - {name: tip, mass: 0.1, position: 0.305, velocity: 0.0}
elements:
  - {name: muscle, type: actuator, from: wall, to: junction, model: muscle, activation: {type: constant, value: 0.3}}
  - {name: parallel, type: spring, from: wall, to: junction, stiffness: 200.0, rest_length: 0.1}
  - {name: tendon, type: tendon, from: junction, to: tip, slack_length: 0.195, stiffness: 3000.0}
  - {name: sheath, type: tendon, from: junction, to: tip, slack_length: 0.2, exponential: {k: 5.0, alpha: 50.0}}
  - {name: damper, type: damper, from: wall, to: tip, damping: 20.0}
loads:
  - {node: tip, type: sine, offset: 15.0, amplitude: 30.0, frequency: 4.0, phase: -0.2}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: elements.csv, interval: 0.025}
)";

std::string Network() { return testing::WriteTempFile("network.yaml", kNetwork); }

TEST(SensitivityElements, ActuatorActivation) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[0].activation.value", 0.3)});
}

TEST(SensitivityElements, Spring) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {}, {At("elements[1].stiffness", 200.0), At("elements[1].rest_length", 0.1)});
}

TEST(SensitivityElements, LinearTendonStiffness) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[2].stiffness", 3000.0)});
}

// The tendon goes slack during the run: df/dp jumps from -k/m to 0 there. Its closed form
// is evaluated on the base system's side of the kink, where the integrator restarts (a
// difference quotient of the scenario rebuilt at l_s +- h would spread the jump over +-h and
// leave the sensitivities off by 2e-5 of their scale past it).
TEST(SensitivityElements, LinearTendonSlackLengthAcrossTheSlackLength) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[2].slack_length", 0.195)});
}

TEST(SensitivityElements, ExponentialTendonAcrossItsSlackLength) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {},
      {At("elements[3].exponential.k", 5.0), At("elements[3].exponential.alpha", 50.0),
       At("elements[3].slack_length", 0.2)});
}

TEST(SensitivityElements, Damper) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[4].damping", 20.0)});
}

TEST(SensitivityElements, NodeMasses) {
  ExpectSensitivitiesMatchDifferences(Network(), {},
                                      {At("nodes[1].mass", 0.02), At("nodes[2].mass", 0.1)});
}

}  // namespace
}  // namespace musclesim
