// Skeletons in scenario files (docs/guide/skeletons.md): bodies, joints and the points of
// bodies read into their fields, and each broken rule told at its file:line:col with the key,
// the value and the rule.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "musclesim/io/readers/scenario_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

const std::string kElbow = R"(name: elbow
dimensions: 2
gravity: [0.0, -9.81]
bodies:
  - {name: humerus, mass: 2.0, center_of_mass: [0.0, -0.15], inertia: [0.015, 0.002, 0.015, 0.0, 0.0, 0.0]}
  - {name: forearm, mass: 1.2, center_of_mass: [0.0, -0.12], inertia: [0.006, 0.001, 0.006, 0.0, 0.0, 0.0]}
joints:
  - {name: shoulder, type: weld, parent: ground, child: humerus}
  - {name: elbow, type: revolute, parent: humerus, child: forearm, in_parent: {position: [0.0, -0.3]}, value: 0.5, damping: 0.05}
nodes:
  - {name: hand, body: forearm, point: [0.0, -0.25]}
elements:
  - {name: flexor, type: spring, stiffness: 100.0, rest_length: 0.2, from: {body: humerus, point: [0.02, -0.02]}, via: [{body: humerus, point: [0.03, -0.27]}], to: {body: forearm, point: [0.01, -0.04]}}
time: {start: 0.0, end: 0.1}
)";

// "FILE:line:column" of the first `needle` in `text`.
std::string At(const std::string& text, const std::string& needle) {
  return "FILE:" + testing::LineColumn(text, needle);
}

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string ErrorOf(const std::string& name, const std::string& text) {
  const std::string path = WriteTempFile(name, text);
  return InputErrorOf(path, [&] { LoadScenario(path); });
}

TEST(SkeletonFile, BodiesJointsAndBodyPointsReadIntoTheirFields) {
  const Scenario s = LoadScenario(WriteTempFile("elbow.yaml", kElbow));
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[1].name, "forearm");
  EXPECT_EQ(s.bodies[1].mass, 1.2);
  EXPECT_EQ(s.bodies[1].center_of_mass, (Coordinates{0.0, -0.12, 0.0}));
  EXPECT_EQ(s.bodies[1].inertia[2], 0.006);
  ASSERT_EQ(s.joints.size(), 2u);
  EXPECT_EQ(s.joints[0].kind, JointKind::kWeld);
  EXPECT_EQ(s.joints[1].in_parent.position, (Coordinates{0.0, -0.3, 0.0}));
  ASSERT_EQ(s.joints[1].coordinates.size(), 1u);
  EXPECT_EQ(s.joints[1].coordinates[0].name, "elbow");
  EXPECT_EQ(s.joints[1].coordinates[0].value, 0.5);
  EXPECT_EQ(s.joints[1].coordinates[0].damping, 0.05);
  // the element's body points are nodes of their own, after the file's nodes
  ASSERT_EQ(s.nodes.size(), 4u);
  EXPECT_EQ(s.nodes[0].kind, NodeKind::kOnBody);
  EXPECT_EQ(s.nodes[1].name, "flexor.from");
  EXPECT_EQ(s.nodes[2].name, "flexor.to");
  EXPECT_EQ(s.nodes[3].name, "flexor.via1");
  EXPECT_EQ(s.nodes[3].body, "humerus");
  EXPECT_EQ(s.elements[0].from, "flexor.from");
  ASSERT_EQ(s.elements[0].via.size(), 1u);
  EXPECT_EQ(s.elements[0].via[0].node, "flexor.via1");
}

TEST(SkeletonFile, AnInertiaThatIsNotPositiveDefiniteIsToldAtTheBody) {
  const std::string text = Replaced(kElbow, "[0.006, 0.001, 0.006, 0.0, 0.0, 0.0]",
                                    "[0.006, 0.001, 0.006, 0.01, 0.0, 0.0]");
  EXPECT_THAT(ErrorOf("inertia.yaml", text),
              HasSubstr("bodies[1].inertia = [0.006, 0.001, 0.006, 0.01, 0, 0] (" +
                        At(text, "[0.006, 0.001") + "): must be positive definite"));
}

TEST(SkeletonFile, AJointWhoseParentIsItsOwnDescendantIsRefused) {
  std::string text = Replaced(kElbow, "{name: shoulder, type: weld, parent: ground",
                              "{name: shoulder, type: weld, parent: forearm");
  EXPECT_THAT(ErrorOf("cycle.yaml", text),
              HasSubstr("joints[0].parent = forearm (" + At(text, "forearm, child: humerus") +
                        "): is a descendant of the joint's own child humerus"));
}

TEST(SkeletonFile, APathPointOnAnUnknownBodyIsToldAtItsKey) {
  const std::string text = Replaced(kElbow, "to: {body: forearm", "to: {body: radius");
  EXPECT_THAT(ErrorOf("unknown_body.yaml", text),
              HasSubstr("elements[0].to.body = radius (" + At(text, "radius") +
                        "): names no body; the bodies are: humerus, forearm"));
}

TEST(SkeletonFile, AQuaternionThatIsNotUnitIsRefused) {
  const std::string text =
      Replaced(kElbow, "in_parent: {position: [0.0, -0.3]}",
               "in_parent: {position: [0.0, -0.3], orientation: [1.0, 0.0, 0.0, 0.1]}");
  EXPECT_THAT(ErrorOf("quaternion.yaml", text),
              HasSubstr("joints[1].in_parent.orientation = [1, 0, 0, 0.1] (" +
                        At(text, "[1.0, 0.0, 0.0, 0.1]") + "): must be a unit quaternion"));
}

TEST(SkeletonFile, InThePlaneARevoluteAxisMustBeAlongZ) {
  const std::string text =
      Replaced(kElbow, "child: forearm,", "child: forearm, axis: [1.0, 0.0, 0.0],");
  EXPECT_THAT(ErrorOf("axis.yaml", text),
              HasSubstr("joints[1].axis = [1, 0, 0] (" + At(text, "[1.0, 0.0, 0.0]") +
                        "): must be along z in 2 dimensions"));
}

TEST(SkeletonFile, BodiesNeedTwoOrThreeDimensions) {
  const std::string text =
      Replaced(Replaced(kElbow, "dimensions: 2\n", ""), "gravity: [0.0, -9.81]\n", "");
  EXPECT_THAT(ErrorOf("line.yaml", text), HasSubstr("bodies = [{name: humerus"));
  EXPECT_THAT(ErrorOf("line.yaml", text), HasSubstr("need dimensions: 2 or 3"));
}

TEST(SkeletonFile, ABodyOfNoJointIsRefused) {
  const std::string text =
      Replaced(kElbow,
               "  - {name: elbow, type: revolute, parent: humerus, child: forearm, in_parent: "
               "{position: [0.0, -0.3]}, value: 0.5, damping: 0.05}\n",
               "");
  EXPECT_THAT(ErrorOf("unjoined.yaml", text),
              HasSubstr("bodies[1].name = forearm (" + At(text, "forearm, mass") +
                        "): is the child of no joint"));
}

const std::string kPulley = R"(name: pulley
dimensions: 2
bodies:
  - {name: link, mass: 0.2, center_of_mass: [0.0, -0.15], inertia: [0.0015, 0.00001, 0.0015, 0.0, 0.0, 0.0]}
joints:
  - {name: joint, type: revolute, child: link}
wraps:
  - {name: pulley, type: cylinder, body: ground, center: [0.0, 0.0], radius: 0.02, side: -y}
nodes:
  - {name: anchor, fixed: [0.02, 0.2228]}
elements:
  - {name: cable, type: spring, stiffness: 100.0, rest_length: 0.2, from: {body: link, point: [-0.0458, -0.02]}, via: [{wrap: pulley}], to: anchor}
time: {start: 0.0, end: 0.1}
)";

TEST(SkeletonFile, AWrapSurfaceAndAPathOverItReadIntoTheirFields) {
  const Scenario s = LoadScenario(WriteTempFile("pulley.yaml", kPulley));
  ASSERT_EQ(s.wraps.size(), 1u);
  EXPECT_EQ(s.wraps[0].radius, 0.02);
  EXPECT_EQ(s.wraps[0].side, WrapSide::kMinusY);
  EXPECT_EQ(s.wraps[0].body, "ground");
  ASSERT_EQ(s.elements[0].via.size(), 1u);
  EXPECT_EQ(s.elements[0].via[0].wrap, "pulley");
}

TEST(SkeletonFile, AWrapRadiusThatIsNotPositiveIsToldAtItsKey) {
  const std::string text = Replaced(kPulley, "radius: 0.02", "radius: 0.0");
  EXPECT_THAT(ErrorOf("radius.yaml", text),
              HasSubstr("wraps[0].radius = 0.0 (" + At(text, "0.0, side") +
                        "): must be > 0 and <= 1000 [m]"));
}

TEST(SkeletonFile, APathPointInsideItsWrapSurfaceIsRefused) {
  const std::string text = Replaced(kPulley, "point: [-0.0458, -0.02]", "point: [-0.01, -0.01]");
  EXPECT_THAT(ErrorOf("inside.yaml", text),
              HasSubstr("elements[0].via[0].wrap = pulley (" + At(text, "pulley}") +
                        "): the path's point before it is 0.01414213562373095 m from the "
                        "cylinder's axis at the start, inside its radius 0.02 m"));
}

TEST(SkeletonFile, AnUnknownWrapSurfaceIsToldAtTheViaPoint) {
  const std::string text = Replaced(kPulley, "{wrap: pulley}", "{wrap: sheave}");
  EXPECT_THAT(ErrorOf("unknown_wrap.yaml", text),
              HasSubstr("elements[0].via[0].wrap = sheave (" + At(text, "sheave") +
                        "): names no wrap surface"));
}

}  // namespace
}  // namespace musclesim
