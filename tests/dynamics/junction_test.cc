// Massless junctions (docs/model.md 14.4): a free node of mass 0 whose velocity is the root of
// its force balance. Checked against a linear network derived by hand and integrated by RK4,
// against the same networks with a junction mass shrinking to 0, the Jacobian against finite
// differences (the implicit function theorem's terms), and the refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/solver/simulation.h"
#include "support/canonical_actuator.h"
#include "support/difference_jacobian.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-11;
  options.atol = 1e-14;
  return options;
}

NetworkRunRequest Span(double t_end, double interval) {
  NetworkRunRequest request;
  request.t_end = t_end;
  request.output_interval = interval;
  return request;
}

// De Groote's fiber (optimal length 0.1 m, 10 optimal lengths per second) of `f_iso` [N] and
// fiber damping `damping` [-], shared as a model.
std::shared_ptr<const TensionModel> DeGrooteFiber(double f_iso, double damping,
                                                  double pennation = 0.0) {
  ModelParams p;
  p.family = CurveFamily::kDeGroote2016;
  p.f_iso = f_iso;
  p.degroote2016.optimal_fiber_length = 0.1;
  p.degroote2016.max_contraction_velocity = 10.0;
  p.degroote2016.fiber_damping = damping;
  p.pennation_angle = pennation;
  return std::make_shared<const TensionModel>(p);
}

// ---- a linear network by hand ---------------------------------------------------------------

// wall (fixed, 0) -spring k1, rest r1- a (mass m) -damper c- j (massless) -spring k2, rest r2-
// end (fixed, L). j's balance, c (w - v_a) = k2 (L - x_j - r2), gives its velocity, so
// y = (x_a, v_a, x_j) with
//   x_a' = v_a,  m v_a' = -k1 (x_a - r1) + k2 (L - x_j - r2),  x_j' = v_a + k2 (L - x_j - r2) / c.
struct Linear {
  double k1 = 40.0, r1 = 0.2, m = 0.3, c = 1.5, k2 = 90.0, r2 = 0.25, L = 1.0;

  NetworkSystem System() const {
    return NetworkSystem(
        {Node::Fixed("wall", 0.0), Node::Free("a", m, 0.3, 0.1), Node::Free("j", 0.0, 0.6),
         Node::Fixed("end", L)},
        {Element::Spring("first", "wall", "a", k1, r1), Element::Damper("damper", "a", "j", c),
         Element::Spring("second", "j", "end", k2, r2)});
  }
  std::array<double, 3> Rate(const std::array<double, 3>& y) const {
    const double pull = k2 * (L - y[2] - r2);
    return {y[1], (-k1 * (y[0] - r1) + pull) / m, y[1] + pull / c};
  }
  // classic RK4 from (0.3, 0.1, 0.6) to t with n steps: error ~ (h / tau)^4, tau = c / k2
  std::array<double, 3> At(double t, int n) const {
    std::array<double, 3> y{0.3, 0.1, 0.6};
    const double h = t / n;
    const auto add = [](const std::array<double, 3>& a, const std::array<double, 3>& b, double s) {
      return std::array<double, 3>{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
    };
    for (int i = 0; i < n; ++i) {
      const auto k_1 = Rate(y);
      const auto k_2 = Rate(add(y, k_1, h / 2));
      const auto k_3 = Rate(add(y, k_2, h / 2));
      const auto k_4 = Rate(add(y, k_3, h));
      for (int q = 0; q < 3; ++q) y[q] += h / 6 * (k_1[q] + 2 * k_2[q] + 2 * k_3[q] + k_4[q]);
    }
    return y;
  }
};

TEST(MasslessJunction, HasAPositionStateAloneAndMatchesTheLinearNetworkByHand) {
  const Linear linear;
  const NetworkSystem system = linear.System();
  EXPECT_EQ(system.state_size(), 3);  // x_a, v_a, x_j
  EXPECT_EQ(system.junction_count(), 1);
  EXPECT_EQ(system.StateIndex(2), 2);
  EXPECT_EQ(system.VelocityStateIndex(2), -1);
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, Tight(), Span(0.5, 0.05));
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  ASSERT_EQ(run.times.size(), 11u);  // 0, 0.05, ..., 0.5
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    const double t = run.times[k];
    // RK4 at h = 1e-5 s against tau = c / k2 = 1/60 s: (6e-4)^4 ~ 1e-13 per unit time
    const std::array<double, 3> y = linear.At(t, static_cast<int>(std::lround(t / 1e-5)));
    const NetworkSample& s = run.samples[k];
    EXPECT_NEAR(s.position[1], y[0], 1e-9) << "t = " << t;
    EXPECT_NEAR(s.velocity[1], y[1], 1e-8) << "t = " << t;
    EXPECT_NEAR(s.position[2], y[2], 1e-9) << "t = " << t;
    // the junction's velocity is its balance's root: the hand formula at the recorded state
    const double w = y[1] + linear.k2 * (linear.L - y[2] - linear.r2) / linear.c;
    EXPECT_NEAR(s.velocity[2], w, 1e-7) << "t = " << t;
    // and the two forces on it cancel to rounding
    EXPECT_NEAR(s.elements[1].tension, s.elements[2].tension,
                1e-12 * std::abs(s.elements[2].tension) + 1e-12);
  }
}

// ---- a muscle in series with a compliant tendon ---------------------------------------------

// De Groote's muscle, with fiber damping, from a wall to the junction `j` (mass `mass`), in
// series with an exponential tendon to `end`, which is held, then stretched and held again;
// the muscle's excitation is a state of activation dynamics, and the junction also carries a
// weak spring load.
NetworkSystem MuscleTendon(double mass, double velocity = 0.0) {
  ExcitationInput drive{Waveform::Sine(0.5, 0.4, 3.0), ActivationDynamics{}, 0.2};
  drive.dynamics.family = ActivationFamily::kDeGroote2016;
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Free("j", mass, 0.1, velocity),
       Node::Prescribed("end", Waveform::Ramp(0.1, 0.3, 0.31, 0.34))},
      {Element::Actuator("muscle", "wall", "j", DeGrooteFiber(200.0, 0.01, 0.1), drive),
       Element::ExponentialTendon("tendon", "j", "end", 0.2, 2.0, 150.0)},
      {{"j", Load::Spring(20.0, 0.12)}});
}

TEST(MasslessJunction, IsTheLimitOfAShrinkingJunctionMass) {
  Simulation simulation;
  const NetworkRunResult massless = simulation.Run(MuscleTendon(0.0), Tight(), Span(0.4, 0.02));
  ASSERT_EQ(massless.stats.status, RunStatus::kCompleted) << massless.stats.message;
  // a junction of mass m starts at rest, where the massless one starts at its root: compare
  // after the fast layer (its time scale m / damping, far below 0.1 s here)
  const NetworkSystem start = MuscleTendon(0.0);
  std::vector<double> y(static_cast<std::size_t>(start.state_size()));
  start.InitialState(y.data());
  const double w0 = start.NodeVelocity(1, 0.0, y.data());
  double previous = 0.0;
  for (const double mass : {1e-5, 1e-6, 1e-7}) {
    const NetworkRunResult massive =
        simulation.Run(MuscleTendon(mass, w0), Tight(), Span(0.4, 0.02));
    ASSERT_EQ(massive.stats.status, RunStatus::kCompleted) << massive.stats.message;
    double worst = 0.0;
    for (std::size_t k = 0; k < massless.times.size(); ++k) {
      worst = std::max(worst,
                       std::abs(massive.samples[k].position[1] - massless.samples[k].position[1]));
      worst = std::max(worst, std::abs(massive.samples[k].elements[1].tension -
                                       massless.samples[k].elements[1].tension) /
                                  200.0);
    }
    // the inertial correction is O(m): ten times less mass, about ten times closer
    if (previous > 0.0) {
      EXPECT_LT(worst, 0.2 * previous) << "mass " << mass;
      EXPECT_GT(worst, 0.05 * previous) << "mass " << mass;
    }
    previous = worst;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(MasslessJunction, JacobianMatchesDifferencesThroughTheBalance) {
  // the junction's neighbours: a wall, a prescribed end and, here, a free mass `b` joined by
  // a tendon and a spring in parallel, so that w's columns reach another node's row
  ExcitationInput drive{Waveform::Sine(0.5, 0.3, 2.0), ActivationDynamics{}, 0.4};
  const NetworkSystem system(
      {Node::Fixed("wall", 0.0), Node::Free("j", 0.0, 0.1), Node::Free("b", 0.2, 0.35, 0.3),
       Node::Prescribed("end", Waveform::Sine(0.6, 0.01, 2.0))},
      {Element::Actuator("fiber", "wall", "j", DeGrooteFiber(50.0, 0.05), drive),
       Element::ExponentialTendon("tendon", "j", "b", 0.2, 2.0, 40.0),
       Element::Spring("spring", "j", "b", 10.0, 0.2), Element::Damper("damper", "b", "end", 2.0)},
      {{"j", Load::Constant(-3.0)}});
  EXPECT_EQ(system.state_size(), 4);  // x_j, x_b, v_b, u
  std::vector<double> y(4);
  for (const double t : {0.05, 0.3, 0.71}) {
    for (const std::array<double, 4>& state :
         {std::array<double, 4>{0.1, 0.35, 0.3, 0.4}, std::array<double, 4>{0.095, 0.33, -0.5, 0.8},
          std::array<double, 4>{0.108, 0.36, 1.2, 0.1}}) {
      y.assign(state.begin(), state.end());
      ASSERT_TRUE(testing::AwayFromKinks(system, t, y, 1e-4));
      testing::ExpectJacobianMatchesDifferences(system, t, y, 1e-7);
    }
  }
}

TEST(MasslessJunction, ARunWhoseBalanceFailsEndsNamingTheCause) {
  // the tendon's end pulled 10 m away in a millisecond: the tendon's tension overflows, or
  // the fiber's as the integrator tries states far out; no velocity of the junction balances
  // them, and the run fails (not a crash, not a silent NaN) naming the junction
  const NetworkSystem system(
      {Node::Fixed("wall", 0.0), Node::Free("junction", 0.0, 0.09),
       Node::Prescribed("end", Waveform::Ramp(0.2, 0.201, 0.3, 10.0))},
      {Element::Actuator("muscle", "wall", "junction", DeGrooteFiber(100.0, 0.01),
                         Waveform::Constant(1.0)),
       Element::DeGrooteTendon("tendon", "junction", "end", 0.2, 100.0, 0.049)});
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, Tight(), Span(0.3, 0.01));
  EXPECT_EQ(run.stats.status, RunStatus::kFailed);
  EXPECT_THAT(run.stats.message, HasSubstr("the right-hand side was not finite"));
  EXPECT_THAT(run.stats.message, HasSubstr("massless junction junction"));
}

// ---- refusals ---------------------------------------------------------------------------

std::string Refusal(const std::function<void()>& build) {
  try {
    build();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(MasslessJunction, IsRefusedWhereItsBalanceCannotFixItsVelocity) {
  // a spring and a tendon: the balance holds for any velocity, or none
  EXPECT_THAT(Refusal([] {
                NetworkSystem(
                    {Node::Fixed("wall", 0.0), Node::Free("j", 0.0, 0.1), Node::Fixed("end", 0.4)},
                    {Element::Spring("spring", "wall", "j", 10.0, 0.1),
                     Element::LinearTendon("tendon", "j", "end", 0.2, 1e3)});
              }),
              HasSubstr("nodes[1].mass = 0: a massless junction's velocity must follow from its "
                        "force balance"));
  EXPECT_THAT(Refusal([] {
                NetworkSystem(
                    {Node::Fixed("wall", 0.0), Node::Free("j", 0.0, 0.1), Node::Fixed("end", 0.4)},
                    {Element::Actuator("muscle", "wall", "j", testing::SharedCanonicalModel(),
                                       Waveform::Constant(1.0)),
                     Element::LinearTendon("tendon", "j", "end", 0.2, 1e3)});
              }),
              HasSubstr("node j has muscle (actuator), tendon (tendon)"));
  // two junctions side by side: their balances couple
  EXPECT_THAT(Refusal([] {
                NetworkSystem(
                    {Node::Fixed("wall", 0.0), Node::Free("i", 0.0, 0.1), Node::Free("j", 0.0, 0.2),
                     Node::Fixed("end", 0.4)},
                    {Element::Damper("d1", "wall", "i", 1.0), Element::Damper("d2", "i", "j", 1.0),
                     Element::Damper("d3", "j", "end", 1.0)});
              }),
              HasSubstr("elements[1].name = d2: joins two massless junctions (i and j)"));
  // in the plane
  EXPECT_THAT(Refusal([] {
                Space plane;
                plane.dimensions = 2;
                NetworkSystem({Node::Fixed("wall", Coordinates{0.0, 0.0, 0.0}),
                               Node::Free("j", 0.0, Coordinates{0.1, 0.0, 0.0})},
                              {Element::Damper("d", "wall", "j", 1.0)}, {}, {}, plane);
              }),
              HasSubstr("nodes[1].mass = 0: a massless junction (mass 0) needs dimensions 1"));
  // a mass load would give it a mass; a start velocity contradicts its balance
  EXPECT_THAT(Refusal([] {
                NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("j", 0.0, 0.1)},
                              {Element::Damper("d", "wall", "j", 1.0)}, {{"j", Load::Mass(0.1)}});
              }),
              HasSubstr("loads[0].type = mass: a massless junction (node j, mass 0) carries "
                        "no mass load"));
  // the elements at it are listed, an inert damper too
  EXPECT_THAT(Refusal([] {
                NetworkSystem(
                    {Node::Fixed("wall", 0.0), Node::Free("j", 0.0, 0.1), Node::Fixed("end", 0.4)},
                    {Element::Damper("idle", "wall", "j", 0.0),
                     Element::Spring("spring", "j", "end", 10.0, 0.2)});
              }),
              HasSubstr("node j has idle (damper) with damping 0, spring (spring)"));
  EXPECT_THAT(Refusal([] { Validate(Node::Free("j", 0.0, 0.1, 0.5)); }),
              HasSubstr("velocity = 0.5: must be absent (or 0) on a massless junction"));
  EXPECT_THAT(Refusal([] { Validate(Node::Free("j", -1.0, 0.1)); }),
              HasSubstr("mass = -1: must be finite and >= 0 [kg] (0: a massless junction"));
}

}  // namespace
}  // namespace musclesim
