// The shipped scenarios in the plane (docs/model.md 12) against independent computations:
// the pendulum's period against the elliptic integral of the rigid pendulum and its energy
// balance with gravity; the suspended mass's equilibrium against a root-find of its force
// balance written here, and its small motion about it against the linearisation's solution
// exp(A t) dy0, A from differences of that force balance.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/simulation.h"
#include "support/numeric.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

NetworkRunResult RunToEnd(const Scenario& scenario) {
  Simulation simulation;
  NetworkRunResult run = simulation.Run(scenario.Build(), scenario.solver, scenario.Request());
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  return run;
}

// ---- planar_pendulum.yaml ------------------------------------------------------------------

constexpr double kBobMass = 1.0, kLink = 1.0, kLinkStiffness = 1e6, kGravity = 9.81;

TEST(PlanarPendulum, SwingsWithTheRigidPendulumsPeriod) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("planar_pendulum.yaml"));
  const NetworkRunResult run = RunToEnd(scenario);
  // the bob (node 1) crossing x = 0 leftwards, by linear interpolation between rows
  std::vector<double> crossings;
  for (std::size_t r = 1; r < run.times.size(); ++r) {
    const double before = run.samples[r - 1].position[2], after = run.samples[r].position[2];
    if (before > 0.0 && after <= 0.0) {
      crossings.push_back(run.times[r - 1] +
                          (run.times[r] - run.times[r - 1]) * before / (before - after));
    }
  }
  ASSERT_GE(crossings.size(), 2u);
  const double amplitude = std::numbers::pi / 3.0;  // released at 60 degrees
  const double exact =
      4.0 * std::sqrt(kLink / kGravity) * testing::EllipticK(std::sin(amplitude / 2.0));
  // the link stretches by m g / k ~ 1e-5 m: the period is the rigid one's to about 1e-5
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    EXPECT_NEAR(crossings[i] - crossings[i - 1], exact, 5e-5 * exact) << "swing " << i;
  }
}

TEST(PlanarPendulum, KeepsItsEnergyWithGravity) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("planar_pendulum.yaml"));
  const NetworkRunResult run = RunToEnd(scenario);
  // E = m |v|^2 / 2 + k (l - L)^2 / 2 - m g . p, with g = (0, -9.81)
  const auto energy = [](const NetworkSample& s) {
    const double vx = s.velocity[2], vy = s.velocity[3], y = s.position[3];
    const double stretch = s.elements[0].length - kLink;
    return 0.5 * kBobMass * (vx * vx + vy * vy) + 0.5 * kLinkStiffness * stretch * stretch +
           kBobMass * kGravity * y;
  };
  const double start = energy(run.samples.front());
  double worst = 0.0;
  for (const NetworkSample& s : run.samples) worst = std::max(worst, std::abs(energy(s) - start));
  // no force but the link's and gravity does work: E is constant to the solver's tolerance
  // (the link's fast stretching mode, 1.2e-5 J at the start, is the most BDF may damp)
  EXPECT_LT(worst, 1e-5 * kBobMass * kGravity * kLink);
}

// ---- suspended_mass.yaml -------------------------------------------------------------------

// The suspended mass's force balance, written here from the file's parts: the three
// actuators' tensions along their unit vectors towards their anchors, plus the weight.
class SuspendedMass {
 public:
  explicit SuspendedMass(const Scenario& s) : scenario_(s) {}

  // The net force [N] at position p [m] and velocity pdot [m/s].
  Eigen::Vector2d Force(const Eigen::Vector2d& p, const Eigen::Vector2d& pdot) const {
    Eigen::Vector2d force(0.0, -mass() * kGravity);
    for (std::size_t e = 0; e < 3; ++e) {
      const Node& anchor = scenario_.nodes[e];
      const Eigen::Vector2d to_anchor = Eigen::Vector2d(anchor.position, anchor.position_yz[0]) - p;
      const double l = to_anchor.norm();
      const Eigen::Vector2d unit = to_anchor / l;
      const double shortening = unit.dot(pdot);  // moving towards the anchor shortens it
      const Element& element = scenario_.elements[e];
      const double u = element.activation.Evaluate(0.0);
      force += element.model->Evaluate(l, shortening, u).total * unit;
    }
    return force;
  }
  double mass() const { return scenario_.nodes[3].mass; }

  // Newton's method on Force(p, 0) = 0 with a difference Jacobian, from the file's start.
  Eigen::Vector2d Equilibrium() const {
    Eigen::Vector2d p(scenario_.nodes[3].position, scenario_.nodes[3].position_yz[0]);
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Eigen::Vector2d f = Force(p, Eigen::Vector2d::Zero());
      if (f.norm() < 1e-12) break;
      p -= Stiffness(p).lu().solve(f);
    }
    return p;
  }
  // dF/dp and dF/dpdot by central differences.
  Eigen::Matrix2d Stiffness(const Eigen::Vector2d& p) const { return Derivative(p, true); }
  Eigen::Matrix2d Damping(const Eigen::Vector2d& p) const { return Derivative(p, false); }

 private:
  Eigen::Matrix2d Derivative(const Eigen::Vector2d& p, bool by_position) const {
    Eigen::Matrix2d d;
    const double h = by_position ? 1e-7 : 1e-6;
    for (int c = 0; c < 2; ++c) {
      Eigen::Vector2d step = Eigen::Vector2d::Zero();
      step[c] = h;
      const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
      d.col(c) = by_position ? (Force(p + step, zero) - Force(p - step, zero)) / (2.0 * h)
                             : (Force(p, step) - Force(p, -step)) / (2.0 * h);
    }
    return d;
  }
  const Scenario& scenario_;
};

TEST(SuspendedMass, HangsStillAtTheRootOfItsForceBalance) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("suspended_mass.yaml"));
  const Eigen::Vector2d p = SuspendedMass(scenario).Equilibrium();
  ASSERT_LT(SuspendedMass(scenario).Force(p, Eigen::Vector2d::Zero()).norm(), 1e-10);
  scenario.parameter("nodes[3].position[0]").Set(scenario, p[0]);
  scenario.parameter("nodes[3].position[1]").Set(scenario, p[1]);
  const NetworkRunResult run = RunToEnd(scenario);
  double drift = 0.0;
  for (const NetworkSample& s : run.samples) {
    drift = std::max(drift, std::hypot(s.position[6] - p[0], s.position[7] - p[1]));
  }
  EXPECT_LT(drift, 1e-9);  // [m]: started at the root, it does not move
}

TEST(SuspendedMass, MovesAboutItsEquilibriumAsItsLinearisationSays) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("suspended_mass.yaml"));
  const SuspendedMass model(scenario);
  const Eigen::Vector2d p = model.Equilibrium();
  // y = (p - p*, pdot): ydot = A y, A = [[0, I], [K / m, C / m]]
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a.block<2, 2>(0, 2) = Eigen::Matrix2d::Identity();
  a.block<2, 2>(2, 0) = model.Stiffness(p) / model.mass();
  a.block<2, 2>(2, 2) = model.Damping(p) / model.mass();
  const Eigen::EigenSolver<Eigen::Matrix4d> modes(a);
  // an oscillation: the motion about the equilibrium swings, lightly damped
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(modes.eigenvalues()[k].real(), 0.0);
    EXPECT_GT(std::abs(modes.eigenvalues()[k].imag()), 5.0 * -modes.eigenvalues()[k].real());
  }
  // started 1e-6 m off the equilibrium: the motion is the linear one to about 1e-6 / 1e-2
  const Eigen::Vector4d y0(1e-6, -0.5e-6, 0.0, 0.0);
  scenario.parameter("nodes[3].position[0]").Set(scenario, p[0] + y0[0]);
  scenario.parameter("nodes[3].position[1]").Set(scenario, p[1] + y0[1]);
  const NetworkRunResult run = RunToEnd(scenario);
  const Eigen::Matrix4cd v = modes.eigenvectors();
  const Eigen::Vector4cd weights = v.lu().solve(y0.cast<std::complex<double>>());
  for (std::size_t r = 0; r < run.times.size(); r += 20) {
    Eigen::Vector4cd y = Eigen::Vector4cd::Zero();
    for (int k = 0; k < 4; ++k) {
      y += weights[k] * std::exp(modes.eigenvalues()[k] * run.times[r]) * v.col(k);
    }
    const NetworkSample& s = run.samples[r];
    EXPECT_NEAR(s.position[6] - p[0], y[0].real(), 1e-3 * y0.norm()) << "t = " << run.times[r];
    EXPECT_NEAR(s.position[7] - p[1], y[1].real(), 1e-3 * y0.norm()) << "t = " << run.times[r];
  }
}

// ---- planar_arm.yaml -----------------------------------------------------------------------

// The arm's geometry, written here: each link's points in the link's own frame (x along the
// link from its proximal joint), placed by the shoulder angle phi and the elbow's flexion
// theta (the forearm's angle from the upper arm's line).
class ArmGeometry {
 public:
  static constexpr double kUpperArm = 0.3;
  // node index -> (link, point in the link's frame); link 0 the upper arm, 1 the forearm
  struct Point {
    int node;
    int link;
    Eigen::Vector2d local;
  };
  static std::vector<Point> Points() {
    return {{1, 0, {0.3, 0.0}},  {2, 0, {0.25, 0.03}}, {3, 0, {0.25, -0.03}},
            {4, 1, {0.25, 0.0}}, {5, 1, {0.04, 0.02}}, {6, 1, {-0.02, -0.02}}};
  }
  static Eigen::Vector2d Place(const Point& point, double phi, double theta) {
    const Eigen::Rotation2Dd upper(phi), fore(phi + theta);
    if (point.link == 0) return upper * point.local;
    return upper * Eigen::Vector2d(kUpperArm, 0.0) + fore * point.local;
  }
  static Eigen::Vector2d At(int node, double phi, double theta) {
    if (node == 0) return Eigen::Vector2d::Zero();  // the shoulder
    for (const Point& point : Points()) {
      if (point.node == node) return Place(point, phi, theta);
    }
    ADD_FAILURE() << "no node " << node;
    return Eigen::Vector2d::Zero();
  }
  // A muscle's length: shoulder -> via point -> insertion (nodes 2 -> 5 or 3 -> 6).
  static double MuscleLength(int via, int insertion, double phi, double theta) {
    return At(via, phi, theta).norm() + (At(insertion, phi, theta) - At(via, phi, theta)).norm();
  }
};

// Puts the scenario's nodes on the rigid arm at (phi, theta), the elbow flexing at 1 rad/s.
void PlaceArm(Scenario& scenario, double phi, double theta) {
  for (const ArmGeometry::Point& point : ArmGeometry::Points()) {
    Node& node = scenario.nodes[static_cast<std::size_t>(point.node)];
    const Eigen::Vector2d p = ArmGeometry::Place(point, phi, theta);
    node.position = p[0];
    node.position_yz[0] = p[1];
    // the forearm turns about the elbow at theta' = 1 rad/s: v = e_z x (p - p_elbow)
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    if (point.link == 1) {
      const Eigen::Vector2d r = p - ArmGeometry::At(1, phi, theta);
      v = Eigen::Vector2d(-r[1], r[0]);
    }
    node.velocity = v[0];
    node.velocity_yz[0] = v[1];
  }
}

TEST(PlanarArm, MomentArmsAreMinusTheGeometrysLengthSlope) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("planar_arm.yaml"));
  struct Muscle {
    const char* name;
    int via, insertion;
    double sign;  // the flexor flexes the elbow (r > 0), the extensor extends it (r < 0), over
                  // 20 to 120 degrees; beyond, the insertions pass their via points
  };
  const Muscle muscles[] = {{"flexor", 2, 5, 1.0}, {"extensor", 3, 6, -1.0}};
  double smallest = 1.0, largest = 0.0;
  for (double phi : {0.0, 0.7, -1.2}) {
    for (double degrees = 20.0; degrees <= 120.0; degrees += 10.0) {
      const double theta = degrees * std::numbers::pi / 180.0;
      PlaceArm(scenario, phi, theta);
      const NetworkSystem system = scenario.Build();
      std::vector<double> y(static_cast<std::size_t>(system.state_size()));
      system.InitialState(y.data());
      for (const Muscle& muscle : muscles) {
        const int e = system.FindElement(muscle.name);
        // with theta' = 1 rad/s and nothing else moving, l' = dl/dtheta
        const double code = -system.LengtheningRate(e, 0.0, y.data());
        const double h = 1e-6;
        const double geometry =
            -(ArmGeometry::MuscleLength(muscle.via, muscle.insertion, phi, theta + h) -
              ArmGeometry::MuscleLength(muscle.via, muscle.insertion, phi, theta - h)) /
            (2.0 * h);
        EXPECT_NEAR(code, geometry, 1e-9) << muscle.name << " at theta " << degrees;
        EXPECT_GT(muscle.sign * code, 0.0) << muscle.name << " at theta " << degrees;
        smallest = std::min(smallest, std::abs(code));
        largest = std::max(largest, std::abs(code));
      }
    }
  }
  // the moment arms change with the angle: the via points make them angle-dependent
  EXPECT_GT(largest, 2.0 * smallest);
}

TEST(PlanarArm, FlexesAsARigidArmOfItsGeometry) {
  const Scenario scenario = LoadScenario(testing::ScenarioPath("planar_arm.yaml"));
  const NetworkRunResult run = RunToEnd(scenario);
  const auto point = [](const NetworkSample& s, int node) {
    return Eigen::Vector2d(s.position[2 * node], s.position[2 * node + 1]);
  };
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a[0] * b[1] - a[1] * b[0];
  };
  const int flexor = 24, extensor = 25;
  ASSERT_EQ(scenario.elements[flexor].name, "flexor");
  ASSERT_EQ(scenario.elements[extensor].name, "extensor");
  double largest_theta = 0.0;
  for (std::size_t r = 0; r < run.samples.size(); ++r) {
    const NetworkSample& s = run.samples[r];
    // the links' angles from the run: the shoulder-elbow and elbow-hand lines
    const Eigen::Vector2d upper = point(s, 1), fore = point(s, 4) - point(s, 1);
    const double phi = std::atan2(upper[1], upper[0]);
    const double theta = std::atan2(cross(upper, fore), upper.dot(fore));
    largest_theta = std::max(largest_theta, theta);
    // every other point where the rigid arm at (phi, theta) has it: the frames deform by
    // T / k, under 1e-4 m for tensions under 100 N
    for (int node = 2; node <= 6; ++node) {
      EXPECT_LT((point(s, node) - ArmGeometry::At(node, phi, theta)).norm(), 2e-4)
          << "node " << node << " at t = " << run.times[r];
    }
    EXPECT_NEAR(s.elements[flexor].length, ArmGeometry::MuscleLength(2, 5, phi, theta), 4e-4)
        << "t = " << run.times[r];
    EXPECT_NEAR(s.elements[extensor].length, ArmGeometry::MuscleLength(3, 6, phi, theta), 4e-4)
        << "t = " << run.times[r];
  }
  // the flexor's rising activation flexes the elbow from its 60 degrees
  EXPECT_GT(largest_theta, 90.0 * std::numbers::pi / 180.0);
}

// ---- lattice.yaml --------------------------------------------------------------------------

TEST(Lattice, BalancesItsEnergyOverTheRun) {
  Scenario scenario = LoadScenario(testing::ScenarioPath("lattice.yaml"));
  // fine rows for the quadrature of the actuators' power, and a tight solution
  scenario.output.interval = 5e-4;
  scenario.solver.rtol = 1e-9;
  scenario.solver.atol = 1e-12;
  const NetworkRunResult run = RunToEnd(scenario);
  const double g = -scenario.space.gravity[1];
  // E = kinetic + springs' + actuators' passive + gravity's; the actuators' active tensions
  // remove P = -sum T_a l' (docs/model.md 7.5, 12.5)
  const auto energy = [&](const NetworkSample& s) {
    double e = 0.0;
    for (std::size_t i = 0; i < scenario.nodes.size(); ++i) {
      const Node& node = scenario.nodes[i];
      if (node.kind != NodeKind::kFree) continue;
      const double vx = s.velocity[2 * i], vy = s.velocity[2 * i + 1];
      e += 0.5 * node.mass * (vx * vx + vy * vy) + node.mass * g * s.position[2 * i + 1];
    }
    for (std::size_t k = 0; k < scenario.elements.size(); ++k) {
      const Element& element = scenario.elements[k];
      const double l = s.elements[k].length;
      if (element.kind == ElementKind::kSpring) {
        e += 0.5 * element.stiffness * (l - element.rest_length) * (l - element.rest_length);
      } else if (element.kind == ElementKind::kActuator) {
        // integral of k_p (exp(alpha (x - x0)) - 1) from the slack length x0
        const PassiveParams& passive = element.model->params().passive;
        const double over = l - passive.slack_length;
        if (over > 0.0) {
          e += passive.k_p * ((std::exp(passive.alpha * over) - 1.0) / passive.alpha - over);
        }
      }
    }
    return e;
  };
  const auto active_power = [&](const NetworkSample& s) {
    double p = 0.0;
    for (std::size_t k = 0; k < scenario.elements.size(); ++k) {
      if (scenario.elements[k].kind != ElementKind::kActuator) continue;
      p -= s.elements[k].parts.active * s.elements[k].lengthening_rate;
    }
    return p;
  };
  // Simpson's rule on the equally spaced rows
  const std::size_t rows = run.samples.size();
  ASSERT_EQ(rows % 2, 1u);
  const double dt = run.times[1] - run.times[0];
  double work = 0.0, magnitude = 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    const double weight = (r == 0 || r + 1 == rows) ? 1.0 : (r % 2 == 1 ? 4.0 : 2.0);
    const double p = active_power(run.samples[r]);
    work += weight * p * dt / 3.0;
    magnitude += weight * std::abs(p) * dt / 3.0;
  }
  const double change = energy(run.samples.back()) - energy(run.samples.front());
  EXPECT_GT(magnitude, 0.1);  // [J]: the actuators do work
  EXPECT_NEAR(change, work, 1e-4 * magnitude);
}

}  // namespace
}  // namespace musclesim
