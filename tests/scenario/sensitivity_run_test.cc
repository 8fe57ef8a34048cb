// RunWithSensitivities as data (scenario/sensitivity_run.h): rows exactly at listed output
// times, with the derivatives there against finite differences of full runs; what the table
// says about its parameters; and each refusal, an InputError naming who asked, the path and
// the rule.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
using ::testing::HasSubstr;
using testing::RunFileWithSensitivities;

// A concentric contraction without kinks: the symmetric velocity curve (no eccentric block,
// so v = 0 is no kink), the length below the slack length throughout; the activation steps
// from 0.3 to 0.6 at 0.05 s (a breakpoint) under a 25 N load. Both sides at rtol 1e-12,
// atol 1e-14.
constexpr const char* kSingle = R"(name: output_times
model:
  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians:
      - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
      - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2}
actuator: {mass: 0.1, damping: 2.0}
initial: {length: 0.1}
activation: {type: step, time: 0.05, before: 0.3, after: 0.6}
load:
  - {type: constant, value: 25.0}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: output_times.csv, interval: 0.02}
)";

// Two co-contracted actuators holding a mass released 1 mm off the midpoint, where their
// tensions cancel: it creeps back (their tension-velocity curves, linear here, damp it),
// both lengths within 1 mm of 0.1 m, below the slack length.
constexpr const char* kNetwork = R"(name: network_output_times
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.102}]
    velocity: {v_max: 1.0, n: 1, epsilon: 1.0e-2}
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.101, velocity: 0.0}
  - {name: wall_b, fixed: 0.2}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle, activation: {type: constant, value: 0.5}}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle, activation: {type: constant, value: 0.5}}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: network_output_times.csv, interval: 0.02}
)";

std::string Single() { return testing::WriteTempFile("single.yaml", kSingle); }
std::string Network() { return testing::WriteTempFile("network.yaml", kNetwork); }

// Off the grid, one exactly at the breakpoint, the last at time.end; t_start not listed.
const std::vector<double> kListed = {0.0123, 0.05, 0.0777, 0.13, 0.2};

TEST(SensitivityOutputTimes, RowsExactlyAtTheListedTimes) {
  const SensitivityTable single =
      RunWithSensitivities(LoadScenario(Single()), {"model.f_iso"}, kListed);
  EXPECT_EQ(single.times, kListed);  // exactly: no row at t_start, none of the grid's
  const SensitivityTable network =
      RunWithSensitivities(LoadScenario(Network()), {"models.muscle.f_iso"}, kListed);
  EXPECT_EQ(network.times, kListed);
  // t_start listed: the first row is the initial state
  const std::vector<double> with_start = {0.0, 0.1, 0.2};
  const SensitivityTable from_start =
      RunWithSensitivities(LoadScenario(Single()), {"initial.length"}, with_start);
  EXPECT_EQ(from_start.times, with_start);
  ASSERT_EQ(from_start.rows(), 3u);
  // dx(t0)/dx0 = 1 and dxdot(t0)/dx0 = 0, exactly: the initial sensitivity itself
  EXPECT_EQ(from_start.derivative(0, 0, static_cast<std::size_t>(from_start.FindColumn("length"))),
            1.0);
  EXPECT_EQ(from_start.derivative(
                0, 0, static_cast<std::size_t>(from_start.FindColumn("shortening_velocity"))),
            0.0);
}

TEST(SensitivityOutputTimes, DerivativesAtListedTimesSingleActuator) {
  // between the solver's steps: the sensitivities' own interpolant
  ExpectSensitivitiesMatchDifferences(
      Single(), {}, {At("model.f_iso", 100.0), At("actuator.damping", 2.0)}, kListed);
}

TEST(SensitivityOutputTimes, DerivativesAtListedTimesNetwork) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {}, {At("models.muscle.velocity.v_max", 1.0), At("nodes[1].position", 0.101)},
      kListed);
}

TEST(SensitivityTable, NamesItsParametersValuesAndSources) {
  const SensitivityTable table =
      RunFileWithSensitivities(Single(), {"actuator.mass=0.25"}, {"model.f_iso", "actuator.mass"});
  EXPECT_EQ(table.parameters, (std::vector<std::string>{"model.f_iso", "actuator.mass"}));
  // the values as run: the file's, or an override's
  EXPECT_EQ(table.parameter_values, (std::vector<double>{100.0, 0.25}));
  EXPECT_EQ(table.sources, (std::vector<DerivativeSource>{DerivativeSource::kAnalytic,
                                                          DerivativeSource::kDifferenceQuotient}));
  EXPECT_EQ(table.columns,
            (std::vector<std::string>{"length", "shortening_velocity", "tension_passive",
                                      "tension_active", "tension_total"}));
  // rows on the scenario's grid, every 20 ms from 0 to 0.2 s
  ASSERT_EQ(table.rows(), 11u);
  EXPECT_EQ(table.times.front(), 0.0);
  EXPECT_EQ(table.times.back(), 0.2);
  EXPECT_EQ(table.values.size(), 11u * 5u);
  EXPECT_EQ(table.derivatives.size(), 11u * 2u * 5u);
}

TEST(SensitivityTable, TheActuatorsDamperAndSpringAreClosedForms) {
  // the single actuator's damping, stiffness and rest length are the coefficients of its
  // network's damper and spring elements (docs/model.md 7.4), whose df/dp has a closed form;
  // its mass, a node's, is a difference quotient
  const SensitivityTable table = RunWithSensitivities(
      LoadScenario(Single()),
      {"actuator.damping", "actuator.stiffness", "actuator.rest_length", "actuator.mass"});
  EXPECT_EQ(table.sources,
            (std::vector<DerivativeSource>{DerivativeSource::kAnalytic, DerivativeSource::kAnalytic,
                                           DerivativeSource::kAnalytic,
                                           DerivativeSource::kDifferenceQuotient}));
}

// The InputError a request from the command line throws, the scenario's path shown as FILE.
std::string Refusal(const std::string& scenario, const std::string& parameter) {
  return testing::InputErrorOf(scenario, [&] {
    SensitivityRun(LoadScenario(scenario), {{parameter, "--sensitivity"}});
  });
}

TEST(SensitivityRefusals, AParameterThatMovesABreakpoint) {
  std::string text = kSingle;
  const std::string constant = "{type: constant, value: 25.0}";
  text.replace(text.find(constant), constant.size(),
               "{type: step, time: 0.1, before: 25.0, after: 30.0}");
  const std::string scenario = testing::WriteTempFile("breakpoint.yaml", text);
  for (const char* path : {"activation.time", "load[0].time"}) {
    const std::string message = Refusal(scenario, path);
    EXPECT_THAT(message, HasSubstr(std::string("--sensitivity ") + path + ": "));
    EXPECT_THAT(message, HasSubstr("moves when an input jumps"));
  }
}

TEST(SensitivityRefusals, AnInteger) {
  const std::string message = Refusal(Single(), "model.velocity.n");
  EXPECT_THAT(message, HasSubstr("--sensitivity model.velocity.n = 3: "));
  EXPECT_THAT(message, HasSubstr("cannot change continuously"));
  EXPECT_THAT(message, HasSubstr("must be an integer"));
}

TEST(SensitivityRefusals, ASetting) {
  const std::string message = Refusal(Single(), "solver.rtol");
  EXPECT_THAT(message, HasSubstr("--sensitivity solver.rtol: a setting of the run, not a "
                                 "parameter of its dynamics"));
}

TEST(SensitivityRefusals, APathAbsentFromTheFile) {
  // a part the scenario does not have (it has one load): nothing to differentiate by
  const std::string message = Refusal(Single(), "load[3].value");
  EXPECT_THAT(message, HasSubstr("--sensitivity load[3].value: "));
  EXPECT_THAT(message, HasSubstr(": a sensitivity needs a number of the scenario's dynamics"));
}

// A key the file leaves out still has its value in the scenario (the initial lengthening
// rate: 0 m/s), and the handle on it differentiates like any other: the sensitivity is
// checked against differences of full runs with the key added by --set.
TEST(SensitivityTable, AValueTheFileLeavesOutIsTheScenariosDefault) {
  const SensitivityTable table =
      RunWithSensitivities(LoadScenario(Single()), {"initial.lengthening_rate"});
  EXPECT_EQ(table.parameter_values, std::vector<double>{0.0});
  testing::Differentiated rate{"initial.lengthening_rate", 0.0, 0.01, false};  // 1 cm/s
  ExpectSensitivitiesMatchDifferences(Single(), {}, {rate});
}

TEST(SensitivityRefusals, ANonNumber) {
  const std::string message = Refusal(Network(), "elements[0].model");
  EXPECT_THAT(message, HasSubstr("--sensitivity elements[0].model: names no number of this "
                                 "actuator: a sensitivity needs a number of the scenario's "
                                 "dynamics"));
}

// No parameters: the plain columns, through the sensitivity path.
TEST(SensitivityTable, NoParametersGiveThePlainColumns) {
  const std::string scenario = Single();
  const SensitivityTable table = RunWithSensitivities(LoadScenario(scenario), {});
  const testing::FullTrajectory plain = testing::FullRun(scenario, {});
  ASSERT_EQ(table.times, plain.times);
  ASSERT_EQ(table.columns, plain.columns);
  const std::size_t columns = plain.columns.size();
  for (std::size_t c = 0; c < columns; ++c) {
    double scale = 0.0;
    for (std::size_t i = c; i < plain.values.size(); i += columns) {
      scale = std::max(scale, std::abs(plain.values[i]));
    }
    for (std::size_t i = c; i < plain.values.size(); i += columns) {
      // two integrations of one trajectory at rtol 1e-12: their global errors, far below 1e-8
      EXPECT_NEAR(table.values[i], plain.values[i], 1e-8 * scale) << plain.columns[c];
    }
  }
}

}  // namespace
}  // namespace musclesim
