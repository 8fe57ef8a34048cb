// Feedback controllers of networks in the plane and in space (docs/model.md 11 and 12): the
// analytic Jacobian with the controllers' terms (a path's length over via points, an
// actuator's tension, a node's y coordinate) against central differences of the right-hand
// side; a point mass held by an actuator under PI control of its height settling where the
// statics solved here put it; and the refusals of a measured node's coordinate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "support/canonical_actuator.h"
#include "support/canonical_networks.h"
#include "support/difference_jacobian.h"

namespace musclesim {
namespace {

using testing::ExpectJacobianMatchesDifferences;

std::shared_ptr<const TensionModel> Model() { return testing::SharedCanonicalModel(); }

// (x, y) in the plane, (x, y, z) in space.
Coordinates At(int d, double x, double y, double z) { return {x, y, d == 3 ? z : 0.0}; }

// Two free masses under gravity in `d` dimensions, with three controllers:
//   `length`: PID on the path length of `muscle` (a -> fixed via point -> m -> n), driving
//             `muscle` itself, without activation dynamics;
//   `force`:  PI on the tension of `helper` (top -> m -> n, over the node m), driving it
//             through activation dynamics (its activation a column of the measure);
//   `height`: PID on the y coordinate of n, driving `lift` (no activation dynamics, takes
//             level + c) and `drop` (with them, level - c) under co-contraction.
NetworkSystem ControlledSpatialNetwork(int d) {
  const Coordinates g = d == 2 ? Coordinates{0.0, -9.81, 0.0} : Coordinates{0.5, -9.81, 0.3};
  std::vector<Node> nodes = {
      Node::Fixed("a", At(d, 0.0, 0.0, 0.0)),
      Node::Fixed("b", At(d, 0.2, 0.05, 0.04)),
      Node::Fixed("top", At(d, 0.0, -0.02, 0.01)),
      Node::Fixed("ceiling", At(d, 0.1, 0.05, 0.0)),
      Node::Fixed("floor", At(d, 0.08, -0.15, -0.02)),
      Node::Free("m", 0.4, At(d, 0.04, -0.04, 0.01), At(d, 0.1, -0.2, 0.05)),
      Node::Free("n", 0.3, At(d, 0.09, -0.05, -0.01), At(d, -0.05, 0.15, -0.1))};
  const ActivationDynamics lag{0.03, 0.05};
  Element muscle = Element::ControlledActuator("muscle", "a", "n", Model());
  muscle.via = {ViaPoint::Fixed(At(d, 0.02, -0.01, 0.005)), ViaPoint::Node("m")};
  Element helper = Element::ControlledActuator("helper", "top", "n", Model(), lag, 0.4);
  helper.via = {ViaPoint::Node("m")};
  Element spring = Element::Spring("spring", "b", "n", 300.0, 0.1);
  spring.via = {ViaPoint::Fixed(At(d, 0.15, -0.01, 0.0))};
  std::vector<Element> elements = {
      muscle,
      helper,
      spring,
      Element::Damper("damper", "a", "m", 2.0),
      Element::ControlledActuator("lift", "n", "ceiling", Model()),
      Element::ControlledActuator("drop", "floor", "n", Model(), lag, 0.3)};
  Controller length = Controller::Pid("length", {"muscle", "", MeasuredQuantity::kLength},
                                      Waveform::Sine(d == 2 ? 0.108 : 0.111, 0.002, 2.0),
                                      {-100.0, -500.0, -0.5}, "muscle");
  length.feedforward = Waveform::Constant(0.3);
  Controller force = Controller::Pid("force", {"helper", "", MeasuredQuantity::kTension},
                                     Waveform::Constant(30.0), {0.005, 0.1, 0.0}, "helper");
  force.feedforward = Waveform::Constant(0.3);
  Controller height = Controller::CoContracting("height", {"", "n", MeasuredQuantity::kPosition, 1},
                                                Waveform::Constant(-0.048), {20.0, 100.0, 0.2},
                                                {"lift", "drop", Waveform::Constant(0.4)});
  std::vector<NodeLoad> loads = {{"n", Load::Constant(2.0), At(d, 1.0, 1.0, 1.0)}};
  return NetworkSystem(std::move(nodes), std::move(elements), std::move(loads),
                       {length, force, height}, Space{d, g});
}

TEST(SpaceControl, JacobianMatchesDifferencesInThePlaneAndInSpace) {
  for (const int d : {2, 3}) {
    SCOPED_TRACE("dimensions " + std::to_string(d));
    const NetworkSystem system = ControlledSpatialNetwork(d);
    // 2 free nodes, 2 activations, 3 integrals
    ASSERT_EQ(system.state_size(), 2 * 2 * d + 2 + 3);
    std::vector<double> y(static_cast<std::size_t>(system.state_size()));
    system.InitialState(0.0, y.data());
    // integrals away from zero, so that their columns carry weight
    const double integrals[3] = {-1e-4, 0.2, 1e-3};
    for (int k = 0; k < 3; ++k) y[system.IntegralStateIndex(k)] = integrals[k];
    for (const double t : {0.0, 0.1, 0.23}) {
      SCOPED_TRACE("t = " + std::to_string(t));
      // every command strictly between its clamps (else a controller's terms are zero and
      // nothing is checked), and no element at a kink
      NetworkSample sample;
      system.Observe(t, y.data(), sample);
      EXPECT_GT(sample.controllers[0].output, 0.05);
      EXPECT_LT(sample.controllers[0].output, 0.95);
      EXPECT_GT(sample.controllers[1].output, 0.05);
      EXPECT_LT(sample.controllers[1].output, 0.95);
      EXPECT_LT(std::abs(sample.controllers[2].output), 0.35);  // level 0.4 +- c inside (0, 1)
      ASSERT_TRUE(testing::AwayFromKinks(system, t, y, 1e-4));
      ExpectJacobianMatchesDifferences(system, t, y, 1e-7);
    }
  }
}

// The measured values are the path's length, the actuator's tension and the coordinate,
// recomputed here from the state.
TEST(SpaceControl, MeasuresThePathTheTensionAndTheCoordinate) {
  const NetworkSystem system = ControlledSpatialNetwork(3);
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  system.InitialState(0.0, y.data());
  NetworkSample sample;
  system.Observe(0.1, y.data(), sample);
  // free node m holds states 0..5, n 6..11
  const auto distance = [](const double* p, const double* q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                     (p[2] - q[2]) * (p[2] - q[2]));
  };
  const double a[3] = {0.0, 0.0, 0.0}, via[3] = {0.02, -0.01, 0.005};
  const double path = distance(a, via) + distance(via, &y[0]) + distance(&y[0], &y[6]);
  EXPECT_NEAR(sample.controllers[0].measured, path, 1e-15);
  EXPECT_EQ(sample.controllers[1].measured, sample.elements[1].tension);
  EXPECT_EQ(sample.controllers[2].measured, y[7]);
  EXPECT_EQ(sample.controllers[2].error, -0.048 - y[7]);
}

// A 2 kg mass in the plane under gravity, hung from `ceiling` by an actuator at an angle and
// held sideways by a horizontal spring from `wall`; a PI(D) controller on the mass's y
// coordinate drives the actuator. At rest the integral leaves no error (y = 0), and the
// statics decide the rest: the actuator's pull along its direction e = (c - p) / l balances
// the weight in y and the spring in x,
//   T e_y = m g,   T e_x = k x   =>   x = c_x / (1 + c_y k / (m g)),
// and the activation is the one at which the actuator pulls T = m g l / c_y at rest.
TEST(SpaceControl, APointMassHeldAtItsReferenceHeightSettlesWhereTheStaticsPutIt) {
  const double mass = 2.0, gravity = 9.81, k = 500.0;
  const double cx = 0.04, cy = 0.09;  // the ceiling anchor, the reference height 0
  const double ki = 400.0;
  const Controller height = Controller::Pid("height", {"", "load", MeasuredQuantity::kPosition, 1},
                                            Waveform::Constant(0.0), {200.0, ki, 0.5}, "lift");
  testing::NetworkExperiment experiment{
      NetworkSystem({Node::Fixed("ceiling", {cx, cy, 0.0}), Node::Fixed("wall", {-0.1, 0.0, 0.0}),
                     Node::Free("load", mass, {0.0, -0.005, 0.0})},
                    {Element::ControlledActuator("lift", "load", "ceiling", Model()),
                     Element::Spring("spring", "wall", "load", k, 0.1),
                     Element::Damper("damper", "wall", "load", 20.0)},
                    {}, {height}, Space{2, {0.0, -gravity, 0.0}}),
      testing::Span(10.0, 1e-2), testing::Tolerances(1e-10, 1e-12)};
  const NetworkRunResult run = experiment.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const NetworkSample& last = run.samples.back();

  const double x = cx / (1.0 + cy * k / (mass * gravity));
  const double l = std::hypot(cx - x, cy);
  const double tension = mass * gravity * l / cy;
  // T = T_p(l) + u dT/du at rest (linear in u: the active part is u f_iso f_L f_V)
  const TensionSample at_rest = Model()->Evaluate(l, 0.0, 1.0);
  const double u = (tension - at_rest.passive) / at_rest.d_activation;
  ASSERT_GT(u, 0.1);
  ASSERT_LT(u, 0.9);
  // the actuator's tension-velocity slope near v = 0 (regularised over 1e-3 m/s) damps the
  // mass with C ~ 1.5e3 N s/m, so the loop is nearly first order: the poles of
  // C s^2 + A kp s + A ki, A = dT/du e_y ~ 90 N, the slower near -2.5 /s. By 10 s e^-25 of the
  // 5 mm start is left, and the rest is the solver's error, rtol 1e-10 of 0.1 m
  EXPECT_NEAR(last.position[4], x, 1e-8);    // load.x
  EXPECT_NEAR(last.position[5], 0.0, 1e-8);  // load.y at the reference
  EXPECT_NEAR(last.controllers[0].error, 0.0, 1e-8);
  // u from a tension of ~21 N: its error is the positions' times dT/dl / dT/du ~ 1e3 / 1e2
  EXPECT_NEAR(last.controllers[0].output, u, 1e-6);
  EXPECT_NEAR(last.elements[0].activation, u, 1e-6);
  EXPECT_NEAR(last.elements[0].tension, tension, 1e-4);
}

// ---- refusals ---------------------------------------------------------------------------

// The ParameterError path of a network in `d` dimensions measuring `measure`.
std::string PathOfRefusal(int d, Measurement measure) {
  try {
    NetworkSystem({Node::Fixed("ceiling", {0.0, 0.1, 0.0}), Node::Free("load", 1.0, {})},
                  {Element::ControlledActuator("lift", "load", "ceiling", Model())}, {},
                  {Controller::Pid("c", std::move(measure), Waveform::Constant(0.0),
                                   {1.0, 0.0, 0.0}, "lift")},
                  Space{d, {}});
  } catch (const ParameterError& e) {
    return e.path();
  }
  return "accepted";
}

TEST(SpaceControl, AMeasuredNodeNamesOneOfTheNetworksCoordinates) {
  const auto node = [](int coordinate) {
    return Measurement{"", "load", MeasuredQuantity::kPosition, coordinate};
  };
  EXPECT_EQ(PathOfRefusal(2, node(Measurement::kNoCoordinate)),
            "controllers[0].measure.coordinate");
  EXPECT_EQ(PathOfRefusal(3, node(Measurement::kNoCoordinate)),
            "controllers[0].measure.coordinate");
  EXPECT_EQ(PathOfRefusal(2, node(2)), "controllers[0].measure.coordinate");  // z, in the plane
  EXPECT_EQ(PathOfRefusal(1, node(1)), "controllers[0].measure.coordinate");  // y, on a line
  EXPECT_EQ(PathOfRefusal(2, node(1)), "accepted");
  EXPECT_EQ(PathOfRefusal(3, node(2)), "accepted");
  EXPECT_EQ(PathOfRefusal(1, node(0)), "accepted");  // x on a line: the position itself
  EXPECT_EQ(PathOfRefusal(1, node(Measurement::kNoCoordinate)), "accepted");
  // an element has no coordinates, and there are three at most: the controller's own
  // factory refuses them, at its key
  EXPECT_EQ(PathOfRefusal(2, {"lift", "", MeasuredQuantity::kLength, 1}), "measure.coordinate");
  EXPECT_EQ(PathOfRefusal(3, node(3)), "measure.coordinate");
}

}  // namespace
}  // namespace musclesim
