// The test problems' network: an actuator whose tension is f_iso u (its curves flat over the
// travel) on a 0.1 kg mass against a constant 20 N load (docs/model.md 13.3).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim::optimize_test {

constexpr double kMass = 0.1, kTravel = 0.02, kSpan = 0.1, kLoad = 20.0, kForce = 100.0;
constexpr double kStart = 0.1;  // the mass's start [m]: the actuator's length

// f_L = 1 within 1e-8 over the travel (one Gaussian of width factor 1e-4 1/m^2), g = 1 within
// 1e-7 (n = 1, v_max = 1e7 m/s), no passive tension: T = f_iso u.
// `drive`: the actuator's activation, or with activation dynamics its excitation and time
// constants (the keys of a network's actuator).
inline Scenario FlatActuatorOnALoad(
    const std::string& drive = "activation: {type: constant, value: 0.2}") {
  // a file of this test's own (ctest runs tests in parallel processes): its name, '/' replaced
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(test->test_suite_name()) + "_" + test->name();
  std::replace(name.begin(), name.end(), '/', '_');
  const std::string path = ::testing::TempDir() + name + "_analytic_optimum.yaml";
  std::ofstream(path) << R"(name: analytic_optimum
models:
  flat:
    f_iso: 100.0
    passive: {k_p: 0.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians: [{amplitude: 1.0, width: 1.0e-4, center: 0.09}]
    velocity: {v_max: 1.0e7, n: 1, epsilon: 1.0e-3}
nodes:
  - {name: anchor, fixed: 0.0}
  - {name: mass, mass: 0.1, position: 0.1, velocity: 0.0}
elements:
  - {name: muscle, type: actuator, from: anchor, to: mass, model: flat,
     )" + drive + R"(}
loads:
  - {node: mass, type: constant, value: 20.0}
time: {start: 0.0, end: 0.1}
solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14, jacobian: analytic, linear_solver: auto}
output: {file: analytic_optimum.csv, interval: 0.001}
)";
  return LoadScenario(path);
}

}  // namespace musclesim::optimize_test
