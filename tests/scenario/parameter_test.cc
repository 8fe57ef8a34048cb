// Parameter handles (scenario/parameter.h) against what they stand for: every kind of key path
// reads the field it names (read here straight from the scenario's parts), a value outside
// its range or breaking the scenario is refused and leaves the scenario as it was, values
// valid only together are taken together, a single actuator's key and its network's key are
// one value, and a model's handle rebuilds the model as the file reader does with --set (a
// run of each, bit for bit).
#include "musclesim/scenario/parameter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using testing::FixturePath;
using ::testing::HasSubstr;
using testing::SameRecordedRun;
using testing::ScenarioPath;

// A key path, the value it names read from the scenario's parts, and what kind of key it is.
struct Key {
  std::string path;
  double value;
  bool setting = false;
  bool integer = false;
};

void ExpectKeysRead(const Scenario& s, const std::vector<Key>& keys) {
  for (const Key& key : keys) {
    SCOPED_TRACE(key.path);
    const Parameter p = s.parameter(key.path);
    EXPECT_EQ(p.path(), key.path);
    EXPECT_EQ(p.Get(s), key.value);
    EXPECT_EQ(p.is_setting(), key.setting);
    EXPECT_EQ(p.is_integer(), key.integer);
  }
}

TEST(Parameter, EverySingleActuatorKeyReadsItsPartOfTheNetwork) {
  const Scenario s = LoadScenario(FixturePath("actuator.yaml"));
  const ModelParams& m = s.models.at("model").spec.params;
  const Node& tip = s.nodes[kActuatorTipNode];
  const Element& actuator = s.elements[kActuatorElement];
  const Element& damper = s.elements[kActuatorDamperElement];
  const Element& spring = s.elements[kActuatorSpringElement];
  const Gaussian& g = m.active_length.gaussians[0];
  ExpectKeysRead(
      s, {
             {"model.f_iso", m.f_iso},
             {"model.passive.k_p", m.passive.k_p},
             {"model.passive.alpha", m.passive.alpha},
             {"model.passive.slack_length", m.passive.slack_length},
             {"model.active_length.optimal_range[0]", m.active_length.optimal_min},
             {"model.active_length.optimal_range[1]", m.active_length.optimal_max},
             {"model.active_length.sigma", m.active_length.sigma},
             {"model.active_length.gaussians[0].amplitude", g.amplitude},
             {"model.active_length.gaussians[0].width", g.precision},
             {"model.active_length.gaussians[0].center", g.center},
             {"model.velocity.v_max", m.velocity.v_max},
             {"model.velocity.n", static_cast<double>(m.velocity.n), false, true},
             {"model.velocity.epsilon", m.velocity.epsilon},
             // the eccentric branch's keys the file leaves out: the concentric ones, and no limit
             {"model.velocity.eccentric.v_max", m.velocity.v_max},
             {"model.velocity.eccentric.n", static_cast<double>(m.velocity.n), false, true},
             {"model.velocity.eccentric.limit", std::numeric_limits<double>::infinity()},
             {"actuator.mass", tip.mass},
             {"actuator.damping", damper.damping},
             {"actuator.stiffness", spring.stiffness},
             {"actuator.rest_length", spring.rest_length},
             {"initial.length", tip.position},
             {"initial.lengthening_rate", tip.velocity},
             {"activation.time", actuator.activation.time},
             {"activation.before", actuator.activation.before},
             {"activation.after", actuator.activation.after},
             {"load[0].value", s.loads[0].load.force.value},
             {"time.start", s.t_start, true},
             {"time.end", s.t_end, true},
             {"solver.rtol", s.solver.rtol, true},
             {"solver.atol", s.solver.atol, true},
             {"solver.max_step", s.solver.max_step, true},
             {"solver.max_steps", static_cast<double>(s.solver.max_steps), true, true},
             {"output.interval", s.output.interval, true},
             {"limits.min_length", *s.limits[0].min_length, true},
             {"limits.max_length", *s.limits[0].max_length, true},
         });
  // and the file's own numbers, as written in tests/fixtures/actuator.yaml
  EXPECT_EQ(s.parameter("model.f_iso").Get(s), 100.0);
  EXPECT_EQ(s.parameter("actuator.mass").Get(s), 0.1);
  EXPECT_EQ(s.parameter("load[0].value").Get(s), 40.0);
  EXPECT_EQ(s.parameter("limits.max_length").Get(s), 0.2);

  // what a handle says it is: a model's parameter, or an element's own coefficient
  const Parameter v_max = s.parameter("model.velocity.v_max");
  EXPECT_EQ(v_max.model(), "model");
  EXPECT_EQ(v_max.model_path(), "velocity.v_max");
  EXPECT_EQ(v_max.element(), -1);
  const Parameter damping = s.parameter("actuator.damping");
  EXPECT_EQ(damping.element(), kActuatorDamperElement);
  EXPECT_EQ(damping.element_path(), "damping");
  EXPECT_EQ(damping.model(), "");
  EXPECT_EQ(s.parameter("actuator.rest_length").element(), kActuatorSpringElement);
  EXPECT_EQ(s.parameter("actuator.mass").element(), -1);  // a node's: not an element's
}

TEST(Parameter, EveryNetworkKeyReadsItsPart) {
  const Scenario s = LoadScenario(FixturePath("every_part.yaml"));
  const ModelParams& flexor = s.models.at("flexor").spec.params;
  const Waveform& crank = s.nodes[3].motion;
  const Waveform& flexor_activation = s.elements[0].activation;
  ExpectKeysRead(s, {
                        {"models.flexor.f_iso", flexor.f_iso},
                        {"models.flexor.passive.slack_length", flexor.passive.slack_length},
                        {"models.extensor.f_iso", s.models.at("extensor").spec.params.f_iso},
                        {"models.extensor.velocity.n", 1.0, false, true},
                        {"nodes[0].fixed", s.nodes[0].position},
                        {"nodes[1].mass", s.nodes[1].mass},
                        {"nodes[1].position", s.nodes[1].position},
                        {"nodes[1].velocity", s.nodes[1].velocity},
                        {"nodes[2].fixed", s.nodes[2].position},
                        {"nodes[3].prescribed.offset", crank.offset},
                        {"nodes[3].prescribed.amplitude", crank.amplitude},
                        {"nodes[3].prescribed.frequency", crank.frequency},
                        {"nodes[3].prescribed.phase", crank.phase},
                        {"elements[0].activation.time", flexor_activation.time},
                        {"elements[0].activation.before", flexor_activation.before},
                        {"elements[0].activation.after", flexor_activation.after},
                        {"elements[1].activation.value", s.elements[1].activation.value},
                        {"elements[2].slack_length", s.elements[2].slack_length},
                        {"elements[2].stiffness", s.elements[2].stiffness},
                        {"elements[3].slack_length", s.elements[3].slack_length},
                        {"elements[3].exponential.k", s.elements[3].k},
                        {"elements[3].exponential.alpha", s.elements[3].alpha},
                        {"elements[4].stiffness", s.elements[4].stiffness},
                        {"elements[4].rest_length", s.elements[4].rest_length},
                        {"elements[5].damping", s.elements[5].damping},
                        {"loads[0].value", s.loads[0].load.force.value},
                        {"loads[1].mass", s.loads[1].load.mass},
                        {"loads[1].gravity", s.loads[1].load.gravity},
                        {"loads[2].stiffness", s.loads[2].load.stiffness},
                        {"loads[2].anchor", s.loads[2].load.anchor},
                        {"time.start", s.t_start, true},
                        {"solver.rtol", s.solver.rtol, true},
                        {"output.interval", s.output.interval, true},
                        {"limits[0].min_length", *s.limits[0].min_length, true},
                        {"limits[0].max_length", *s.limits[0].max_length, true},
                        {"limits[1].max_length", *s.limits[1].max_length, true},
                    });
  // the file's numbers, as tests/fixtures/every_part.yaml writes them
  EXPECT_EQ(s.parameter("nodes[3].prescribed.phase").Get(s), 0.5);
  EXPECT_EQ(s.parameter("elements[3].exponential.alpha").Get(s), 20.0);
  EXPECT_EQ(s.parameter("loads[2].anchor").Get(s), 0.12);
  const Parameter alpha = s.parameter("elements[3].exponential.alpha");
  EXPECT_EQ(alpha.element(), 3);
  EXPECT_EQ(alpha.element_path(), "exponential.alpha");
  const Parameter k_p = s.parameter("models.extensor.passive.k_p");
  EXPECT_EQ(k_p.model(), "extensor");
  EXPECT_EQ(k_p.model_path(), "passive.k_p");
}

TEST(Parameter, ActivationDynamicsControllersAndTablesReadTheirParts) {
  const Scenario twitches = LoadScenario(ScenarioPath("twitches.yaml"));
  const ExcitationInput& input = *twitches.elements[kActuatorElement].excitation;
  ExpectKeysRead(twitches,
                 {
                     {"excitation.start", input.signal.start},
                     {"excitation.period", input.signal.period},
                     {"excitation.width", input.signal.width},
                     {"excitation.high", input.signal.high},
                     {"activation_dynamics.tau_activation", input.dynamics.tau_activation},
                     {"activation_dynamics.tau_deactivation", input.dynamics.tau_deactivation},
                     // left out of the file: the excitation at the start
                     {"initial.activation", input.InitialActivation(twitches.t_start)},
                 });

  const Scenario tracking = LoadScenario(ScenarioPath("position_tracking.yaml"));
  const Controller& c = tracking.controllers[0];
  ExpectKeysRead(tracking,
                 {
                     {"controllers[0].gains.kp", c.gains.kp},
                     {"controllers[0].gains.ki", c.gains.ki},
                     {"controllers[0].gains.kd", c.gains.kd},
                     {"controllers[0].reference.offset", c.reference.offset},
                     {"controllers[0].reference.amplitude", c.reference.amplitude},
                     {"controllers[0].co_contraction.level.value", c.co_contraction->level.value},
                 });
  EXPECT_EQ(tracking.parameter("controllers[0].gains.kp").Get(tracking), 250.0);

  std::string text = testing::ReadFile(FixturePath("actuator.yaml"));
  const std::string constant = "{type: constant, value: 40.0}";
  text.replace(text.find(constant), constant.size(),
               "{type: table, points: [[0.0, 1.0], [0.5, 2.0]]}");
  const Scenario table = LoadScenario(testing::WriteTempFile("table.yaml", text));
  ExpectKeysRead(table, {{"load[0].points[1][0]", 0.5}, {"load[0].points[1][1]", 2.0}});
}

// The ParameterError FindParameter throws for `path` in `s`, as "path: rule".
std::string Refusal(const Scenario& s, const std::string& path) {
  try {
    FindParameter(s, path);
  } catch (const ParameterError& e) {
    return e.path() + ": " + e.rule();
  }
  return "found";
}

TEST(Parameter, PathsThatNameNoNumberAreRefused) {
  const Scenario actuator = LoadScenario(FixturePath("actuator.yaml"));
  EXPECT_THAT(Refusal(actuator, "model..f_iso"), HasSubstr("is not a key path"));
  EXPECT_THAT(Refusal(actuator, "[0].mass"), HasSubstr("is not a key path"));
  // the single actuator's vocabulary is its file's, not its network's
  EXPECT_THAT(Refusal(actuator, "nodes[1].mass"),
              HasSubstr("nodes[1].mass: names no key of a single-actuator scenario"));
  EXPECT_THAT(Refusal(actuator, "load[3].value"), HasSubstr("indexes past the end of loads"));
  EXPECT_THAT(Refusal(actuator, "activation.amplitude"),
              HasSubstr("names no field of this step waveform"));
  EXPECT_THAT(Refusal(actuator, "model.velocity"),
              HasSubstr("model.velocity: names a block, not one number"));
  EXPECT_THAT(Refusal(actuator, "model.velocity.eccentric"),
              HasSubstr("model.velocity.eccentric: names a block, not one number"));
  EXPECT_THAT(Refusal(actuator, "model.colour"),
              HasSubstr("model.colour: names no parameter of a paper model (f_iso, passive.k_p, "
                        "passive.alpha, passive.slack_length, active_length.sigma, "));
  EXPECT_THAT(Refusal(actuator, "output.phase_tolerance"),
              HasSubstr("names no numeric setting"));  // the file gives none

  const Scenario network = LoadScenario(FixturePath("every_part.yaml"));
  EXPECT_THAT(Refusal(network, "models.nope.f_iso"), HasSubstr("names no model block"));
  EXPECT_THAT(Refusal(network, "nodes[0].mass"), HasSubstr("names no number of this fixed node"));
  EXPECT_THAT(Refusal(network, "elements[0].stiffness"),
              HasSubstr("names no number of this actuator"));
  EXPECT_THAT(Refusal(network, "elements[2].damping"), HasSubstr("names no number of this"));
  EXPECT_THAT(Refusal(network, "controllers[0].gains.kp"),
              HasSubstr("indexes past the end of controllers"));
  EXPECT_THAT(Refusal(network, "colour"), HasSubstr("names no numeric value of the scenario"));
}

// A model's lists (model/family_fields.h): L_opt and MuJoCo's pairs are lists of numbers, the
// Gaussians a list of sub-parts; each item's number is a handle, an index past the list or a
// list named whole is refused.
TEST(Parameter, AModelsListsAreIndexedWithinThem) {
  const Scenario paper = LoadScenario(FixturePath("actuator.yaml"));
  EXPECT_EQ(paper.models.at("model").spec.params.active_length.gaussians.size(), 1u);
  EXPECT_THAT(Refusal(paper, "model.active_length.optimal_range"),
              HasSubstr("needs an index of optimal_range"));
  EXPECT_THAT(Refusal(paper, "model.active_length.optimal_range[2]"),
              HasSubstr("indexes past the end of optimal_range (2)"));
  EXPECT_THAT(Refusal(paper, "model.active_length.gaussians"),
              HasSubstr("needs an index of gaussians"));
  EXPECT_THAT(Refusal(paper, "model.active_length.gaussians[1].width"),
              HasSubstr("indexes past the end of gaussians (1)"));
  EXPECT_THAT(Refusal(paper, "model.active_length.gaussians[0]"),
              HasSubstr("names a block, not one number"));
  EXPECT_THAT(Refusal(paper, "model.active_length.gaussians[0].widht"),
              HasSubstr("names no field of a Gaussian (amplitude, width, center)"));

  const std::string path = testing::WriteTempFile(
      "mujoco_lists.yaml",
      "models:\n  m: {family: mujoco, f_iso: 100, range: [0.7, 1.1], lengthrange: [0.1, 0.3]}\n"
      "nodes:\n  - {name: wall, fixed: 0.0}\n  - {name: tip, mass: 1.0, position: 0.2}\n"
      "elements:\n  - {name: m1, type: actuator, from: wall, to: tip, model: m, "
      "activation: {type: constant, value: 0.5}}\n"
      "time: {start: 0.0, end: 0.1}\n");
  Scenario mujoco = LoadScenario(path);
  const MujocoMuscleParams& m = mujoco.models.at("m").spec.params.mujoco;
  EXPECT_EQ(m.range[0], 0.7);
  EXPECT_EQ(m.range[1], 1.1);
  EXPECT_EQ(m.lengthrange[0], 0.1);
  EXPECT_EQ(m.lengthrange[1], 0.3);
  ExpectKeysRead(mujoco, {{"models.m.range[1]", 1.1}, {"models.m.lengthrange[0]", 0.1}});
  mujoco.parameter("models.m.lengthrange[1]").Set(mujoco, 0.4);
  EXPECT_EQ(mujoco.models.at("m").spec.params.mujoco.lengthrange[1], 0.4);
  EXPECT_THAT(Refusal(mujoco, "models.m.range"), HasSubstr("needs an index of range"));
  EXPECT_THAT(Refusal(mujoco, "models.m.lengthrange[2]"),
              HasSubstr("indexes past the end of lengthrange (2)"));
}

// In 2 or 3 dimensions a node's coordinate is indexed, nodes[i].position[1] its y, and the
// gravity is gravity[c]; on a line neither takes an index. (Built in code: Get and Assign
// check nothing of the network, so this holds whatever the engine does in the plane.)
// De Groote's tendon holds its law as (k, alpha) = (0.2 F0, ln 6 / (strain l_s)): each of its
// YAML keys, set through its handle (as a sweep or a sensitivity's difference quotient sets
// it), leaves the element a scenario read with that value has, its slack length keeping the
// strain (not alpha).
TEST(Parameter, ADeGrooteTendonsKeysSetItsLawAsTheFileWould) {
  const Scenario s = LoadScenario(ScenarioPath("musculotendon_compliant.yaml"));
  ASSERT_EQ(s.elements[1].name, "tendon");
  struct Case {
    const char* path;
    double initial, value;
    Element expected;
  };
  const Case cases[] = {
      {"elements[1].slack_length", 0.2, 0.21,
       Element::DeGrooteTendon("tendon", "junction", "end", 0.21, 100.0, 0.049)},
      {"elements[1].degroote2016.max_isometric_force", 100.0, 150.0,
       Element::DeGrooteTendon("tendon", "junction", "end", 0.2, 150.0, 0.049)},
      {"elements[1].degroote2016.strain_at_one_norm_force", 0.049, 0.03,
       Element::DeGrooteTendon("tendon", "junction", "end", 0.2, 100.0, 0.03)},
  };
  for (const Case& c : cases) {
    Scenario moved = s;
    const Parameter handle = FindParameter(moved, c.path);
    EXPECT_NEAR(handle.Get(s), c.initial, 1e-15 * c.initial) << c.path;
    handle.Set(moved, c.value);
    const Element& got = moved.elements[1];
    EXPECT_NEAR(got.slack_length, c.expected.slack_length, 1e-15) << c.path;
    EXPECT_NEAR(got.k, c.expected.k, 1e-12) << c.path;
    EXPECT_NEAR(got.alpha, c.expected.alpha, 1e-12 * c.expected.alpha) << c.path;
    EXPECT_NEAR(handle.Get(moved), c.value, 1e-15 * c.value) << c.path;
  }
  EXPECT_THAT(Refusal(s, "elements[1].exponential.k"),
              HasSubstr("names no number of this De Groote tendon"));
}

TEST(Parameter, InAPlaneACoordinateIsIndexed) {
  Scenario s;
  s.space.dimensions = 2;
  s.space.gravity = {0.0, -9.81, 0.0};
  s.nodes = {Node::Fixed("wall", Coordinates{0.0, 0.5, 0.0}),
             Node::Prescribed("arm", {Waveform::Constant(0.1), Waveform::Sine(0.2, 0.01, 2.0),
                                      Waveform::Constant(0.0)}),
             Node::Free("load", 2.0, Coordinates{0.4, 0.1, 0.0}, Coordinates{0.0, -0.5, 0.0})};
  ExpectKeysRead(s, {{"nodes[0].fixed[0]", 0.0},
                     {"nodes[0].fixed[1]", 0.5},
                     {"nodes[1].prescribed[0].value", 0.1},
                     {"nodes[1].prescribed[1].amplitude", 0.01},
                     {"nodes[2].mass", 2.0},
                     {"nodes[2].position[0]", 0.4},
                     {"nodes[2].position[1]", 0.1},
                     {"nodes[2].velocity[1]", -0.5},
                     {"gravity[1]", -9.81}});
  // a handle writes the field it reads
  Scenario copy = s;
  FindParameter(s, "nodes[2].position[1]").Assign(copy, 0.3);
  FindParameter(s, "nodes[1].prescribed[1].offset").Assign(copy, 0.25);
  FindParameter(s, "gravity[0]").Assign(copy, 1.5);
  EXPECT_EQ(copy.nodes[2].position_yz[0], 0.3);
  EXPECT_EQ(copy.nodes[2].position, 0.4);
  EXPECT_EQ(copy.nodes[1].motion_yz[0].offset, 0.25);
  EXPECT_EQ(copy.space.gravity[0], 1.5);
  EXPECT_THAT(Refusal(s, "nodes[2].position"),
              HasSubstr("nodes[2].position: needs a coordinate's index in 2 dimensions: "
                        "position[0] (x) to position[1]"));
  EXPECT_THAT(Refusal(s, "nodes[0].fixed[2]"),
              HasSubstr("indexes past the 2 coordinates of fixed (0 to 1)"));
  EXPECT_THAT(Refusal(s, "nodes[1].prescribed.value"), HasSubstr("needs a coordinate's index"));
  EXPECT_THAT(Refusal(s, "gravity"), HasSubstr("needs a coordinate's index"));
  EXPECT_THAT(Refusal(s, "nodes[2].position[1].x"), HasSubstr("names a block, not one number"));

  const Scenario line = LoadScenario(FixturePath("every_part.yaml"));
  EXPECT_THAT(Refusal(line, "nodes[1].position[0]"),
              HasSubstr("nodes[1].position[0]: takes no index: position is one number, x, in 1 "
                        "dimension"));
  EXPECT_THAT(Refusal(line, "gravity[1]"), HasSubstr("names nothing in 1 dimension"));
}

TEST(Parameter, OneLoadWrittenAsAMapIsLoad0) {
  // the README: a single load may be written as a map, and is load[0]: the same number
  // under either name
  const Scenario s = LoadScenario(FixturePath("actuator.yaml"));
  EXPECT_EQ(s.parameter("load.value").Get(s), s.loads[0].load.force.value);
  Scenario copy = s;
  s.parameter("load.value").Set(copy, 55.0);
  EXPECT_EQ(s.parameter("load[0].value").Get(copy), 55.0);
}

TEST(Parameter, OneLoadUnderEitherNameIsOneSensitivity) {
  // the column keeps the name first asked for (a file's `sensitivities:` list names its
  // columns); the other name of the same number is a repeat and is dropped
  const Scenario s = LoadScenario(FixturePath("actuator.yaml"));
  EXPECT_EQ(s.parameter("load.value").network_path(), s.parameter("load[0].value").network_path());
  EXPECT_NE(s.parameter("load.value").network_path(), s.parameter("actuator.mass").network_path());
  const SensitivityTable table = RunWithSensitivities(s, {"load.value", "load[0].value"});
  EXPECT_EQ(table.parameters, std::vector<std::string>{"load.value"});
}

TEST(Parameter, AHandleFoundOnceWritesAnyCopy) {
  const Scenario s = LoadScenario(FixturePath("actuator.yaml"));
  const Parameter mass = s.parameter("actuator.mass");
  Scenario copy = s;
  mass.Set(copy, 0.2);
  EXPECT_EQ(copy.nodes[kActuatorTipNode].mass, 0.2);
  EXPECT_EQ(s.nodes[kActuatorTipNode].mass, 0.1);  // a Scenario is a value
  EXPECT_EQ(mass.Get(copy), 0.2);
}

// Every handle's value, for telling whether a refused Set left anything changed.
std::vector<double> Values(const Scenario& s, const std::vector<std::string>& paths) {
  std::vector<double> values;
  for (const std::string& path : paths) values.push_back(s.parameter(path).Get(s));
  return values;
}

TEST(Parameter, ARefusedSetLeavesTheScenarioAsItWas) {
  const std::vector<std::string> paths = {
      "model.f_iso",   "model.velocity.n", "model.velocity.epsilon",
      "actuator.mass", "initial.length",   "activation.after",
      "time.end",      "limits.max_length"};
  struct Case {
    std::string path;
    double value;
    std::string error;  // what the ParameterError says: "path = value: rule" in part
  };
  const std::vector<Case> cases = {
      // the key's own range, as the file reader checks it
      {"actuator.mass", -1.0, "actuator.mass = -1"},
      {"actuator.mass", std::nan(""), "must be finite"},
      {"model.velocity.n", 2.5, "must be an integer"},
      {"time.end", -1.0, "time.end = -1"},
      // the model block, rebuilt: epsilon must stay below v_max
      {"model.velocity.epsilon", 5.0, "model.velocity.epsilon = 5"},
      // the scenario as a whole: the length against its limit, an activation above 1
      {"initial.length", 0.3, "limits.max_length"},
      {"activation.after", 1.5, "activation.after = 1.5"},
  };
  const Scenario before = LoadScenario(FixturePath("actuator.yaml"));
  Scenario s = before;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    try {
      s.parameter(c.path).Set(s, c.value);
      ADD_FAILURE() << c.path << " = " << c.value << " was accepted";
    } catch (const ParameterError& e) {
      EXPECT_THAT(e.what(), HasSubstr(c.error));
    }
    EXPECT_EQ(Values(s, paths), Values(before, paths));
    EXPECT_EQ(s.elements[kActuatorElement].model, before.elements[kActuatorElement].model);
  }
  // and it runs as it did, to the last bit
  EXPECT_TRUE(SameRecordedRun(RunScenario(s), RunScenario(before)));
}

TEST(Parameter, SetParametersTakesValuesValidOnlyTogether) {
  Scenario s = LoadScenario(FixturePath("actuator.yaml"));
  const Parameter length = s.parameter("initial.length");
  const Parameter limit = s.parameter("limits.max_length");
  // 0.25 m alone starts above the 0.2 m limit
  EXPECT_THROW(length.Set(s, 0.25), ParameterError);
  EXPECT_EQ(length.Get(s), 0.1);
  SetParameters(s, {length, limit}, {0.25, 0.3});
  EXPECT_EQ(s.nodes[kActuatorTipNode].position, 0.25);
  EXPECT_EQ(*s.limits[0].max_length, 0.3);
  // in either order
  Scenario other = LoadScenario(FixturePath("actuator.yaml"));
  SetParameters(other, {limit, length}, {0.3, 0.25});
  EXPECT_EQ(other.nodes[kActuatorTipNode].position, 0.25);

  // values each valid alone but not together: refused, naming what the whole breaks, and
  // nothing of them kept
  try {
    SetParameters(s, {length, limit}, {0.19, 0.15});
    ADD_FAILURE() << "0.19 m against a 0.15 m limit was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "limits.max_length");
  }
  EXPECT_EQ(length.Get(s), 0.25);
  EXPECT_EQ(limit.Get(s), 0.3);
  // a value breaking its own rule is named before anything is set
  try {
    SetParameters(s, {length, s.parameter("actuator.mass")}, {0.12, -1.0});
    ADD_FAILURE() << "a mass of -1 kg was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "actuator.mass");
  }
  EXPECT_EQ(length.Get(s), 0.25);
}

TEST(Parameter, ASingleActuatorsKeyAndItsNetworksKeyAreOneValue) {
  const Scenario actuator = LoadScenario(FixturePath("actuator.yaml"));
  // the same parts seen as a network: its handles take the network's key paths
  Scenario network = actuator;
  network.form = ScenarioForm::kNetwork;
  struct Case {
    std::string path;
    double value;  // a new value, valid
  };
  const std::vector<Case> cases = {
      {"model.f_iso", 120.0},       {"model.velocity.v_max", 1.5},
      {"actuator.mass", 0.2},       {"actuator.damping", 0.5},
      {"actuator.stiffness", 10.0}, {"actuator.rest_length", 0.11},
      {"initial.length", 0.11},     {"initial.lengthening_rate", -0.01},
      {"activation.after", 0.9},    {"activation.time", 0.02},
      {"load[0].value", 30.0},      {"limits.min_length", 0.06},
      {"limits.max_length", 0.25},  {"time.end", 0.5},
      {"solver.rtol", 1e-7},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    const std::optional<std::string> network_path = NetworkKeyPath(c.path);
    ASSERT_TRUE(network_path.has_value());
    const Parameter a = actuator.parameter(c.path);
    const Parameter n = network.parameter(*network_path);
    EXPECT_EQ(n.path(), *network_path);
    EXPECT_EQ(a.Get(actuator), n.Get(network));
    // set through one, read through the other
    Scenario x = actuator;
    a.Set(x, c.value);
    EXPECT_EQ(n.Get(x), c.value);
    Scenario y = network;
    n.Set(y, c.value);
    EXPECT_EQ(a.Get(y), c.value);
  }
}

TEST(Parameter, AModelsHandleRebuildsItAsTheFileWithSetDoes) {
  const std::string path = ScenarioPath("concentric.yaml");
  Scenario s = LoadScenario(path);
  const std::shared_ptr<const TensionModel> old_model = s.elements[kActuatorElement].model;
  s.parameter("model.f_iso").Set(s, 120.0);
  EXPECT_EQ(s.models.at("model").spec.params.f_iso, 120.0);
  // the actuator holds the rebuilt model, the block's own
  EXPECT_NE(s.elements[kActuatorElement].model, old_model);
  EXPECT_EQ(s.elements[kActuatorElement].model, s.models.at("model").model);
  EXPECT_EQ(s.elements[kActuatorElement].model->params().f_iso, 120.0);
  EXPECT_EQ(old_model->params().f_iso, 100.0);  // a model is immutable
  const RecordedRun in_code = RunScenario(s);
  const RecordedRun from_file = RunScenario(LoadScenario(path, {"model.f_iso=120"}));
  ASSERT_EQ(in_code.stats.status, RunStatus::kCompleted) << in_code.stats.message;
  EXPECT_TRUE(SameRecordedRun(in_code, from_file));
  // and not the run it was: f_iso moved it
  EXPECT_FALSE(SameRecordedRun(in_code, RunScenario(LoadScenario(path))));
}

// The smoothing of OpenSim's and MuJoCo's activation dynamics (their families' own keys,
// dynamics/activation_families.h) as handles: set in code, the run is the file's with that
// value, and not the run it was.
TEST(Parameter, AnActivationFamilysSmoothingIsAHandleAsInTheFile) {
  const std::string path = ScenarioPath("twitches.yaml");
  for (const auto& [family, key, value] :
       {std::tuple{"degroote2016", "smoothing", 0.5}, std::tuple{"mujoco", "tausmooth", 0.3}}) {
    SCOPED_TRACE(family);
    const std::string family_set = std::string("activation_dynamics.family=") + family;
    const std::string at = std::string("activation_dynamics.") + key;
    Scenario s = LoadScenario(path, {family_set});
    const Parameter handle = s.parameter(at);
    EXPECT_THROW(handle.Check(1e10), ParameterError);  // past its range
    handle.Set(s, value);
    const RecordedRun in_code = RunScenario(s);
    ASSERT_EQ(in_code.stats.status, RunStatus::kCompleted) << in_code.stats.message;
    EXPECT_TRUE(SameRecordedRun(
        in_code, RunScenario(LoadScenario(path, {family_set, at + "=" + FormatNumber(value)}))));
    EXPECT_FALSE(SameRecordedRun(in_code, RunScenario(LoadScenario(path, {family_set}))));
  }
  // thelen2003 has neither: the refusal lists its keys
  EXPECT_THAT(Refusal(LoadScenario(path), "activation_dynamics.smoothing"),
              HasSubstr("names no number of thelen2003's activation dynamics (tau_activation, "
                        "tau_deactivation)"));
}

TEST(Parameter, AFittedBlockIsFittedAgainWhenWhatTheFitDependsOnChanges) {
  // the fixture's model fitted to the indicator of its optimal range at load time
  std::string text = testing::ReadFile(FixturePath("actuator.yaml"));
  const std::string gaussians = "gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]";
  text.replace(text.find(gaussians), gaussians.size(), "fit: {count: 2, target: indicator}");
  const std::string path = testing::WriteTempFile("fitted.yaml", text);
  Scenario s = LoadScenario(path);
  const Parameter upper = s.parameter("model.active_length.optimal_range[1]");
  upper.Set(s, 0.107);
  const Scenario from_file = LoadScenario(path, {"model.active_length.optimal_range[1]=0.107"});
  const std::vector<Gaussian>& refitted = s.models.at("model").spec.params.active_length.gaussians;
  const std::vector<Gaussian>& read =
      from_file.models.at("model").spec.params.active_length.gaussians;
  ASSERT_EQ(refitted.size(), 2u);
  ASSERT_EQ(read.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    // the same fit on the same numbers: the same components, to the last bit
    EXPECT_EQ(refitted[k].amplitude, read[k].amplitude) << k;
    EXPECT_EQ(refitted[k].precision, read[k].precision) << k;
    EXPECT_EQ(refitted[k].center, read[k].center) << k;
  }
  EXPECT_NE(refitted[0].center,
            LoadScenario(path).models.at("model").spec.params.active_length.gaussians[0].center);
  // the fitted components are not parameters: they follow the fit
  EXPECT_THAT(Refusal(s, "model.active_length.gaussians[0].center"), HasSubstr("is fitted"));
  EXPECT_TRUE(SameRecordedRun(RunScenario(s), RunScenario(from_file)));
}

TEST(Parameter, ANetworksModelHandleChangesEveryActuatorOfTheBlock) {
  // the antagonist pair's two actuators share block `muscle`; 0.5 s of its 4 s is enough
  const std::string path = ScenarioPath("antagonist_pair.yaml");
  Scenario s = LoadScenario(path);
  SetParameters(s, {s.parameter("models.muscle.velocity.v_max"), s.parameter("time.end")},
                {15.0, 0.5});
  EXPECT_EQ(s.elements[0].model, s.elements[1].model);
  EXPECT_EQ(s.elements[0].model->params().velocity.v_max, 15.0);
  EXPECT_TRUE(SameRecordedRun(
      RunScenario(s),
      RunScenario(LoadScenario(path, {"models.muscle.velocity.v_max=15", "time.end=0.5"}))));
}

}  // namespace
}  // namespace musclesim
