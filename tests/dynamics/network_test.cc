// The network's dynamics (docs/model.md 7.1-7.4): the right-hand side against a hand
// computation of 7.2, the Jacobian against finite differences, the pattern of a chain, the
// validation of how the parts fit, and the single actuator as a network.
#include "musclesim/dynamics/network.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/dynamics/actuator.h"
#include "musclesim/core/errors.h"
#include "support/canonical_actuator.h"
#include "support/canonical_networks.h"
#include "support/difference_jacobian.h"

namespace musclesim {
namespace {

constexpr double kPi = std::numbers::pi;

// Every kind of part. Nodes: `wall` fixed at 0; `a` (0.2 kg) and `b` (0.3 kg) free; `crank`
// prescribed, 0.4 + 0.01 sin(4 pi t + 0.3) m; `c` (0.05 kg) free, joined to the crank only.
// Elements: `muscle` (canonical actuator, activation 0.5 + 0.2 sin(6 pi t)) wall -> a;
// `spring` (80 N/m, rest 0.16 m) and `tendon` (linear, slack 0.14 m, 2e3 N/m) a -> b;
// `sheath` (exponential tendon: slack 0.14 m, k 5 N, alpha 60 /m) and `damper` (3 N s/m)
// b -> crank; `tether` (spring, 30 N/m, rest 0.12 m) crank -> c. Loads: 5 N on a; on b a
// spring (100 N/m to 0.3 m), a hanging 0.1 kg and 2 + sin(3 pi t) N.
NetworkSystem EveryKind() {
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Free("a", 0.2, 0.1), Node::Free("b", 0.3, 0.25),
       Node::Prescribed("crank", Waveform::Sine(0.4, 0.01, 2.0, 0.3)), Node::Free("c", 0.05, 0.52)},
      {Element::Actuator("muscle", "wall", "a", testing::SharedCanonicalModel(),
                         Waveform::Sine(0.5, 0.2, 3.0)),
       Element::Spring("spring", "a", "b", 80.0, 0.16),
       Element::LinearTendon("tendon", "a", "b", 0.14, 2e3),
       Element::ExponentialTendon("sheath", "b", "crank", 0.14, 5.0, 60.0),
       Element::Damper("damper", "b", "crank", 3.0),
       Element::Spring("tether", "crank", "c", 30.0, 0.12)},
      {{"a", Load::Constant(5.0)},
       {"b", Load::Spring(100.0, 0.3)},
       {"b", Load::Mass(0.1)},
       {"b", Load::Force(Waveform::Sine(2.0, 1.0, 1.5))}});
}

// ---- the right-hand side: docs/model.md 7.2 by hand ---------------------------------------

// One state of EveryKind(): y = (x_a, xdot_a, x_b, xdot_b, x_c, xdot_c), the free nodes in
// the order given.
struct State {
  double t, xa, va, xb, vb, xc, vc;
};

// The accelerations of a, b and c, each term written out from 7.1 and 7.2.
struct HandComputation {
  double crank, crank_rate;                               // p(t), p'(t)
  double muscle, spring, tendon, sheath, damper, tether;  // tensions [N]
  double load_a, load_b;                                  // [N]
  double acc_a, acc_b, acc_c;                             // [m/s^2]
};

HandComputation ByHand(const State& s) {
  HandComputation h;
  const double phase = 4.0 * kPi * s.t + 0.3;
  h.crank = 0.4 + 0.01 * std::sin(phase);
  h.crank_rate = 0.01 * 4.0 * kPi * std::cos(phase);
  const double u = 0.5 + 0.2 * std::sin(6.0 * kPi * s.t);
  // an element's tension at l = x_to - x_from, v = -(xdot_to - xdot_from)
  h.muscle = TensionModel(testing::CanonicalModel()).Evaluate(s.xa, -s.va, u).total;
  const double ab = s.xb - s.xa;
  h.spring = 80.0 * (ab - 0.16);
  h.tendon = ab > 0.14 ? 2e3 * (ab - 0.14) : 0.0;
  const double bc = h.crank - s.xb;
  h.sheath = bc > 0.14 ? 5.0 * (std::exp(60.0 * (bc - 0.14)) - 1.0) : 0.0;
  h.damper = 3.0 * (h.crank_rate - s.vb);
  h.tether = 30.0 * (s.xc - h.crank - 0.12);
  h.load_a = 5.0;
  h.load_b = 100.0 * (0.3 - s.xb) + 0.1 * 9.81 + 2.0 + std::sin(3.0 * kPi * s.t);
  // +T on an element's `from` node, -T on its `to` node; a mass load adds its mass
  h.acc_a = (h.load_a - h.muscle + h.spring + h.tendon) / 0.2;
  h.acc_b = (h.load_b - h.spring - h.tendon + h.sheath + h.damper) / (0.3 + 0.1);
  h.acc_c = -h.tether / 0.05;
  return h;
}

void ExpectRightHandSideByHand(const State& s) {
  const NetworkSystem system = EveryKind();
  const double y[6] = {s.xa, s.va, s.xb, s.vb, s.xc, s.vc};
  double ydot[6];
  system.RightHandSide(s.t, y, ydot);
  const HandComputation h = ByHand(s);
  // the same terms summed in another order: they agree to rounding, 1e-12 relative to the
  // largest force over the mass
  const auto close = [](double scale) { return 1e-12 * scale; };
  EXPECT_EQ(ydot[0], s.va);
  EXPECT_EQ(ydot[2], s.vb);
  EXPECT_EQ(ydot[4], s.vc);
  EXPECT_NEAR(ydot[1], h.acc_a, close(200.0 / 0.2));
  EXPECT_NEAR(ydot[3], h.acc_b, close(200.0 / 0.4));
  EXPECT_NEAR(ydot[5], h.acc_c, close(10.0 / 0.05));

  // what the CSV records: the prescribed node moves with its waveform and its derivative
  NetworkSample sample;
  system.Observe(s.t, y, sample);
  const int crank = system.FindNode("crank");
  EXPECT_NEAR(sample.position[crank], h.crank, 1e-15);
  EXPECT_NEAR(sample.velocity[crank], h.crank_rate, 1e-15);
  EXPECT_EQ(sample.load[system.FindNode("wall")], 0.0);
  EXPECT_NEAR(sample.load[system.FindNode("a")], h.load_a, 1e-13);
  EXPECT_NEAR(sample.load[system.FindNode("b")], h.load_b, 1e-13);
  const std::pair<const char*, double> tensions[] = {{"muscle", h.muscle}, {"spring", h.spring},
                                                     {"tendon", h.tendon}, {"sheath", h.sheath},
                                                     {"damper", h.damper}, {"tether", h.tether}};
  for (const auto& [name, tension] : tensions) {
    EXPECT_NEAR(sample.elements[system.FindElement(name)].tension, tension, 1e-12) << name;
  }
}

TEST(Network, NonFiniteCauseNamesTheElementItsTensionAndTheTime) {
  // b 20 m behind the crank: the sheath's exp(60 (l - 0.14)) overflows, and with it b's
  // acceleration; the diagnosis names the sheath, not a node or a load
  const NetworkSystem system = EveryKind();
  const double y[6] = {0.1, 0.0, -20.0, 0.0, 0.5, 0.0};
  double ydot[6];
  system.RightHandSide(0.25, y, ydot);
  ASSERT_FALSE(std::isfinite(ydot[3]));
  const std::string cause = system.NonFiniteCause(0.25, y);
  const std::string sheath = std::to_string(system.FindElement("sheath"));
  EXPECT_EQ(cause.find("elements[" + sheath + "] (sheath)'s tension is inf N at length "), 0u)
      << cause;
  EXPECT_NE(cause.find(" at t = 0.25 s: its law's parameters overflow at that length"),
            std::string::npos)
      << cause;
}

TEST(Network, NonFiniteCauseNamesANodeWhoseFiniteForcesOverflowOverItsMass) {
  // 1e12 N/m (the stiffest a spring may be) stretched 10 m is 1e13 N, finite; over 1e-300 kg
  // it is not
  const NetworkSystem system({Node::Fixed("wall", 0.0), Node::Free("light", 1e-300, 10.1)},
                             {Element::Spring("spring", "wall", "light", 1e12, 0.1)}, {});
  const double y[2] = {10.1, 0.0};
  const std::string cause = system.NonFiniteCause(0.5, y);
  EXPECT_EQ(cause,
            "node light's acceleration is -inf m/s^2: the forces on it, each finite, over "
            "its mass of 1e-300 kg overflow at t = 0.5 s")
      << cause;
}

TEST(Network, RightHandSideIsSection72ByHandWithTendonSlackAndSheathTaut) {
  const State s{0.13, 0.1, 0.02, 0.235, -0.03, 0.53, 0.01};
  // the sides of the kinks this state is meant to cover
  ASSERT_LT(s.xb - s.xa, 0.14);             // tendon slack
  ASSERT_LT(s.xb - s.xa, 0.16);             // spring compressed: it pushes
  ASSERT_GT(ByHand(s).crank - s.xb, 0.14);  // sheath taut
  ASSERT_LT(s.xa, 0.105);                   // muscle below its passive slack length
  ExpectRightHandSideByHand(s);
}

TEST(Network, RightHandSideIsSection72ByHandWithTendonTautAndSheathSlack) {
  const State s{0.71, 0.112, -0.05, 0.28, 0.04, 0.49, -0.02};
  ASSERT_GT(s.xb - s.xa, 0.16);             // tendon taut, spring stretched
  ASSERT_LT(ByHand(s).crank - s.xb, 0.14);  // sheath slack
  ASSERT_GT(s.xa, 0.105);                   // muscle's passive element stretched
  ExpectRightHandSideByHand(s);
}

// ---- the Jacobian against central differences -------------------------------------------

using testing::Dense;

using testing::AwayFromKinks;
using testing::ExpectJacobianMatchesDifferences;
using testing::PatternMask;

TEST(Network, JacobianMatchesCentralDifferencesOnItsPatternAndNothingLiesOutside) {
  const NetworkSystem system = EveryKind();
  const JacobianPattern& pattern = system.jacobian_pattern();
  const int n = system.state_size();
  ASSERT_EQ(pattern.size, n);
  const std::vector<bool> in_pattern = PatternMask(system);
  for (int j = 0; j < n; ++j) {
    EXPECT_TRUE(in_pattern[Dense(n, j, j)]) << "diagonal " << j;
  }

  std::mt19937 random(20240611);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return lo + (hi - lo) * uniform(random); };
  constexpr double kStep = 1e-7;  // [m] and [m/s]
  int states = 0;
  while (states < 200) {
    const double t = in(0.0, 1.0);
    const double xa = in(0.08, 0.12), xb = xa + in(0.12, 0.18);
    // velocities small and large against eps = 1e-3 m/s, where g_eps bends hardest
    const double scale = uniform(random) < 0.5 ? 2e-3 : 0.5;
    const std::vector<double> y = {
        xa, in(-scale, scale), xb, in(-scale, scale), in(0.45, 0.6), in(-0.5, 0.5)};
    // a difference straddling a kink measures neither side's slope
    if (!AwayFromKinks(system, t, y, 100.0 * kStep)) continue;
    ++states;

    ExpectJacobianMatchesDifferences(system, t, y, kStep);
  }
}

TEST(Network, ChainGivenInOrderHasBandwidthsThreeBelowAndTwoAbove) {
  // node i (i = 1..n) has states x_i at 2(i - 1) and xdot_i at 2(i - 1) + 1. The element
  // from node i to node i + 1 makes both accelerations depend on both nodes' states: rows
  // 2i - 1 and 2i + 1 (the velocity rows) get entries in columns 2i - 2 .. 2i + 1. The
  // farthest below the diagonal is row 2i + 1, column 2i - 2: 3; the farthest above is
  // row 2i - 1, column 2i + 1: 2. Position rows hold only (x, xdot) of their own node.
  const testing::NetworkExperiment chain = testing::Chain(10);
  const JacobianPattern& pattern = chain.system.jacobian_pattern();
  EXPECT_EQ(pattern.size, 20);
  EXPECT_EQ(pattern.lower_bandwidth, 3);
  EXPECT_EQ(pattern.upper_bandwidth, 2);
  // and auto takes the band solver for it
  EXPECT_EQ(ChooseLinearSolver(pattern), LinearSolverKind::kBand);
}

TEST(Network, AutoTakesTheSmallPathUpToSixteenStates) {
  for (int n : {1, 8, 9}) {
    const testing::NetworkExperiment chain = testing::Chain(n);
    const JacobianPattern& pattern = chain.system.jacobian_pattern();
    EXPECT_EQ(pattern.size, 2 * n);
    EXPECT_EQ(ChooseLinearSolver(pattern),
              n <= 8 ? LinearSolverKind::kSmall : LinearSolverKind::kBand)
        << n;
  }
}

// ---- validation: how the parts fit ----------------------------------------------------

// The path and message of the ParameterError that `build` throws; "accepted" if none.
template <typename Build>
std::pair<std::string, std::string> Rejection(Build build) {
  try {
    build();
  } catch (const ParameterError& e) {
    return {e.path(), e.what()};
  }
  return {"", "accepted"};
}

std::vector<Element> OneSpring(std::string from, std::string to) {
  return {Element::Spring("spring", std::move(from), std::move(to), 50.0, 0.1)};
}

TEST(Network, RejectsAnUnknownNodeNamingTheKnownOnes) {
  const auto [path, message] = Rejection([] {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1)},
                  {Element::Damper("damper", "wall", "load", 1.0),
                   Element::Spring("spring", "wall", "lode", 50.0, 0.1)});
  });
  EXPECT_EQ(path, "elements[1].to");
  EXPECT_EQ(message, "elements[1].to = lode: names no node; the nodes are: wall, load");

  const auto load = Rejection([] {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1)},
                  OneSpring("wall", "load"), {{"lode", Load::Constant(5.0)}});
  });
  EXPECT_EQ(load.first, "loads[0].node");
  EXPECT_EQ(load.second, "loads[0].node = lode: names no node; the nodes are: wall, load");
}

TEST(Network, RejectsDuplicateNames) {
  const auto nodes = Rejection([] {
    NetworkSystem(
        {Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1), Node::Free("load", 0.5, 0.2)},
        OneSpring("wall", "load"));
  });
  EXPECT_EQ(nodes.first, "nodes[2].name");
  EXPECT_EQ(nodes.second, "nodes[2].name = load: must be unique: nodes[1] has it too");

  const auto elements = Rejection([] {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1)},
                  {Element::Spring("spring", "wall", "load", 50.0, 0.1),
                   Element::Damper("spring", "wall", "load", 1.0)});
  });
  EXPECT_EQ(elements.first, "elements[1].name");
  EXPECT_EQ(elements.second, "elements[1].name = spring: must be unique: elements[0] has it too");
}

TEST(Network, RejectsAFreeNodeNoElementsTieToAFixedOrPrescribedOne) {
  // `a` and `b` are joined to each other only: together they would drift off
  const auto [path, message] = Rejection([] {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1),
                   Node::Free("a", 0.1, 0.3), Node::Free("b", 0.1, 0.4)},
                  {Element::Spring("spring", "wall", "load", 50.0, 0.1),
                   Element::Damper("link", "a", "b", 1.0)});
  });
  EXPECT_EQ(path, "nodes[2].name");
  EXPECT_EQ(message,
            "nodes[2].name = a: floats: no chain of elements joins this free node to a fixed "
            "or prescribed node");
}

TEST(Network, RejectsALoadOnAFixedNode) {
  const auto [path, message] = Rejection([] {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 0.5, 0.1)},
                  OneSpring("wall", "load"), {{"wall", Load::Constant(5.0)}});
  });
  EXPECT_EQ(path, "loads[0].node");
  EXPECT_EQ(message, "loads[0].node = wall: must name a free node (one with a mass); it is fixed");
}

TEST(Network, RejectsAStepAsAPrescribedMotion) {
  // the factory refuses it ...
  const auto factory = Rejection([] { Node::Prescribed("crank", Waveform::Step(0.1, 0.2, 0.3)); });
  EXPECT_EQ(factory.first, "prescribed.type");
  EXPECT_EQ(factory.second,
            "prescribed.type = step: must be continuous in time: constant, ramp, sine or table");
  // ... and so does the network, for a node filled in field by field, at the node's path
  Node crank;
  crank.name = "crank";
  crank.kind = NodeKind::kPrescribed;
  crank.motion = Waveform::Step(0.1, 0.2, 0.3);
  const auto network = Rejection([&] {
    NetworkSystem({Node::Free("load", 0.5, 0.1), crank}, OneSpring("load", "crank"));
  });
  EXPECT_EQ(network.first, "nodes[1].prescribed.type");
  EXPECT_EQ(network.second,
            "nodes[1].prescribed.type = step: must be continuous in time: constant, ramp, sine "
            "or table");
}

TEST(Network, RejectsANetworkWithNoFreeNode) {
  const auto [path, message] = Rejection([] {
    NetworkSystem(
        {Node::Fixed("wall", 0.0), Node::Prescribed("crank", Waveform::Sine(0.3, 0.01, 1.0))},
        OneSpring("wall", "crank"));
  });
  EXPECT_EQ(path, "nodes");
  EXPECT_EQ(message,
            "nodes = 2 nodes: need at least one free node (one with a mass) or an actuator with "
            "activation dynamics: the state is their positions and activations");
}

// ---- a system is a value ------------------------------------------------------------------

// A 0.5 kg mass on a spring (50 N/m, rest 0.1 m) to a crank moving as `offset` +
// 0.01 sin(2 pi t) m.
NetworkSystem Cranked(double offset) {
  return NetworkSystem(
      {Node::Free("load", 0.5, 0.1), Node::Prescribed("crank", Waveform::Sine(offset, 0.01, 1.0))},
      {Element::Spring("spring", "load", "crank", 50.0, 0.1)});
}

// A NetworkSystem is a value: its copy must own everything it evaluates. (It fails today:
// the implicit copy keeps End::motion, a pointer into the original's nodes, so the copy
// reads freed memory once the original is gone; AddressSanitizer reports it as a
// heap-use-after-free in Waveform::Evaluate from PositionOf.)
TEST(Network, CopyKeepsItsPrescribedMotionWhenTheOriginalIsGone) {
  auto original = std::make_unique<NetworkSystem>(Cranked(0.3));
  const NetworkSystem copy = *original;
  original.reset();
  // another system of the same shape, likely to take the memory the original freed: a
  // copy that still read the original's prescribed motions would read this one's
  const NetworkSystem other = Cranked(0.5);
  const double y[2] = {0.1, 0.0};
  double ydot[2];
  copy.RightHandSide(0.25, y, ydot);
  // at t = 0.25 s the crank is at 0.3 + 0.01 = 0.31 m: the spring, 0.21 m long, pulls the
  // load with 50 * 0.11 = 5.5 N
  EXPECT_NEAR(ydot[1], 5.5 / 0.5, 1e-12);
  other.RightHandSide(0.25, y, ydot);
  EXPECT_NEAR(ydot[1], 50.0 * 0.31 / 0.5, 1e-12);  // 0.51 m: 0.41 m long
}

// ---- the single actuator as a network (docs/model.md 7.4) --------------------------------

TEST(Network, SingleActuatorNetworkIsItsAccelerationBitForBit) {
  ActuatorParams actuator;
  actuator.mass = 0.1;
  actuator.damping = 3.0;
  actuator.stiffness = 50.0;
  actuator.rest_length = 0.1;
  const ActuatorSystem single(
      testing::SharedCanonicalModel(), actuator, Waveform::Sine(0.5, 0.4, 2.0),
      {Load::Force(Waveform::Sine(30.0, 5.0, 2.0)), Load::Spring(200.0, 0.12), Load::Mass(2.0)});
  const NetworkSystem& network = single.network();
  ASSERT_EQ(network.state_size(), 2);

  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const double t = uniform(random);
    const double x = 0.05 + 0.15 * uniform(random);
    // lengthening rates across the regularisation (eps = 1e-3 m/s) and well beyond it
    const double xdot = (uniform(random) - 0.5) * (k % 2 == 0 ? 4e-3 : 2.0);
    const double y[2] = {x, xdot};
    double ydot[2];
    network.RightHandSide(t, y, ydot);
    // EXPECT_EQ on doubles on purpose: the network (ground fixed at 0, so l = x - 0 = x and
    // ldot = xdot exactly; elements in the order actuator, damper, spring) performs the very
    // floating-point operations of Acceleration, in the same order, so the results are
    // identical, not merely close
    EXPECT_EQ(ydot[0], xdot);
    EXPECT_EQ(ydot[1], single.Acceleration(t, x, xdot))
        << "t = " << t << ", x = " << x << ", xdot = " << xdot;
  }
}

// De Groote's tendon against OpenSim 4.6's own DeGrooteFregly2016Muscle::
// calcTendonForceMultiplier and its derivative (tendon_strain_at_one_norm_force 0.049, printed
// to 17 digits from OpenSim's Python API), on both sides of the slack length: below it
// OpenSim's tendon pushes, and so does this one, with no kink to restart at.
TEST(NetworkElements, DeGrooteTendonIsOpenSims) {
  struct Point {
    double normalized_length, multiplier, slope;
  };
  constexpr Point kOpenSim[] = {
      {0.9, -0.19483623797463076, 0.18882080624072622},
      {0.99, -0.061252994731052, 5.073495112605566},
      {1.0, 0.0, 7.313303956032887},
      {1.02, 0.21556862460054138, 15.195898331471424},
      {1.049, 0.9999999999999998, 43.87982373619731},
      {1.1, 7.546290360299851, 283.2548796828016},
  };
  const double f_iso = 300.0, slack = 0.25;
  const NetworkSystem system(
      {Node::Fixed("wall", 0.0), Node::Free("end", 1.0, slack)},
      {Element::DeGrooteTendon("tendon", "wall", "end", slack, f_iso, 0.049)});
  EXPECT_TRUE(system.kinks().empty());
  ElementSample sample;
  for (const Point& p : kOpenSim) {
    const double y[2] = {p.normalized_length * slack, 0.0};
    system.ObserveElement(0, 0.0, y, sample);
    EXPECT_NEAR(sample.tension, f_iso * p.multiplier, 1e-12 * f_iso) << p.normalized_length;
    // dT/dl = F0 / l_s df/dl~, read off the Jacobian's acceleration-by-position entry (-dT/dl
    // over the unit mass)
    std::vector<double> values(static_cast<std::size_t>(system.jacobian_pattern().entries()));
    system.Jacobian(0.0, y, values.data());
    const JacobianPattern& pattern = system.jacobian_pattern();
    for (int k = 0; k < pattern.entries(); ++k) {
      if (pattern.rows[k] == 1 && pattern.ColumnOf(k) == 0) {
        EXPECT_NEAR(-values[k], f_iso / slack * p.slope, 1e-12 * f_iso / slack * p.slope)
            << p.normalized_length;
      }
    }
  }
}

// De Groote's tendon is stored as an exponential whose alpha = ln 6 / (strain l_s) may be far
// past an exponential tendon's own bound: a micrometre tendon at 0.1 % strain (alpha about
// 1.8e9 1/m) is accepted and carries F0 at its strain, and what is refused is named by the
// keys a file gives it.
TEST(NetworkElements, ADeGrooteTendonIsCheckedUnderItsOwnKeys) {
  const double slack = 1e-6, strain = 1e-3, f_iso = 50.0;
  const Element tiny = Element::DeGrooteTendon("tendon", "wall", "end", slack, f_iso, strain);
  EXPECT_GT(tiny.alpha, 1e9);
  const NetworkSystem system({Node::Fixed("wall", 0.0), Node::Free("end", 1.0, slack)}, {tiny});
  ElementSample sample;
  const double y[2] = {slack * (1.0 + strain), 0.0};
  system.ObserveElement(0, 0.0, y, sample);
  EXPECT_NEAR(sample.tension, f_iso, 1e-9 * f_iso);  // F0 (0.2 exp(ln 6) - 0.2) = F0

  Element broken = tiny;
  broken.slack_length = 0.0;
  try {
    Validate(broken);
    FAIL() << "a slack length of 0 was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "slack_length");
  }
  try {
    Element::DeGrooteTendon("tendon", "wall", "end", slack, 0.0, strain);
    FAIL() << "F0 = 0 was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "degroote2016.max_isometric_force");
  }
}

}  // namespace
}  // namespace musclesim
