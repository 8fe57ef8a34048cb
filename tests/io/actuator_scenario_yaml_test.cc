// The single-actuator form of scenario files (io/readers/scenario_yaml.h): every key read into the
// network of docs/model.md 7.4, --set on any scalar, and every broken rule placed at its
// file, line and column.
#include "musclesim/io/readers/scenario_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "musclesim/core/errors.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The single actuator of tests/fixtures/actuator.yaml, as text to edit: a constant 40 N load
// after a step to full activation, lines 1-7 its model block, line 8 `actuator:`.
std::string Valid() { return testing::ReadFile(testing::FixturePath("actuator.yaml")); }

// The error LoadScenario raises for the valid file with `from` replaced by `to`, with the
// temporary path shown as FILE.
std::string ErrorFor(const std::string& from, const std::string& to,
                     const std::vector<std::string>& sets = {}) {
  std::string text = Valid();
  if (!from.empty()) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  const std::string path = testing::WriteTempFile("scenario_test.yaml", text);
  return testing::InputErrorOf(path, [&] { LoadScenario(path, sets); });
}

TEST(Scenario, ReadsEveryKey) {
  const std::string path = testing::FixturePath("actuator.yaml");
  const Scenario s = LoadScenario(path);
  EXPECT_EQ(s.form, ScenarioForm::kActuator);
  // the network of docs/model.md 7.4: the actuator's mass and initial state on node `tip`,
  // its activation on element `actuator`, the damper and the spring beside it
  ASSERT_EQ(s.nodes.size(), 2u);
  ASSERT_EQ(s.elements.size(), 3u);
  EXPECT_EQ(s.nodes[kActuatorTipNode].mass, 0.1);
  EXPECT_EQ(s.nodes[kActuatorTipNode].position, 0.1);
  EXPECT_EQ(s.nodes[kActuatorTipNode].velocity, 0.0);
  EXPECT_EQ(s.elements[kActuatorElement].activation.kind, WaveformKind::kStep);
  EXPECT_EQ(s.elements[kActuatorDamperElement].damping, 0.0);
  EXPECT_EQ(s.elements[kActuatorSpringElement].rest_length, 0.1);
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].node, "tip");
  EXPECT_EQ(s.loads[0].load.force.value, 40.0);
  EXPECT_EQ(s.t_end, 1.0);
  EXPECT_EQ(s.solver.method, IntegrationMethod::kBdf);
  EXPECT_EQ(s.output.file, "out.csv");
  EXPECT_EQ(s.output.interval, 0.001);
  ASSERT_EQ(s.limits.size(), 1u);
  EXPECT_EQ(s.limits[0].element, "actuator");
  EXPECT_EQ(*s.limits[0].min_length, 0.05);
  // defaults to epsilon, docs/model.md section 6
  EXPECT_EQ(s.PhaseTolerance(kActuatorElement), 1e-3);
}

TEST(Scenario, ReadsEveryWaveformAndLoadType) {
  const std::string loads = R"(load:
  - {type: constant, value: 1.0}
  - {type: step, time: 0.1, before: 0.0, after: 2.0}
  - {type: ramp, start: 0.1, end: 0.2, from: 0.0, to: 3.0}
  - {type: sine, offset: 1.0, amplitude: 0.5, frequency: 2.0, phase: 0.1}
  - {type: pulses, start: 0.0, period: 0.1, width: 0.02, low: 0.0, high: 4.0}
  - {type: table, points: [[0.0, 1.0], [0.5, 2.0]]}
  - {type: spring, stiffness: 100.0, anchor: 0.1}
  - {type: mass, mass: 2.0}
)";
  const std::string valid = Valid();
  const std::string path =
      testing::WriteTempFile("scenario_loads.yaml", valid.substr(0, valid.find("load:")) + loads +
                                                        valid.substr(valid.find("time: {")));
  const Scenario s = LoadScenario(path);
  ASSERT_EQ(s.loads.size(), 8u);
  EXPECT_EQ(s.loads[6].load.kind, LoadKind::kSpring);
  EXPECT_EQ(s.loads[7].load.gravity, 9.81);
  EXPECT_EQ(s.loads[5].load.force.points[1].value, 2.0);
}

TEST(Scenario, SetOverridesAnyScalarByItsPath) {
  const std::string path = testing::FixturePath("actuator.yaml");
  const Scenario s =
      LoadScenario(path, {"model.velocity.n=4", "load[0].value=55", "solver.method=adams",
                          "model.active_length.optimal_range[1]=0.11", "output.interval=steps",
                          "model.active_length.sigma=2"});
  const ModelParams& model = s.models.at("model").spec.params;
  EXPECT_EQ(model.velocity.n, 4);
  EXPECT_EQ(s.loads[0].load.force.value, 55.0);
  EXPECT_EQ(s.solver.method, IntegrationMethod::kAdams);
  EXPECT_EQ(model.active_length.optimal_max, 0.11);
  EXPECT_TRUE(s.output.every_step);
  EXPECT_EQ(model.active_length.sigma, 2.0);  // a new key in an existing map
  // the actuator holds the model built from the block as overridden
  EXPECT_EQ(s.elements[kActuatorElement].model->params().velocity.n, 4);
}

TEST(Scenario, SetIsValidatedLikeTheFile) {
  EXPECT_EQ(ErrorFor("", "", {"model.velocity.n=0"}),
            "model.velocity.n = 0 (override): must be an integer from 1 to 1000 [-]: the power "
            "1/n; at 1000 it is 0.001, the curve a step");
  EXPECT_THAT(ErrorFor("", "", {"model.velocity.m=3"}),
              HasSubstr("model.velocity.m (override): unknown key"));
  EXPECT_EQ(ErrorFor("", "", {"model.speed.n=3"}),
            "override model.speed.n=3: model.speed does not exist in FILE");
  EXPECT_EQ(ErrorFor("", "", {"load[3].value=3"}),
            "override load[3].value=3: load[3] does not exist in FILE");
  EXPECT_EQ(ErrorFor("", "", {"model.velocity=3"}),
            "override model.velocity=3: model.velocity is a map or list; an override replaces "
            "single values only");
  EXPECT_THAT(ErrorFor("", "", {"model.velocity.n"}), HasSubstr("expected KEY=VALUE"));
  EXPECT_THAT(ErrorFor("", "", {"a..b=1"}), HasSubstr("is not a dotted key path"));
}

TEST(Scenario, SetKeepsTheFileLocationsOfOtherErrors) {
  // the copy the overrides go into must not lose where the file's values are
  EXPECT_THAT(ErrorFor("mass: 0.1,", "mass: -1,", {"model.velocity.n=2"}),
              HasSubstr("actuator.mass = -1 (FILE:8:18): must be from 1e-09"));
  EXPECT_THAT(ErrorFor("", "", {"actuator.mass=-1"}), HasSubstr("actuator.mass = -1 (override)"));
}

TEST(Scenario, SetIndexesOnlyLists) {
  EXPECT_THAT(ErrorFor("", "", {"model[0].f_iso=50"}),
              HasSubstr("override model[0].f_iso=50: model is a map, not a list"));
  EXPECT_THAT(ErrorFor("", "", {"[0].name=x"}), HasSubstr("the file's top level is a map"));
  // one load written as a map is load[0], as the README says
  std::string one_load = Valid();
  one_load.replace(one_load.find("load:\n  - {"), 11, "load: {");
  const std::string path = testing::WriteTempFile("scenario_one_load.yaml", one_load);
  const Scenario s = LoadScenario(path, {"load[0].value=55"});
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].load.force.value, 55.0);
}

TEST(Scenario, DuplicateKeysAreErrorsNamingBothPlaces) {
  EXPECT_EQ(ErrorFor("mass: 0.1,", "mass: 0.1, mass: -5.0,"),
            "actuator.mass (FILE:8:23): duplicate key: already given at line 8, column 12; a map "
            "holds each key once");
  EXPECT_THAT(ErrorFor("time: {start: 0.0, end: 1.0}\n",
                       "time: {start: 0.0, end: 1.0}\ntime: {start: 0.0, end: 2.0}\n"),
              HasSubstr("time (FILE:14:1): duplicate key: already given at line 13, column 1"));
}

TEST(Scenario, RejectsEveryBrokenRule) {
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"mass: 0.1,", "mass: 0,",
       "actuator.mass = 0 (FILE:8:18): must be from 1e-09 to 1e+09 [kg]: a microgram"},
      {"damping: 0.0", "damping: -1", "actuator.damping = -1"},
      {"stiffness: 0.0", "stiffness: -5", "actuator.stiffness = -5"},
      {"rest_length: 0.1}", "rest_length: 0.1, color: red}",
       "actuator.color (FILE:8:71): unknown key"},
      {"length: 0.1,", "length: 0,", "initial.length = 0 (FILE:9:19): must be > 0 and <= 1000 [m]"},
      {"lengthening_rate: 0.0", "lengthening_rate: x", "initial.lengthening_rate = x"},
      {"after: 1.0}", "after: 1.2}",
       "activation.after = 1.2 (FILE:10:58): activation must stay within [0, 1]"},
      {"before: 0.0,", "before: -0.5,", "activation.before = -0.5"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}",
       "{type: ramp, start: 0, end: 1, from: 0, to: 2}", "activation.to = 2"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}",
       "{type: sine, offset: 0.5, amplitude: 0.7, frequency: 1}", "activation.amplitude = 0.7"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}",
       "{type: pulses, start: 0, period: 0.1, width: 0.02, low: 0, high: 3}",
       "activation.high = 3"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}",
       "{type: table, points: [[0, 0], [1, 1.5]]}", "activation.points[1][1] = 1.5"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}",
       "{type: table, points: [[0, 0], [1, 1], [0.5, 1]]}",
       "activation.points[2][0] = 0.5 (FILE:10:53): table times must be strictly increasing"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: square, value: 1}",
       "activation.type = square (FILE:10:20): must be one of constant, step, ramp, sine, pulses, "
       "table"},
      {"{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: step, time: 0.05, after: 1.0}",
       "activation.before (FILE:10:13): missing required key"},
      {"{type: constant, value: 40.0}", "{type: spring, stiffness: -1, anchor: 0.1}",
       "load[0].stiffness = -1 (FILE:12:31): must be from 0 to 1e+12 [N/m]"},
      {"{type: constant, value: 40.0}", "{type: mass, mass: 0}", "load[0].mass = 0"},
      {"{type: constant, value: 40.0}", "{type: rocket, value: 1}",
       "load[0].type = rocket (FILE:12:12): must be one of constant, step, ramp, sine, pulses, "
       "table, spring, mass"},
      {"{type: constant, value: 40.0}",
       "{type: pulses, start: 0, period: 1.0e-8, width: 1.0e-9, low: 0, high: 1}",
       "load[0].period = 1.0e-8 (FILE:12:38): gives more than 5 million pulses"},
      {"end: 1.0}", "end: 0.0}",
       "time.end = 0.0 (FILE:13:25): must be greater than time.start = 0 by at least 1e-09 s"},
      {"rtol: 1.0e-6", "rtol: 0", "solver.rtol = 0 (FILE:14:29)"},
      {"atol: 1.0e-9", "atol: -1", "solver.atol = -1"},
      {"method: bdf", "method: rk4", "solver.method = rk4 (FILE:14:18): must be bdf or adams"},
      {"jacobian: analytic", "jacobian: exact",
       "solver.jacobian = exact (FILE:14:61): must be analytic or difference_quotient"},
      {"max_step: 0.0", "max_step: -1", "solver.max_step = -1"},
      {"interval: 0.001", "interval: 0",
       "output.interval = 0 (FILE:15:35): must be `steps` or a time [s] giving at most 1e8 rows"},
      {"interval: 0.001", "interval: often", "output.interval = often"},
      {"min_length: 0.05", "min_length: 0.15",
       "limits.min_length = 0.15 (FILE:16:22): must be >= 0 and below initial.length = 0.1"},
      {"max_length: 0.2", "max_length: 0.1",
       "limits.max_length = 0.1 (FILE:16:40): must be above initial.length"},
      {"time: {start", "tim: {start", "tim (FILE:13:1): unknown key"},
      {"time: {start: 0.0, end: 1.0}\n", "", "time (FILE:1:1): missing required key"},
  };
  for (const auto& [from, to, expected] : cases) {
    EXPECT_THAT(ErrorFor(from, to), HasSubstr(expected)) << from << " -> " << to;
  }
}

}  // namespace
}  // namespace musclesim
