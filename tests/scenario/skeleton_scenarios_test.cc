// Skeletons (docs/model.md 15) against independent computations: the pendulum link's period
// against the elliptic integral of the physical pendulum and its energy, written here from the
// link's mass, centre of mass and inertia; the double pendulum's energy and trajectory against
// a Lagrangian reference computed by SciPy (tests/fixtures/double_pendulum_reference.py); a
// path over a joint: its moment arm against a central difference of its length over the
// angle, and the torque its tension puts on the joint against that moment arm.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "musclesim/scenario/run_columns.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/simulation.h"
#include "support/numeric.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

constexpr double kGravity = 9.81;

NetworkRunResult RunToEnd(const Scenario& scenario) {
  Simulation simulation;
  NetworkRunResult run = simulation.Run(scenario.Build(), scenario.solver, scenario.Request());
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  return run;
}

// Times where `values` crosses zero upwards, by linear interpolation between rows.
std::vector<double> UpwardCrossings(const std::vector<double>& times,
                                    const std::vector<double>& values) {
  std::vector<double> crossings;
  for (std::size_t r = 1; r < times.size(); ++r) {
    if (values[r - 1] < 0.0 && values[r] >= 0.0) {
      crossings.push_back(times[r - 1] +
                          (times[r] - times[r - 1]) * -values[r - 1] / (values[r] - values[r - 1]));
    }
  }
  return crossings;
}

// ---- pendulum_link.yaml ---------------------------------------------------------------------

TEST(PendulumLink, SwingsWithThePhysicalPendulumsPeriodAndKeepsItsEnergy) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("pendulum_link.yaml"));
  ASSERT_EQ(scenario.bodies.size(), 1u);
  const Body& link = scenario.bodies[0];
  const double d = -link.center_of_mass[1];                  // hinge to centre of mass [m]
  const double pivot = link.inertia[2] + link.mass * d * d;  // about the hinge [kg m^2]
  const double omega0 = std::sqrt(link.mass * kGravity * d / pivot);
  const double amplitude = scenario.joints[0].coordinates[0].value;
  const double period = 4.0 * testing::EllipticK(std::sin(amplitude / 2.0)) / omega0;

  const NetworkRunResult run = RunToEnd(scenario);
  std::vector<double> speed, energy;
  for (const NetworkSample& s : run.samples) {
    speed.push_back(s.speeds[0]);
    // E = 1/2 I_pivot u^2 + m g (height of the centre of mass), the height -d cos q
    energy.push_back(0.5 * pivot * s.speeds[0] * s.speeds[0] -
                     link.mass * kGravity * d * std::cos(s.coordinates[0]));
  }
  const std::vector<double> crossings = UpwardCrossings(run.times, speed);
  ASSERT_GE(crossings.size(), 3u);
  // the crossing interpolated linearly on a 1 ms grid: about 1e-7 s of error each
  EXPECT_NEAR(crossings[1] - crossings[0], period, 1e-6 * period);
  EXPECT_NEAR(crossings[2] - crossings[1], period, 1e-6 * period);
  const double scale = link.mass * kGravity * d;
  for (const double e : energy) EXPECT_NEAR(e, energy.front(), 1e-8 * scale);
  // the tip node moves with the link: at distance 1 m from the hinge, below it by cos q
  for (std::size_t r = 0; r < run.samples.size(); r += 500) {
    const NetworkSample& s = run.samples[r];
    EXPECT_NEAR(s.position[0], std::sin(s.coordinates[0]), 1e-12);
    EXPECT_NEAR(s.position[1], -std::cos(s.coordinates[0]), 1e-12);
  }
}

// ---- double_pendulum.yaml -------------------------------------------------------------------

struct Row {
  double t, q1, q2, u1, u2;
};

std::vector<Row> ReadReference() {
  std::ifstream in(testing::FixturePath("double_pendulum_reference.csv"));
  std::string line;
  std::getline(in, line);  // the header
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    Row row{};
    char comma = 0;
    fields >> row.t >> comma >> row.q1 >> comma >> row.q2 >> comma >> row.u1 >> comma >> row.u2;
    rows.push_back(row);
  }
  return rows;
}

TEST(DoublePendulum, FollowsAnIndependentLagrangianReferenceAndKeepsItsEnergy) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("double_pendulum.yaml"));
  const NetworkRunResult run = RunToEnd(scenario);
  const std::vector<Row> reference = ReadReference();
  ASSERT_EQ(reference.size(), 31u);
  // the run's rows every 0.01 s, the reference's every 0.1 s
  for (const Row& row : reference) {
    const std::size_t r = static_cast<std::size_t>(std::lround(row.t / 0.01));
    ASSERT_NEAR(run.times[r], row.t, 1e-12);
    const NetworkSample& s = run.samples[r];
    EXPECT_NEAR(s.coordinates[0], row.q1, 1e-7) << row.t;
    EXPECT_NEAR(s.coordinates[1], row.q2, 1e-7) << row.t;
    EXPECT_NEAR(s.speeds[0], row.u1, 1e-7) << row.t;
    EXPECT_NEAR(s.speeds[1], row.u2, 1e-7) << row.t;
  }
  // the energy of the reference's Lagrangian, from the file's masses and inertias
  const Body& upper = scenario.bodies[0];
  const Body& lower = scenario.bodies[1];
  const double c1 = -upper.center_of_mass[1], c2 = -lower.center_of_mass[1];
  const double l1 = -scenario.joints[1].in_parent.position[1];
  const auto energy = [&](const NetworkSample& s) {
    const double th1 = s.coordinates[0], th2 = s.coordinates[0] + s.coordinates[1];
    const double w1 = s.speeds[0], w2 = s.speeds[0] + s.speeds[1];
    const double kinetic =
        0.5 * (upper.mass * c1 * c1 + upper.inertia[2]) * w1 * w1 +
        0.5 * lower.inertia[2] * w2 * w2 +
        0.5 * lower.mass *
            (l1 * l1 * w1 * w1 + c2 * c2 * w2 * w2 + 2.0 * l1 * c2 * w1 * w2 * std::cos(th1 - th2));
    const double potential = -upper.mass * kGravity * c1 * std::cos(th1) -
                             lower.mass * kGravity * (l1 * std::cos(th1) + c2 * std::cos(th2));
    return kinetic + potential;
  };
  const double e0 = energy(run.samples.front());
  for (const NetworkSample& s : run.samples) EXPECT_NEAR(energy(s), e0, 1e-8);
}

// ---- a path over a joint ----------------------------------------------------------------------

// A forearm on a revolute elbow at the origin, its centre of mass on the axis (no gravity
// torque), and a spring from a fixed point of the ground over a via point of the ground to a
// point of the forearm: a flexor whose moment arm changes with the angle.
NetworkSystem ElbowWithSpring(double stiffness) {
  Body forearm{"forearm", 1.5, {0.0, 0.0, 0.0}, {0.01, 0.002, 0.012, 0.0, 0.0, 0.0}};
  Joint elbow = Joint::Make("elbow", JointKind::kRevolute, "ground", "forearm");
  auto skeleton = std::make_shared<const Skeleton>(std::vector<Body>{forearm},
                                                   std::vector<Joint>{elbow}, Coordinates{});
  std::vector<Node> nodes{Node::Fixed("origin", Coordinates{-0.3, 0.02, 0.0}),
                          Node::OnBody("insertion", "forearm", {0.05, 0.03, 0.0})};
  Element spring = Element::Spring("flexor", "origin", "insertion", stiffness, 0.1);
  spring.via = {ViaPoint::Fixed({-0.02, 0.04, 0.0})};
  return NetworkSystem(nodes, {spring}, {}, {}, Space{2, {}}, skeleton);
}

TEST(PathOverAJoint, MomentArmIsMinusTheLengthsDerivativeAndMakesTheTorque) {
  const double stiffness = 200.0;
  const NetworkSystem system = ElbowWithSpring(stiffness);
  ASSERT_NE(system.skeleton(), nullptr);
  const int s = system.skeleton_state();
  ASSERT_TRUE(system.Spans(0, 0));
  const double izz = system.skeleton()->bodies()[0].inertia[2];
  for (const double angle : {-0.8, -0.2, 0.0, 0.4, 1.1, 1.9}) {
    std::vector<double> y(static_cast<std::size_t>(system.state_size()), 0.0);
    y[s] = angle;
    NetworkSample sample;
    system.Observe(0.0, y.data(), sample);
    const double h = 1e-5;
    std::vector<double> plus = y, minus = y;
    plus[s] += h;
    minus[s] -= h;
    const double dl =
        (system.Length(0, 0.0, plus.data()) - system.Length(0, 0.0, minus.data())) / (2.0 * h);
    EXPECT_NEAR(sample.moment_arms[0], -dl, 1e-8) << angle;
    // u' = tau / I with tau = r T, no gravity and no other force
    std::vector<double> ydot(y.size());
    system.RightHandSide(0.0, y.data(), ydot.data());
    const double tension = stiffness * (system.Length(0, 0.0, y.data()) - 0.1);
    EXPECT_NEAR(ydot[s + 1], -dl * tension / izz, 1e-6 * std::abs(dl * tension / izz)) << angle;
    EXPECT_EQ(ydot[s], 0.0);  // q' = u = 0
  }
}

// A spring from the ground over a cylinder about the elbow's axis (radius 2 cm, on the upper
// arm: the ground) to a point of the forearm 6 cm out: as the elbow turns clockwise from 0,
// the straight line from the origin to the insertion sweeps across the cylinder (through its
// axis near -0.46 rad), and the path starts wrapping.
NetworkSystem ElbowOverCylinder(WrapSide side, int dimensions = 2, double height = 0.0) {
  Body forearm{"forearm", 1.5, {0.0, 0.0, 0.0}, {0.01, 0.002, 0.012, 0.0, 0.0, 0.0}};
  Joint elbow = Joint::Make("elbow", JointKind::kRevolute, "ground", "forearm");
  WrapCylinder cylinder{"condyle", "ground", {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.02, side};
  auto skeleton =
      std::make_shared<const Skeleton>(std::vector<Body>{forearm}, std::vector<Joint>{elbow},
                                       Coordinates{}, std::vector<WrapCylinder>{cylinder});
  std::vector<Node> nodes{Node::Fixed("origin", Coordinates{-0.3, 0.15, height}),
                          Node::OnBody("insertion", "forearm", {0.06, 0.0, 0.0})};
  Element spring = Element::Spring("flexor", "origin", "insertion", 200.0, 0.1);
  spring.via = {ViaPoint::Wrap("condyle")};
  return NetworkSystem(nodes, {spring}, {}, {}, Space{dimensions, {}}, skeleton);
}

TEST(WrapCylinder, LengthAndMomentArmAreContinuousWhereThePathStartsToWrap) {
  const NetworkSystem system = ElbowOverCylinder(WrapSide::kAll);
  const int s = system.skeleton_state();
  const auto length = [&](double q) {
    std::vector<double> y(static_cast<std::size_t>(system.state_size()), 0.0);
    y[s] = q;
    return system.Length(0, 0.0, y.data());
  };
  const auto arm = [&](double q) {
    std::vector<double> y(static_cast<std::size_t>(system.state_size()), 0.0);
    y[s] = q;
    NetworkSample sample;
    system.Observe(0.0, y.data(), sample);
    return sample.moment_arms[0];
  };
  // the insertion at 6 cm and angle q, the origin to the left and above: the straight line
  // touches the cylinder where its distance from the axis is the radius
  double lo = 0.0, hi = -0.4;  // straight at 0 (the line passes above), wrapped at -0.4
  const auto straight_length = [&](double q) {
    return std::hypot(0.06 * std::cos(q) + 0.3, 0.06 * std::sin(q) - 0.15);
  };
  ASSERT_NEAR(length(0.0), straight_length(0.0), 1e-15);
  ASSERT_GT(length(hi) - straight_length(hi), 1e-4);  // wrapped: longer than the chord
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (length(mid) - straight_length(mid) > 0.0 ? hi : lo) = mid;
  }
  const double touch = 0.5 * (lo + hi);
  // continuous in value and slope across the touch: their steps across it shrink with its
  // width (a jump would not): the length's as 2 h r (r about 2 cm), the arm's as 2 h r'
  for (const double h : {1e-3, 1e-5, 1e-7}) {
    EXPECT_NEAR(length(touch + h), length(touch - h), 0.1 * h) << h;
    EXPECT_NEAR(arm(touch + h), arm(touch - h), 0.1 * h) << h;
  }
  // and the moment arm -dl/dq on both sides, wrapped or not, and far into the wrap
  for (const double q : {0.2, touch + 0.05, touch - 0.05, -0.35, -0.6, -1.0}) {
    const double h = 1e-6;
    EXPECT_NEAR(arm(q), -(length(q + h) - length(q - h)) / (2 * h), 1e-8) << q;
  }
}

TEST(WrapCylinder, OneSidedItKeepsThePathOnItsSide) {
  // side -y: the path goes under the cylinder even where its straight line passes above
  const NetworkSystem below = ElbowOverCylinder(WrapSide::kMinusY);
  const NetworkSystem any = ElbowOverCylinder(WrapSide::kAll);
  std::vector<double> y(static_cast<std::size_t>(below.state_size()), 0.0);
  // the tangent lengths and the arc under the cylinder from angle pi to 2 pi + 0, closed form:
  // origin (-0.3, 0.15), insertion (0.06, 0) at angle 0
  const double r = 0.02, dp = std::hypot(0.3, 0.15), ds = 0.06;
  const double arc_start = std::atan2(0.15, -0.3) + std::acos(r / dp);  // counterclockwise
  const double arc_end = 2.0 * std::numbers::pi - std::acos(r / ds);
  const double expected =
      std::sqrt(dp * dp - r * r) + r * (arc_end - arc_start) + std::sqrt(ds * ds - r * r);
  EXPECT_NEAR(below.Length(0, 0.0, y.data()), expected, 1e-14);
  EXPECT_NEAR(any.Length(0, 0.0, y.data()), std::hypot(0.36, 0.15), 1e-15);
  // in space, the origin 5 cm up the axis: unrolled, the path is one straight line, of the
  // planar length and the rise
  const NetworkSystem helix = ElbowOverCylinder(WrapSide::kMinusY, 3, 0.05);
  std::vector<double> z(static_cast<std::size_t>(helix.state_size()), 0.0);
  EXPECT_NEAR(helix.Length(0, 0.0, z.data()), std::hypot(expected, 0.05), 1e-14);
  NetworkSample sample;
  helix.Observe(0.0, z.data(), sample);
  const double h = 1e-6;
  std::vector<double> plus = z, minus = z;
  plus[helix.skeleton_state()] += h;
  minus[helix.skeleton_state()] -= h;
  EXPECT_NEAR(sample.moment_arms[0],
              -(helix.Length(0, 0.0, plus.data()) - helix.Length(0, 0.0, minus.data())) / (2 * h),
              1e-8);
}

TEST(WrapCylinder, OnAMovingBodyItsTangentPointsMoveAndPushWithIt) {
  // the cylinder on the forearm, off the elbow's axis: as the forearm turns, the surface and
  // the tangent points on it move, and the forces there act on the forearm
  Body forearm{"forearm", 1.5, {0.0, 0.0, 0.0}, {0.01, 0.002, 0.012, 0.0, 0.0, 0.0}};
  Joint elbow = Joint::Make("elbow", JointKind::kRevolute, "ground", "forearm");
  WrapCylinder bump{"bump", "forearm", {0.03, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.015, WrapSide::kAll};
  auto skeleton =
      std::make_shared<const Skeleton>(std::vector<Body>{forearm}, std::vector<Joint>{elbow},
                                       Coordinates{}, std::vector<WrapCylinder>{bump});
  std::vector<Node> nodes{Node::Fixed("origin", Coordinates{-0.2, 0.05, 0.0}),
                          Node::OnBody("insertion", "forearm", {0.08, -0.01, 0.0})};
  const double stiffness = 300.0;
  Element spring = Element::Spring("flexor", "origin", "insertion", stiffness, 0.1);
  spring.via = {ViaPoint::Wrap("bump")};
  const NetworkSystem system(nodes, {spring}, {}, {}, Space{2, {}}, skeleton);
  const int s = system.skeleton_state();
  const double izz = forearm.inertia[2];
  for (const double angle : {-0.1, 0.0, 0.1, 0.2}) {
    std::vector<double> y(static_cast<std::size_t>(system.state_size()), 0.0);
    y[s] = angle;
    std::vector<double> plus = y, minus = y;
    const double h = 1e-6;
    plus[s] += h;
    minus[s] -= h;
    const double length = system.Length(0, 0.0, y.data());
    const double straight = std::hypot(0.08 * std::cos(angle) + 0.01 * std::sin(angle) + 0.2,
                                       0.08 * std::sin(angle) - 0.01 * std::cos(angle) - 0.05);
    EXPECT_GT(length, straight + 1e-5) << angle;  // it wraps
    const double dl =
        (system.Length(0, 0.0, plus.data()) - system.Length(0, 0.0, minus.data())) / (2 * h);
    NetworkSample sample;
    system.Observe(0.0, y.data(), sample);
    EXPECT_NEAR(sample.moment_arms[0], -dl, 1e-8) << angle;
    // the forces at the tangent points and the insertion, all on the forearm, turn it by
    // -T dl/dq together
    std::vector<double> ydot(y.size());
    system.RightHandSide(0.0, y.data(), ydot.data());
    const double torque = -stiffness * (length - 0.1) * dl;
    EXPECT_NEAR(ydot[s + 1], torque / izz, 1e-6 * std::abs(torque / izz)) << angle;
  }
}

// ---- elbow_flexion.yaml ---------------------------------------------------------------------

TEST(ElbowFlexion, EachMomentArmAlongTheRunIsMinusTheLengthsDerivative) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("elbow_flexion.yaml"));
  const NetworkSystem system = scenario.Build();
  const NetworkRunResult run = RunToEnd(scenario);
  const int s = system.skeleton_state();
  ASSERT_EQ(system.skeleton()->coordinate_count(), 1);
  // the biceps lifts the forearm: the elbow flexes from 0.5 rad
  EXPECT_GT(run.samples.back().coordinates[0], 0.5 + 0.2);
  for (std::size_t r = 0; r < run.samples.size(); r += 20) {
    std::vector<double> y(static_cast<std::size_t>(system.state_size()), 0.0);
    y[s] = run.samples[r].coordinates[0];
    const double h = 1e-5;
    std::vector<double> plus = y, minus = y;
    plus[s] += h;
    minus[s] -= h;
    for (int e = 0; e < 2; ++e) {
      const double dl =
          (system.Length(e, 0.0, plus.data()) - system.Length(e, 0.0, minus.data())) / (2 * h);
      EXPECT_NEAR(run.samples[r].moment_arms[static_cast<std::size_t>(e)], -dl, 1e-8)
          << system.elements()[e].name << " at " << y[s];
    }
    // the biceps flexes (r > 0), the triceps extends
    EXPECT_GT(run.samples[r].moment_arms[0], 0.0);
    EXPECT_LT(run.samples[r].moment_arms[1], 0.0);
  }
}

// ---- pulley_joint.yaml ----------------------------------------------------------------------

// The pulley joint's closed forms (docs/model.md 15.6), from the file's parts: each cable
// wrapped a quarter turn at angle 0, so its length is l0 -+ r q with l0 = (the anchor's
// height) + r pi/2 + sqrt(|B|^2 - r^2), B the link's point it leaves for.
struct Pulley {
  double r, l0, u_flexor, u_extensor, gravity_torque, pivot_inertia, damping;
  std::shared_ptr<const TensionModel> model;

  explicit Pulley(const Scenario& s) {
    r = s.wraps.at(0).radius;
    const Node& anchor = s.nodes.at(0);
    const Node& leave = s.nodes.at(2);  // flexor.from, on the link
    const double b = std::hypot(leave.position, leave.position_yz[0]);
    l0 = anchor.position_yz[0] + r * std::numbers::pi / 2.0 + std::sqrt(b * b - r * r);
    u_flexor = s.elements.at(0).activation.Evaluate(0.0);
    u_extensor = s.elements.at(1).activation.Evaluate(0.0);
    model = s.elements.at(0).model;
    // the link's and the payload's masses below the joint, at their centres of mass
    const Body& link = s.bodies.at(0);
    const Body& payload = s.bodies.at(1);
    const double drop = -s.joints.at(1).in_parent.position[1];
    gravity_torque = kGravity * (link.mass * -link.center_of_mass[1] + payload.mass * drop);
    pivot_inertia = link.inertia[2] + link.mass * link.center_of_mass[1] * link.center_of_mass[1] +
                    payload.inertia[2] + payload.mass * drop * drop;
    damping = s.joints.at(0).coordinates.at(0).damping;
  }
  // The net torque at rest at angle q [N m]: the cables' r (T_f - T_e), gravity's.
  double Torque(double q) const {
    return r * (model->Evaluate(l0 - r * q, 0.0, u_flexor).total -
                model->Evaluate(l0 + r * q, 0.0, u_extensor).total) -
           gravity_torque * std::sin(q);
  }
};

TEST(PulleyJoint, MomentArmsAreExactlyTheRadiusAndTheJointRestsAtTheClosedFormsAngle) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("pulley_joint.yaml"));
  const Pulley pulley(scenario);
  // the equilibrium, by bisection of the net torque
  double lo = 0.0, hi = 1.2;
  ASSERT_GT(pulley.Torque(lo), 0.0);
  ASSERT_LT(pulley.Torque(hi), 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pulley.Torque(mid) > 0.0 ? lo : hi) = mid;
  }
  const double rest = 0.5 * (lo + hi);
  // the shipped run swings about it with every moment arm exactly +-r
  const NetworkRunResult swing = RunToEnd(scenario);
  for (const NetworkSample& s : swing.samples) {
    EXPECT_NEAR(s.moment_arms[0], pulley.r, 1e-14);
    EXPECT_NEAR(s.moment_arms[1], -pulley.r, 1e-14);
    EXPECT_NEAR(s.elements[0].length, pulley.l0 - pulley.r * s.coordinates[0], 1e-12);
  }
  // started there at rest, it stays
  scenario.joints.at(0).coordinates.at(0).value = rest;
  scenario.t_end = 2.0;
  const NetworkRunResult still = RunToEnd(scenario);
  for (const NetworkSample& s : still.samples) EXPECT_NEAR(s.coordinates[0], rest, 1e-9);
}

TEST(PulleyJoint, SmallOscillationHasTheClosedFormsFrequency) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("pulley_joint.yaml"));
  const Pulley pulley(scenario);
  double lo = 0.0, hi = 1.2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pulley.Torque(mid) > 0.0 ? lo : hi) = mid;
  }
  const double rest = 0.5 * (lo + hi);
  // linearised: I q'' + c q' + k q = 0, k = r^2 (dT_f/dl + dT_e/dl) + (gravity's torque)',
  // c = c_joint - r^2 (dT_f/dv + dT_e/dv) (each cable shortens at r u or lengthens at it)
  const TensionSample f = pulley.model->Evaluate(pulley.l0 - pulley.r * rest, 0.0, pulley.u_flexor);
  const TensionSample e =
      pulley.model->Evaluate(pulley.l0 + pulley.r * rest, 0.0, pulley.u_extensor);
  const double r2 = pulley.r * pulley.r;
  const double k = r2 * (f.d_length + e.d_length) + pulley.gravity_torque * std::cos(rest);
  const double c = pulley.damping - r2 * (f.d_velocity + e.d_velocity);
  const double I = pulley.pivot_inertia;
  const double omega = std::sqrt(k / I - (c / (2.0 * I)) * (c / (2.0 * I)));
  const double period = 2.0 * std::numbers::pi / omega;
  // released 1 mrad off its rest: the nonlinear terms shift the period by about 1e-6
  scenario.joints.at(0).coordinates.at(0).value = rest + 1e-3;
  scenario.t_end = 3.0 * period;
  scenario.output.interval = 1e-4;
  const NetworkRunResult run = RunToEnd(scenario);
  std::vector<double> speed;
  for (const NetworkSample& s : run.samples) speed.push_back(s.speeds[0]);
  const std::vector<double> crossings = UpwardCrossings(run.times, speed);
  ASSERT_GE(crossings.size(), 2u);
  EXPECT_NEAR(crossings[1] - crossings[0], period, 1e-4 * period);
}

// What the skeleton cannot do yet is refused, never computed without the bodies' terms.
TEST(Skeleton, SensitivitiesAndOptimalControlAreRefusedUntilTheirTermsAreDerived) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("pulley_joint.yaml"));
  std::string refusal;
  try {
    SensitivityRun run(scenario, {{"elements[0].activation.value", "", 0.0}});
  } catch (const InputError& e) {
    refusal = e.what();
  }
  EXPECT_THAT(refusal, ::testing::HasSubstr("sensitivities of a scenario with bodies, joints or "
                                            "wrap surfaces are not supported yet"));
  OptimalControlProblem problem;
  problem.scenario = scenario;
  problem.controls = {ControlSpec{"flexor", 0.0, 1.0}};
  refusal.clear();
  try {
    SolveOptimalControl(problem);
  } catch (const InputError& e) {
    refusal = e.what();
  }
  EXPECT_THAT(refusal, ::testing::HasSubstr("cannot be optimised yet"));
}

TEST(PathOverAJoint, TheRunsColumnsNameEachCoordinateAndMomentArm) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("elbow_flexion.yaml"));
  const NetworkSystem system = scenario.Build();
  const RunColumns columns(scenario, system);
  const std::vector<std::string>& names = columns.names();
  const auto has = [&](const char* name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  EXPECT_TRUE(has("elbow.q"));
  EXPECT_TRUE(has("elbow.u"));
  EXPECT_TRUE(has("biceps.moment_arm.elbow"));
  EXPECT_TRUE(has("triceps.moment_arm.elbow"));
  EXPECT_TRUE(has("biceps.to.x"));  // a point of a body, as a node
  // a weld has no coordinate
  EXPECT_FALSE(has("shoulder.q"));
}

}  // namespace
}  // namespace musclesim
