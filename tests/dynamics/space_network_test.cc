// Networks in the plane and in space (docs/model.md 12) against independent computations: the
// analytic Jacobian (with its geometric stiffness) against central differences of the
// right-hand side; a planar network lying on the x axis against the same network on a line
// (section 7); the forces of a path over via points against T times the unit vectors of its
// segments, written out here; and the checks a spatial network makes of its parts.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/network.h"
#include "support/canonical_actuator.h"
#include "support/difference_jacobian.h"

namespace musclesim {
namespace {

using testing::ExpectJacobianMatchesDifferences;

std::shared_ptr<const TensionModel> Model() { return testing::SharedCanonicalModel(); }

// An actuator with activation dynamics, so that its activation is a state.
Element DynamicActuator(std::string name, std::string from, std::string to) {
  ExcitationInput input;
  input.signal = Waveform::Sine(0.5, 0.3, 2.0);
  input.initial_activation = 0.4;
  return Element::Actuator(std::move(name), std::move(from), std::move(to), Model(),
                           std::move(input));
}

// A network in `d` dimensions: two free masses hung from fixed anchors, an actuator over a
// fixed via point and over the other mass, a spring, a damper, a tendon, loads along
// directions, gravity.
NetworkSystem SpatialNetwork(int d) {
  const Coordinates g = d == 2 ? Coordinates{0.0, -9.81, 0.0} : Coordinates{0.5, -9.81, 0.3};
  std::vector<Node> nodes = {
      Node::Fixed("a", {0.0, 0.0, 0.0}), Node::Fixed("b", {0.2, 0.05, d == 3 ? 0.04 : 0.0}),
      Node::Free("m", 0.4, {0.04, -0.04, d == 3 ? 0.01 : 0.0}, {0.1, -0.2, d == 3 ? 0.05 : 0.0}),
      Node::Free("n", 0.3, {0.09, -0.05, d == 3 ? -0.01 : 0.0},
                 {-0.05, 0.15, d == 3 ? -0.1 : 0.0})};
  Element muscle = DynamicActuator("muscle", "a", "n");
  // 0.109 m long in the plane (0.110 m in space): just above its passive slack length
  muscle.via = {ViaPoint::Fixed({0.02, -0.01, d == 3 ? 0.005 : 0.0}), ViaPoint::Node("m")};
  Element cable = Element::LinearTendon("cable", "b", "n", 0.1, 300.0);
  Element spring = Element::Spring("spring", "a", "m", 150.0, 0.05);
  Element damper = Element::Damper("damper", "b", "m", 2.0);
  damper.via = {ViaPoint::Fixed({0.15, -0.01, 0.0})};
  NodeLoad pull{"n", Load::Constant(2.0), {1.0, 1.0, d == 3 ? 1.0 : 0.0}};
  NodeLoad spring_load{"m", Load::Spring(40.0, 0.05), {0.0, 1.0, 0.0}};
  return NetworkSystem(std::move(nodes), {muscle, cable, spring, damper}, {pull, spring_load}, {},
                       Space{d, g});
}

TEST(SpaceNetwork, JacobianMatchesDifferencesInThePlaneAndInSpace) {
  for (const int d : {2, 3}) {
    SCOPED_TRACE("dimensions " + std::to_string(d));
    const NetworkSystem system = SpatialNetwork(d);
    EXPECT_EQ(system.state_size(), 2 * 2 * d + 1);
    std::vector<double> y(static_cast<std::size_t>(system.state_size()));
    system.InitialState(0.0, y.data());
    ASSERT_TRUE(testing::AwayFromKinks(system, 0.1, y, 1e-4));
    ExpectJacobianMatchesDifferences(system, 0.1, y, 1e-7);
  }
}

// The same network in the plane with every node on the x axis, and on a line: the x rows of
// the planar right-hand side are the line's, the y rows zero.
TEST(SpaceNetwork, APlanarNetworkOnTheAxisIsTheNetworkOnALine) {
  const auto build = [](int d) {
    std::vector<Node> nodes = {Node::Fixed("wall", 0.0), Node::Free("m1", 0.5, 0.05, 0.1),
                               Node::Free("m2", 0.7, 0.12, -0.2), Node::Fixed("far", 0.2)};
    std::vector<Element> elements = {DynamicActuator("muscle", "wall", "m1"),
                                     Element::Spring("spring", "m1", "m2", 80.0, 0.06),
                                     Element::LinearTendon("tendon", "m2", "far", 0.05, 500.0),
                                     Element::Damper("damper", "wall", "m2", 1.5)};
    std::vector<NodeLoad> loads = {{"m2", Load::Constant(3.0), {1.0, 0.0, 0.0}}};
    return NetworkSystem(nodes, elements, loads, {}, Space{d, {}});
  };
  const NetworkSystem line = build(1), plane = build(2);
  std::vector<double> y1(static_cast<std::size_t>(line.state_size()));
  std::vector<double> y2(static_cast<std::size_t>(plane.state_size()));
  line.InitialState(0.0, y1.data());
  plane.InitialState(0.0, y2.data());
  // (x, v) per free node on the line; (x, y, vx, vy) in the plane; then the activation
  ASSERT_EQ(y2.size(), 9u);
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(y2[4 * f], y1[2 * f]);
    EXPECT_EQ(y2[4 * f + 2], y1[2 * f + 1]);
    EXPECT_EQ(y2[4 * f + 1], 0.0);
    EXPECT_EQ(y2[4 * f + 3], 0.0);
  }
  std::vector<double> f1(y1.size()), f2(y2.size());
  for (const double t : {0.0, 0.13, 0.4}) {
    line.RightHandSide(t, y1.data(), f1.data());
    plane.RightHandSide(t, y2.data(), f2.data());
    for (int f = 0; f < 2; ++f) {
      EXPECT_NEAR(f2[4 * f], f1[2 * f], 1e-14);
      EXPECT_NEAR(f2[4 * f + 2], f1[2 * f + 1], 1e-12 * (1.0 + std::abs(f1[2 * f + 1])));
      EXPECT_EQ(f2[4 * f + 3], 0.0);
    }
    EXPECT_NEAR(f2[8], f1[4], 1e-14);  // the activation's rate
  }
}

// A cable over a frictionless pulley node: from a fixed anchor, over the free node `p`, to a
// fixed anchor. The cable's tension T pulls p along both segments' unit vectors towards the
// anchors, T (e_in_reversed + e_out), written out here; p also carries its weight.
TEST(SpaceNetwork, APulleyNodeFeelsTheTensionAlongBothSegments) {
  const Coordinates a{0.0, 0.0, 0.0}, b{0.3, 0.1, 0.0}, p{0.12, -0.2, 0.0};
  const double mass = 0.2, g = -9.81, stiffness = 400.0, slack = 0.3;
  Element cable = Element::LinearTendon("cable", "a", "b", slack, stiffness);
  cable.via = {ViaPoint::Node("p")};
  const NetworkSystem system({Node::Fixed("a", a), Node::Fixed("b", b), Node::Free("p", mass, p)},
                             {cable}, {}, {}, Space{2, {0.0, g, 0.0}});
  std::vector<double> y(static_cast<std::size_t>(system.state_size())), f(y.size());
  system.InitialState(0.0, y.data());
  system.RightHandSide(0.0, y.data(), f.data());
  const double to_a[2] = {a[0] - p[0], a[1] - p[1]}, to_b[2] = {b[0] - p[0], b[1] - p[1]};
  const double la = std::hypot(to_a[0], to_a[1]), lb = std::hypot(to_b[0], to_b[1]);
  const double tension = stiffness * (la + lb - slack);
  EXPECT_NEAR(system.Length(0, 0.0, y.data()), la + lb, 1e-15);
  for (int c = 0; c < 2; ++c) {
    const double force = tension * (to_a[c] / la + to_b[c] / lb) + (c == 1 ? mass * g : 0.0);
    EXPECT_NEAR(f[2 + c], force / mass, 1e-12 * std::abs(force / mass)) << "coordinate " << c;
  }
}

TEST(SpaceNetwork, RefusesPartsThatDoNotFit) {
  const auto fails_at = [](const std::function<NetworkSystem()>& build, const std::string& path) {
    try {
      build();
      ADD_FAILURE() << "no error, expected one at " << path;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.path(), path) << e.what();
    }
  };
  const auto nodes = [] {
    return std::vector<Node>{Node::Fixed("a", {0.0, 0.0, 0.0}),
                             Node::Free("m", 1.0, {0.1, 0.0, 0.0})};
  };
  Element via_unknown = Element::Spring("s", "a", "m", 10.0, 0.1);
  via_unknown.via = {ViaPoint::Node("nowhere")};
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {via_unknown}, {}, {}, Space{2, {}});
      },
      "elements[0].via[0]");
  Element via_end = Element::Spring("s", "a", "m", 10.0, 0.1);
  via_end.via = {ViaPoint::Node("m")};
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {via_end}, {}, {}, Space{2, {}});
      },
      "elements[0].via[0]");
  Element twice = Element::Spring("s", "a", "m", 10.0, 0.1);
  twice.via = {ViaPoint::Fixed({0.05, 0.1, 0.0}), ViaPoint::Fixed({0.05, 0.1, 0.0})};
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {twice}, {}, {}, Space{2, {}});
      },
      "elements[0].via[1]");
  Element on_line = Element::Spring("s", "a", "m", 10.0, 0.1);
  on_line.via = {ViaPoint::Fixed({0.05, 0.1, 0.0})};
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {on_line}, {}, {}, Space{1, {}});
      },
      "elements[0].via");
  NodeLoad zero{"m", Load::Constant(1.0), {0.0, 0.0, 1.0}};  // z is not in the plane
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {Element::Spring("s", "a", "m", 10.0, 0.1)}, {zero}, {},
                             Space{2, {}});
      },
      "loads[0].direction");
  fails_at([&] { return NetworkSystem(nodes(), {}, {}, {}, Space{4, {}}); }, "dimensions");
  fails_at(
      [&] {
        return NetworkSystem(nodes(), {}, {}, {}, Space{2, {0.0, 0.0, -9.81}});
      },
      "gravity[2]");
}

TEST(SpaceNetwork, AViaPointOnItsNeighbourIsRefusedAtTheStart) {
  Element spring = Element::Spring("s", "a", "m", 10.0, 0.1);
  spring.via = {ViaPoint::Fixed({0.1, 0.05, 0.0})};  // where m starts
  const NetworkSystem system(
      {Node::Fixed("a", {0.0, 0.0, 0.0}), Node::Free("m", 1.0, {0.1, 0.05, 0.0})}, {spring}, {}, {},
      Space{2, {}});
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  system.InitialState(0.0, y.data());
  try {
    system.CheckInitialState(0.0, y.data());
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "elements[0].via[0]");
    EXPECT_NE(std::string(e.what()).find("segment from the via point (0.1, 0.05) to m"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace musclesim
