// Forward sensitivities to the initial state (dy0/dp, the sensitivities' starting values) and
// to the actuator, activation dynamics and excitation (difference quotients of the rebuilt
// scenario), against finite differences of full runs (support/sensitivity_reference.h); in a
// single actuator with activation dynamics and in a network.
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::Differentiated;
using testing::ExpectSensitivitiesMatchDifferences;

constexpr const char* kModelBlock = R"(  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians:
      - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
      - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
      - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2, eccentric: {v_max: 0.5, n: 2, limit: 1.8}}
)";

// The canonical curves (eps = 1e-2 m/s, an asymmetric velocity curve) driven through
// activation dynamics by a 0.5 +- 0.4, 5 Hz excitation, from u = 0.3, against a constant
// 45 N, with a parallel spring (50 N/m) and no damper, lengthening at 0.02 m/s at the start
// (not at rest: v = 0 is a kink of the asymmetric curve, where the tension has no
// derivative in the initial rate). The activation meets the excitation
// at 0.070 s and 0.181 s (kinks of udot), the velocity changes sign at 0.012 s, 0.131 s and
// 0.211 s, and the length passes the slack length at 0.190 s: rows every 25 ms are 5 ms or
// more from each. Both sides at rtol 1e-12, atol 1e-14.
std::string SingleActuator() {
  return testing::WriteTempFile(
      "single.yaml", std::string("name: initial_sensitivities\nmodel:\n") + kModelBlock + R"(
actuator: {mass: 0.1, damping: 0.0, stiffness: 50.0, rest_length: 0.1}
initial: {length: 0.1, lengthening_rate: 0.02, activation: 0.3}
excitation: {type: sine, offset: 0.5, amplitude: 0.4, frequency: 5.0, phase: 0.0}
activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}
load: {type: constant, value: 45.0}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: single.csv, interval: 0.025}
)");
}

// Two actuators of one model on either side of a 0.1 kg mass that starts moving at
// 0.05 m/s: the flexor through activation dynamics from u = 0.4, excited by 40 ms pulses
// from 0.1 to 0.7 every 100 ms (breakpoints, where the run restarts), the extensor at a
// constant 0.4. The mass turns at 0.036, 0.094, 0.136, 0.194 and 0.236 s, 5.5 ms or more from
// rows every 25 ms. Both sides at rtol 1e-12, atol 1e-14.
std::string Network() {
  std::string indented;
  const std::string model = kModelBlock;
  for (std::size_t at = 0; at < model.size();) {
    const std::size_t end = model.find('\n', at);
    indented += "  " + model.substr(at, end - at + 1);
    at = end + 1;
  }
  return testing::WriteTempFile(
      "network.yaml", "name: network_initial_sensitivities\nmodels:\n  muscle:\n" + indented + R"(
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1036, velocity: 0.05}
  - {name: wall_b, fixed: 0.2072}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle, excitation: {type: pulses, start: 0.03, period: 0.1, width: 0.04, low: 0.1, high: 0.7}, activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}, initial_activation: 0.4}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle, activation: {type: constant, value: 0.4}}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: network.csv, interval: 0.025}
)");
}

TEST(SensitivityInitialState, SingleActuatorLengthAndRate) {
  ExpectSensitivitiesMatchDifferences(
      SingleActuator(), {}, {At("initial.length", 0.1), At("initial.lengthening_rate", 0.02)});
}

TEST(SensitivityInitialState, SingleActuatorActivation) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, {At("initial.activation", 0.3)});
}

TEST(SensitivityInitialState, NetworkNodePositionAndVelocity) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {}, {At("nodes[1].position", 0.1036), At("nodes[1].velocity", 0.05)});
}

TEST(SensitivityInitialState, NetworkInitialActivation) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[0].initial_activation", 0.4)});
}

TEST(SensitivityActuator, MassSpringAndRestLength) {
  ExpectSensitivitiesMatchDifferences(
      SingleActuator(), {},
      {At("actuator.mass", 0.1), At("actuator.stiffness", 50.0), At("actuator.rest_length", 0.1)});
}

TEST(SensitivityActuator, DampingAtItsBoundOfZero) {
  // a damping cannot go below 0: the reference's quotient is one-sided there, its steps
  // relative to 1 N s/m (next to the muscle's own ~1e3 N s/m near rest); the library's df/dp
  // is the damper element's closed form, which a bound does not affect
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {},
                                      {Differentiated{"actuator.damping", 0.0, 1.0, true}});
}

TEST(SensitivityActivationDynamics, SingleActuatorTimeConstants) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {},
                                      {At("activation_dynamics.tau_activation", 0.015),
                                       At("activation_dynamics.tau_deactivation", 0.05)});
}

TEST(SensitivityActivationDynamics, SingleActuatorExcitationLevels) {
  ExpectSensitivitiesMatchDifferences(
      SingleActuator(), {}, {At("excitation.offset", 0.5), At("excitation.amplitude", 0.4)});
}

TEST(SensitivityActivationDynamics, NetworkTimeConstants) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {},
      {At("elements[0].activation_dynamics.tau_activation", 0.015),
       At("elements[0].activation_dynamics.tau_deactivation", 0.05)});
}

TEST(SensitivityActivationDynamics, NetworkPulseLevels) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {},
      {At("elements[0].excitation.low", 0.1), At("elements[0].excitation.high", 0.7)});
}

}  // namespace
}  // namespace musclesim
