// Network scenario files in the plane and in space (docs/model.md 12, docs/guide/networks.md
// "In the plane and in space"): the reader puts every coordinate, motion, via point, load
// direction and the gravity into its field, refuses each misshapen key at its file:line:col
// with the rule broken, and a file without `dimensions` reads as it always has.
//
// The parts are read here by the part readers (io/readers/network_parts_yaml.h), which build no
// system. The tests of the suite SpatialNetworkFile read whole files through LoadScenario,
// which builds the network and checks its initial state: they depend on the engine's
// support of 2 and 3 dimensions.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/readers/network_parts_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::WriteTempFile;

constexpr const char* kFile = "test.yaml";

// "test.yaml:line:column" (1-based) of the first `needle` in `text`.
std::string At(const std::string& text, const std::string& needle) {
  return std::string(kFile) + ":" + testing::LineColumn(text, needle);
}

// The space, nodes, elements and loads of `text` as the network reader reads them, without
// building the system.
Scenario ReadParts(const std::string& text) {
  const yaml::Source src{kFile};
  const Document root = yaml::Parse(kFile, text);
  Scenario s;
  s.space = ReadSpace(src, root);
  const int d = s.space.dimensions;
  s.nodes = ReadNodes(src, root["nodes"], d);
  s.elements = ReadElements(src, root["elements"], NamedModels{}, DrivenActuators{}, d, 0.0, 1.0);
  if (root["loads"]) s.loads = ReadNodeLoads(src, root["loads"], d, 0.0, 1.0);
  return s;
}

template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

std::string PartsError(const std::string& text) {
  return ErrorOf([&] { ReadParts(text); });
}

// A network of `dimensions` whose `nodes`, `elements` and `loads` lists are the given lines
// (loads left out when empty), with a time span for LoadScenario.
std::string Network(const std::string& dimensions, const std::string& nodes,
                    const std::string& elements, const std::string& loads = "") {
  return (dimensions.empty() ? "" : "dimensions: " + dimensions + "\n") + "nodes:\n" + nodes +
         "elements:\n" + elements + (loads.empty() ? "" : "loads:\n" + loads) +
         "time: {start: 0.0, end: 1.0}\n";
}

// A planar network with every kind of node, a cable over a fixed via point and a pulley node,
// a load along a direction and gravity.
const std::string kPlanar =
    "dimensions: 2\n"
    "gravity: [0.0, -9.81]\n"
    "nodes:\n"
    "  - {name: wall, fixed: [0.0, 0.5]}\n"
    "  - {name: pulley, fixed: [0.3, 0.6]}\n"
    "  - {name: arm, prescribed: [{type: constant, value: 0.1},\n"
    "                             {type: sine, offset: 0.2, amplitude: 0.01, frequency: 2.0,\n"
    "                              phase: 0.25}]}\n"
    "  - {name: load, mass: 2.0, position: [0.4, 0.1], velocity: [0.0, -0.5]}\n"
    "elements:\n"
    "  - {name: cable, type: tendon, from: wall, to: load, via: [[0.2, 0.7], pulley],\n"
    "     slack_length: 0.4, stiffness: 1.0e4}\n"
    "  - {name: spring, type: spring, from: arm, to: load, stiffness: 50.0, rest_length: 0.2}\n"
    "loads:\n"
    "  - {node: load, type: constant, value: 3.0, direction: [0.0, -2.0]}\n"
    "time: {start: 0.0, end: 1.0}\n";

// The same kinds of part in space.
const std::string kSpatial =
    "dimensions: 3\n"
    "gravity: [0.0, 0.0, -9.81]\n"
    "nodes:\n"
    "  - {name: wall, fixed: [0.0, 0.5, 1.0]}\n"
    "  - {name: hook, fixed: [0.1, 0.5, 1.2]}\n"
    "  - {name: arm, prescribed: [{type: constant, value: 0.1}, {type: constant, value: 0.2},\n"
    "                             {type: ramp, start: 0.0, end: 1.0, from: 0.3, to: 0.4}]}\n"
    "  - {name: load, mass: 2.0, position: [0.4, 0.1, 0.7], velocity: [0.0, -0.5, 0.25]}\n"
    "elements:\n"
    "  - {name: cable, type: tendon, from: wall, to: load, via: [hook, [0.2, 0.3, 0.9]],\n"
    "     slack_length: 0.4, exponential: {k: 3.0, alpha: 20.0}}\n"
    "  - {name: damper, type: damper, from: arm, to: load, damping: 2.0}\n"
    "loads:\n"
    "  - {node: load, type: spring, stiffness: 10.0, anchor: 0.5, direction: [1.0, 1.0, 0.0]}\n"
    "time: {start: 0.0, end: 1.0}\n";

void ExpectPlanar(const Scenario& s) {
  EXPECT_EQ(s.space.dimensions, 2);
  EXPECT_EQ(s.space.gravity, (Coordinates{0.0, -9.81, 0.0}));
  ASSERT_EQ(s.nodes.size(), 4u);
  EXPECT_EQ(s.nodes[0].kind, NodeKind::kFixed);
  EXPECT_EQ(s.nodes[0].PositionCoordinates(), (Coordinates{0.0, 0.5, 0.0}));
  EXPECT_EQ(s.nodes[1].PositionCoordinates(), (Coordinates{0.3, 0.6, 0.0}));
  const Node& arm = s.nodes[2];
  EXPECT_EQ(arm.kind, NodeKind::kPrescribed);
  EXPECT_EQ(arm.motion.kind, WaveformKind::kConstant);
  EXPECT_EQ(arm.motion.value, 0.1);
  EXPECT_EQ(arm.motion_yz[0].kind, WaveformKind::kSine);
  EXPECT_EQ(arm.motion_yz[0].offset, 0.2);
  EXPECT_EQ(arm.motion_yz[0].phase, 0.25);
  EXPECT_EQ(arm.motion_yz[1].kind, WaveformKind::kConstant);  // z unused: 0
  EXPECT_EQ(arm.motion_yz[1].value, 0.0);
  const Node& load = s.nodes[3];
  EXPECT_EQ(load.kind, NodeKind::kFree);
  EXPECT_EQ(load.mass, 2.0);
  EXPECT_EQ(load.PositionCoordinates(), (Coordinates{0.4, 0.1, 0.0}));
  EXPECT_EQ(load.VelocityCoordinates(), (Coordinates{0.0, -0.5, 0.0}));

  ASSERT_EQ(s.elements.size(), 2u);
  const Element& cable = s.elements[0];
  ASSERT_EQ(cable.via.size(), 2u);
  EXPECT_EQ(cable.via[0].node, "");
  EXPECT_EQ(cable.via[0].position, (Coordinates{0.2, 0.7, 0.0}));
  EXPECT_EQ(cable.via[1].node, "pulley");
  EXPECT_EQ(cable.stiffness, 1.0e4);
  EXPECT_TRUE(s.elements[1].via.empty());

  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].node, "load");
  EXPECT_EQ(s.loads[0].load.force.value, 3.0);
  EXPECT_EQ(s.loads[0].direction, (Coordinates{0.0, -2.0, 0.0}));  // as written
}

void ExpectSpatial(const Scenario& s) {
  EXPECT_EQ(s.space.dimensions, 3);
  EXPECT_EQ(s.space.gravity, (Coordinates{0.0, 0.0, -9.81}));
  ASSERT_EQ(s.nodes.size(), 4u);
  EXPECT_EQ(s.nodes[0].PositionCoordinates(), (Coordinates{0.0, 0.5, 1.0}));
  EXPECT_EQ(s.nodes[1].PositionCoordinates(), (Coordinates{0.1, 0.5, 1.2}));
  const Node& arm = s.nodes[2];
  EXPECT_EQ(arm.motion.value, 0.1);
  EXPECT_EQ(arm.motion_yz[0].value, 0.2);
  EXPECT_EQ(arm.motion_yz[1].kind, WaveformKind::kRamp);
  EXPECT_EQ(arm.motion_yz[1].to, 0.4);
  EXPECT_EQ(s.nodes[3].PositionCoordinates(), (Coordinates{0.4, 0.1, 0.7}));
  EXPECT_EQ(s.nodes[3].VelocityCoordinates(), (Coordinates{0.0, -0.5, 0.25}));
  ASSERT_EQ(s.elements.size(), 2u);
  const Element& cable = s.elements[0];
  EXPECT_TRUE(cable.exponential());
  ASSERT_EQ(cable.via.size(), 2u);
  EXPECT_EQ(cable.via[0].node, "hook");
  EXPECT_EQ(cable.via[1].node, "");
  EXPECT_EQ(cable.via[1].position, (Coordinates{0.2, 0.3, 0.9}));
  EXPECT_EQ(s.elements[1].damping, 2.0);
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].load.kind, LoadKind::kSpring);
  EXPECT_EQ(s.loads[0].direction, (Coordinates{1.0, 1.0, 0.0}));
}

TEST(SpatialNetworkYaml, ReadsAPlanarNetworkIntoItsFields) { ExpectPlanar(ReadParts(kPlanar)); }

TEST(SpatialNetworkYaml, ReadsANetworkInSpaceIntoItsFields) { ExpectSpatial(ReadParts(kSpatial)); }

TEST(SpatialNetworkYaml, ANetworkWithoutDimensionsIsOnALine) {
  const std::string nodes =
      "  - {name: wall, fixed: 0.0}\n"
      "  - {name: load, mass: 1.0, position: 0.1, velocity: 0.2}\n";
  const std::string elements =
      "  - {name: spring, type: spring, from: wall, to: load, stiffness: 50.0, rest_length: "
      "0.1}\n";
  const std::string loads = "  - {node: load, type: constant, value: 2.0}\n";
  for (const std::string dimensions : {"", "1"}) {
    SCOPED_TRACE("dimensions: " + dimensions);
    const Scenario s = ReadParts(Network(dimensions, nodes, elements, loads));
    EXPECT_EQ(s.space.dimensions, 1);
    EXPECT_EQ(s.space.gravity, (Coordinates{0.0, 0.0, 0.0}));
    EXPECT_EQ(s.nodes[1].PositionCoordinates(), (Coordinates{0.1, 0.0, 0.0}));
    EXPECT_EQ(s.nodes[1].VelocityCoordinates(), (Coordinates{0.2, 0.0, 0.0}));
    EXPECT_TRUE(s.elements[0].via.empty());
    EXPECT_EQ(s.loads[0].direction, (Coordinates{1.0, 0.0, 0.0}));
  }
}

TEST(SpatialNetworkYaml, DimensionsAndGravityAreCheckedAtTheirKeys) {
  const std::string nodes = "  - {name: wall, fixed: 0.0}\n";
  const std::string elements = "  - {name: s, type: spring, from: wall, to: wall}\n";
  std::string text = Network("4", nodes, elements);
  EXPECT_THAT(PartsError(text),
              HasSubstr("dimensions = 4 (" + At(text, "4") +
                        "): must be 1 (a line, the default), 2 (the x-y plane) or 3 (space)"));
  text = Network("2.5", nodes, elements);
  EXPECT_THAT(PartsError(text),
              HasSubstr("dimensions = 2.5 (" + At(text, "2.5") + "): must be an integer"));

  text = "gravity: [0.0, -9.81]\n" + Network("", nodes, elements);
  EXPECT_THAT(PartsError(text), HasSubstr("gravity = [0.0, -9.81] (" + At(text, "[0.0") +
                                          "): needs dimensions: 2 or 3 at the top level; on a "
                                          "line hang a weight with a load of type mass"));
  text = "gravity: [0.0, 0.0, -9.81]\n" + Network("2", nodes, elements);
  EXPECT_THAT(PartsError(text),
              HasSubstr("gravity = [0.0, 0.0, -9.81] (" + At(text, "[0.0") +
                        "): must be a list of 2 numbers [gx, gy]: the scenario has dimensions: 2"));
  text = "gravity: -9.81\n" + Network("3", nodes, elements);
  EXPECT_THAT(PartsError(text), HasSubstr("gravity = -9.81 (" + At(text, "-9.81") +
                                          "): must be a list of 3 numbers [gx, gy, gz]"));
  text = "gravity: [0.0, -2000.0]\n" + Network("2", nodes, elements);
  EXPECT_THAT(PartsError(text), HasSubstr("gravity[1] = -2000.0 (" + At(text, "-2000") +
                                          "): must be from -1000 to 1000 [m/s^2]"));
}

TEST(SpatialNetworkYaml, ACoordinateMustHaveTheScenariosDimensions) {
  const std::string element = "  - {name: s, type: spring, from: wall, to: load}\n";
  // a list on a line
  std::string text = Network("", "  - {name: wall, fixed: [0.0, 0.5]}\n", element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].fixed = [0.0, 0.5] (" + At(text, "[0.0") +
                        "): must be a number in 1 dimension: a list of coordinates needs "
                        "dimensions: 2 or 3"));
  // a number in the plane
  text = Network("2", "  - {name: wall, fixed: 0.25}\n", element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].fixed = 0.25 (" + At(text, "0.25") +
                        "): must be a list of 2 numbers [x, y]: the scenario has dimensions: 2"));
  // three coordinates in the plane
  text = Network("2",
                 "  - {name: wall, fixed: [0.0, 0.5]}\n"
                 "  - {name: load, mass: 1.0, position: [0.1, 0.2, 0.3]}\n",
                 element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[1].position = [0.1, 0.2, 0.3] (" + At(text, "[0.1") +
                        "): must be a list of 2 numbers [x, y]: the scenario has dimensions: 2"));
  // two in space
  text = Network("3", "  - {name: load, mass: 1.0, position: [0.1, 0.2]}\n", element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].position = [0.1, 0.2] (" + At(text, "[0.1") +
                        "): must be a list of 3 numbers [x, y, z]: the scenario has dimensions: "
                        "3"));
  // a velocity, and each coordinate's range as the number's on a line
  text =
      Network("2", "  - {name: load, mass: 1.0, position: [0.1, 0.2], velocity: 1.5}\n", element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].velocity = 1.5 (" + At(text, "1.5") +
                        "): must be a list of 2 numbers [vx, vy]: the scenario has dimensions: "
                        "2"));
  text = Network("2", "  - {name: load, mass: 1.0, position: [0.1, 5000.0]}\n", element);
  EXPECT_THAT(PartsError(text), HasSubstr("nodes[0].position[1] = 5000.0 (" + At(text, "5000") +
                                          "): must be from -1000 to 1000 [m]"));
  text = Network("3", "  - {name: load, mass: 1.0, position: [0, 0, 0], velocity: [0, 0, x]}\n",
                 element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].velocity[2] = x (" + At(text, "x]") + "): must be a number"));
  text =
      Network("2", "  - {name: load, mass: 1.0, position: [0, 0], velocity: [0, 2e3]}\n", element);
  EXPECT_THAT(PartsError(text), HasSubstr("nodes[0].velocity[1] = 2e3 (" + At(text, "2e3") +
                                          "): must be from -1000 to 1000 [m/s]"));
}

TEST(SpatialNetworkYaml, APrescribedNodeHasOneMotionPerCoordinate) {
  const std::string element = "  - {name: s, type: spring, from: wall, to: load}\n";
  std::string text =
      Network("2", "  - {name: arm, prescribed: {type: constant, value: 0.1}}\n", element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].prescribed = {type: constant, value: 0.1} (" + At(text, "{type") +
                        "): must be a list of 2 motions [x(t), y(t)], each a waveform (constant, "
                        "ramp, sine or table): the scenario has dimensions: 2"));
  text = Network("",
                 "  - {name: arm, prescribed: [{type: constant, value: 0.1},"
                 " {type: constant, value: 0.2}]}\n",
                 element);
  EXPECT_THAT(PartsError(text),
              HasSubstr("nodes[0].prescribed = [{type: constant, value: 0.1}, {type: constant, "
                        "value: 0.2}] (" +
                        At(text, "[{") + "): must be one motion (a waveform) in 1 dimension"));
  // each motion read as the one motion on a line: continuous, its errors at its index
  text = Network("2",
                 "  - {name: arm, prescribed: [{type: constant, value: 0.1},"
                 " {type: step, time: 0.5, before: 0.0, after: 0.1}]}\n",
                 element);
  EXPECT_THAT(PartsError(text), HasSubstr("nodes[0].prescribed[1].type = step (" +
                                          At(text, "step") + "): must be continuous in time"));
  text = Network("3",
                 "  - {name: arm, prescribed: [{type: constant, value: 0.1},"
                 " {type: constant, value: 0.2}, {type: constant, value: 2000.0}]}\n",
                 element);
  EXPECT_THAT(PartsError(text), HasSubstr("nodes[0].prescribed[2].value = 2000.0 (" +
                                          At(text, "2000") + "): must be from -1000 to 1000 [m]"));
}

TEST(SpatialNetworkYaml, ViaPointsAreNamesOrCoordinatesAndNeedAPlaneOrSpace) {
  const std::string nodes =
      "  - {name: wall, fixed: [0.0, 0.0]}\n"
      "  - {name: load, mass: 1.0, position: [1.0, 0.0]}\n";
  const auto with_via = [&](const std::string& dimensions, const std::string& via) {
    return Network(dimensions, dimensions.empty() ? "  - {name: wall, fixed: 0.0}\n" : nodes,
                   "  - {name: s, type: spring, from: wall, to: load, stiffness: 1.0,"
                   " rest_length: 0.5, via: " +
                       via + "}\n");
  };
  std::string text = with_via("", "[[0.5, 0.5]]");
  EXPECT_THAT(PartsError(text),
              HasSubstr("elements[0].via = [[0.5, 0.5]] (" + At(text, "[[") +
                        "): via points need dimensions: 2 or 3 at the top level"));
  text = with_via("2", "wall");
  EXPECT_THAT(PartsError(text),
              HasSubstr("elements[0].via = wall (" + At(text, "wall}") +
                        "): must be a list of via points, each a node's name or a fixed point, "
                        "a list of 2 numbers [x, y]"));
  text = with_via("2", "[[0.5, 0.5], [0.5, 0.5, 0.5]]");
  EXPECT_THAT(PartsError(text),
              HasSubstr("elements[0].via[1] = [0.5, 0.5, 0.5] (" + At(text, "[0.5, 0.5, 0.5]") +
                        "): must be a list of 2 numbers [x, y]: the scenario has dimensions: 2"));
  text = with_via("2", "[wall, {x: 1.0}]");
  EXPECT_THAT(PartsError(text),
              HasSubstr("elements[0].via[1] = {x: 1.0} (" + At(text, "{x") +
                        "): must be a node's name or a fixed point, a list of 2 numbers [x, y]"));
  text = with_via("2", "[\"\"]");
  EXPECT_THAT(PartsError(text), HasSubstr("elements[0].via[0] = \"\" (" + At(text, "\"\"") +
                                          "): must be a node's name or a fixed point"));
  text = with_via("2", "[[0.5, 4000.0]]");
  EXPECT_THAT(PartsError(text), HasSubstr("elements[0].via[0][1] = 4000.0 (" + At(text, "4000") +
                                          "): must be from -1000 to 1000 [m]"));
}

TEST(SpatialNetworkYaml, ALoadActsAlongADirectionOnlyInAPlaneOrSpace) {
  const std::string element =
      "  - {name: s, type: spring, from: wall, to: load, stiffness: 1.0, rest_length: 0.1}\n";
  const std::string line_nodes = "  - {name: load, mass: 1.0, position: 0.1}\n";
  const std::string plane_nodes = "  - {name: load, mass: 1.0, position: [0.1, 0.0]}\n";
  std::string text = Network("", line_nodes, element,
                             "  - {node: load, type: constant, value: 1.0, direction: [1, 0]}\n");
  EXPECT_THAT(PartsError(text),
              HasSubstr("loads[0].direction = [1, 0] (" + At(text, "[1, 0]") +
                        "): needs dimensions: 2 or 3 at the top level (on a line a load acts "
                        "along x)"));
  text = Network("2", plane_nodes, element, "  - {node: load, type: constant, value: 1.0}\n");
  EXPECT_THAT(PartsError(text),
              HasSubstr("loads[0].direction (" + At(text, "{node") +
                        "): missing required key: in 2 dimensions a load acts along a "
                        "direction, a list of 2 numbers [dx, dy]"));
  text = Network("2", plane_nodes, element,
                 "  - {node: load, type: mass, mass: 1.0, direction: [0, 0]}\n");
  EXPECT_THAT(PartsError(text),
              HasSubstr("loads[0].direction = [0, 0] (" + At(text, "[0, 0]") +
                        "): must not be zero: the load acts along it, made a unit vector"));
  text = Network("3", "  - {name: load, mass: 1.0, position: [0.1, 0.0, 0.0]}\n", element,
                 "  - {node: load, type: constant, value: 1.0, direction: [0, 1]}\n");
  EXPECT_THAT(PartsError(text),
              HasSubstr("loads[0].direction = [0, 1] (" + At(text, "[0, 1]") +
                        "): must be a list of 3 numbers [dx, dy, dz]: the scenario has "
                        "dimensions: 3"));
  // a misspelt key still lists the keys a load may have, its node and direction among them
  text = Network("2", plane_nodes, element,
                 "  - {node: load, type: constant, value: 1.0, direktion: [0, 1]}\n");
  EXPECT_THAT(PartsError(text), HasSubstr("loads[0].direktion (" + At(text, "direktion") +
                                          "): unknown key; allowed here: type, value, node, "
                                          "direction"));
}

// The system's errors name paths such as "elements[1].via[0]" and "nodes[0].position[1]": the
// reader relocates them (yaml::ValidateAt) to the entry of the list they index.
TEST(SpatialNetworkYaml, TheSystemsErrorsAtCoordinatesAndViaPointsFindTheirEntry) {
  const yaml::Source src{kFile};
  const Document root = yaml::Parse(kFile, kPlanar);
  const auto relocated = [&](const std::string& path, const std::string& value) {
    return ErrorOf([&] {
      yaml::ValidateAt(src, root, "", [&] { throw ParameterError(path, value, "the rule"); });
    });
  };
  EXPECT_EQ(relocated("elements[0].via[1]", "pulley"),
            "elements[0].via[1] = pulley (" + At(kPlanar, "pulley]") + "): the rule");
  EXPECT_EQ(relocated("elements[0].via[0][1]", "0.7"),
            "elements[0].via[0][1] = 0.7 (" + At(kPlanar, "0.7") + "): the rule");
  EXPECT_EQ(relocated("nodes[3].position[1]", "0.1"),
            "nodes[3].position[1] = 0.1 (" + At(kPlanar, "0.1]") + "): the rule");
  EXPECT_EQ(relocated("nodes[2].prescribed[1].phase", "0.25"),
            "nodes[2].prescribed[1].phase = 0.25 (" + At(kPlanar, "0.25") + "): the rule");
  EXPECT_EQ(relocated("loads[0].direction", "[0.0, -2.0]"),
            "loads[0].direction = [0.0, -2.0] (" + At(kPlanar, "[0.0, -2.0]") + "): the rule");
}

TEST(SpatialNetworkYaml, TheNewTopLevelKeysAreNetworkKeys) {
  // a misspelt one is an unknown key, and the list of allowed keys names them
  const std::string path = WriteTempFile(
      "misspelt.yaml", "dimension: 2\nnodes: []\nelements: []\ntime: {start: 0.0, end: 1.0}\n");
  EXPECT_THAT(testing::InputErrorOf(path, [&] { LoadScenario(path); }),
              HasSubstr("dimension (FILE:1:1): unknown key; allowed here: name, models, nodes, "
                        "elements, loads, time, solver, output, limits, sensitivities, "
                        "controllers, dimensions, gravity"));
}

// ---- whole files, read and built: these depend on the engine in 2 and 3 dimensions ----

TEST(SpatialNetworkFile, APlanarFileReadsAndBuilds) {
  const Scenario s = LoadScenario(WriteTempFile("planar.yaml", kPlanar));
  ExpectPlanar(s);
}

TEST(SpatialNetworkFile, AFileInSpaceReadsAndBuilds) {
  const Scenario s = LoadScenario(WriteTempFile("spatial.yaml", kSpatial));
  ExpectSpatial(s);
}

TEST(SpatialNetworkFile, SetReachesACoordinate) {
  const Scenario s = LoadScenario(WriteTempFile("planar.yaml", kPlanar),
                                  Overrides{"nodes[3].position[1]=0.15", "gravity[1]=-1.62"});
  EXPECT_EQ(s.nodes[3].PositionCoordinates(), (Coordinates{0.4, 0.15, 0.0}));
  EXPECT_EQ(s.space.gravity[1], -1.62);
}

TEST(SpatialNetworkFile, AViaPointNamingNoNodeIsToldAtItsEntry) {
  std::string text = kPlanar;
  text.replace(text.find("pulley]"), 6, "pully");
  const std::string path = WriteTempFile("unknown_via.yaml", text);
  EXPECT_THAT(testing::InputErrorOf(path, [&] { LoadScenario(path); }),
              HasSubstr("elements[0].via[1] = pully (FILE" +
                        At(text, "pully]").substr(std::string(kFile).size())));
}

}  // namespace
}  // namespace musclesim
