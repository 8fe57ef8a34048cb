// Activation dynamics (docs/model.md section 8): the activation u as a state of the ODE,
//   udot = (e - u) / tau(e, u),  tau = tau_act (0.5 + 1.5 u) if e > u, tau_deact / (0.5 + 1.5 u)
// otherwise, checked against its closed-form step responses, an independent Runge-Kutta
// integration across the kink e = u, central differences of the right-hand side, a run with
// the closed-form u(t) given as an instantaneous activation, and the two scenario forms.
#include "musclesim/dynamics/activation_dynamics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/plot/plot.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/run_columns.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/sweep/sweep_file.h"
#include "support/canonical_actuator.h"
#include "support/difference_jacobian.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::DoubleEq;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr double kTauAct = 0.015, kTauDeact = 0.05;  // [s], the twitch scenario's

// ---- closed forms of a step in excitation ---------------------------------------------------
//
// With e = E constant and E > u, dt = tau_a (0.5 + 1.5 u) / (E - u) du. Writing
// 0.5 + 1.5 u = (0.5 + 1.5 E) - 1.5 (E - u), the integrand is (0.5 + 1.5 E) / (E - u) - 1.5:
//   t(u) = tau_a [ -1.5 (u - u0) + (0.5 + 1.5 E) ln((E - u0) / (E - u)) ].
// With E < u, dt = tau_d du / ((E - u)(0.5 + 1.5 u)); in partial fractions
// 1 / ((E - u)(0.5 + 1.5 u)) = [1 / (E - u) + 1.5 / (0.5 + 1.5 u)] / (0.5 + 1.5 E), so
//   t(u) = tau_d / (0.5 + 1.5 E) [ ln((u0 - E) / (u - E)) + ln((0.5 + 1.5 u) / (0.5 + 1.5 u0)) ].
// Both are strictly monotone in u between u0 and E, and a bisection inverts them.

double RiseTime(double e, double u0, double u) {
  return kTauAct * (-1.5 * (u - u0) + (0.5 + 1.5 * e) * std::log((e - u0) / (e - u)));
}

double FallTime(double e, double u0, double u) {
  return kTauDeact / (0.5 + 1.5 * e) *
         (std::log((u0 - e) / (u - e)) + std::log((0.5 + 1.5 * u) / (0.5 + 1.5 * u0)));
}

// u(t) after a step to the constant excitation e from u0: the root of time(u) = t, bisected
// to the last bit between u0 and e.
double ActivationAfter(double t, double e, double u0) {
  if (t <= 0.0 || e == u0) return u0;
  const bool rising = e > u0;
  double near = u0, far = e;  // time(near) <= t < time(far) = infinity
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (near + far);
    if (mid == near || mid == far) break;
    const double time = rising ? RiseTime(e, u0, mid) : FallTime(e, u0, mid);
    (time <= t ? near : far) = mid;
  }
  return near;
}

ExcitationInput Excitation(Waveform signal, std::optional<double> initial = std::nullopt) {
  return {std::move(signal), {kTauAct, kTauDeact}, initial};
}

// The canonical actuator (0.1 kg, under a 20 N load from 0.1 m) driven by `excitation`.
ActuatorSystem ExcitedActuator(ExcitationInput excitation) {
  ActuatorParams actuator;
  actuator.mass = 0.1;
  return ActuatorSystem(testing::SharedCanonicalModel(), actuator, std::move(excitation),
                        {Load::Constant(20.0)});
}

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-12;
  return options;
}

RunRequest Span(double t_end, double interval) {
  RunRequest request;
  request.t_end = t_end;
  request.length = 0.1;
  request.output_interval = interval;
  return request;
}

// BDF at rtol 1e-10 keeps each step's local error near 1e-10 |u|, and the decay of u towards
// e forgets old errors within a few time constants, so the global error stays a few rtol
// (3e-10 is seen); 2e-9 leaves a margin of about 5 and is still 1e-8 of u's range
constexpr double kTightError = 2e-9;

TEST(ActivationDynamics, StepUpFollowsTheClosedForm) {
  const double e = 0.8, u0 = 0.1;
  Simulation simulation;
  const RunResult run = simulation.Run(ExcitedActuator(Excitation(Waveform::Constant(e), u0)),
                                       Tight(), Span(0.2, 1e-3));
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  ASSERT_EQ(run.trajectory.size(), 201u);
  for (const TrajectoryPoint& p : run.trajectory) {
    EXPECT_NEAR(p.sample.activation, ActivationAfter(p.t, e, u0), kTightError) << "t = " << p.t;
    EXPECT_EQ(p.sample.excitation, e);
  }
  // most of the way up by 0.2 s: the test compares a rise, not a constant
  EXPECT_GT(run.trajectory.back().sample.activation, 0.79);
}

TEST(ActivationDynamics, StepDownFollowsTheClosedForm) {
  for (const double e : {0.0, 0.3}) {
    const double u0 = 0.9;
    Simulation simulation;
    const RunResult run = simulation.Run(ExcitedActuator(Excitation(Waveform::Constant(e), u0)),
                                         Tight(), Span(0.4, 1e-3));
    ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
    for (const TrajectoryPoint& p : run.trajectory) {
      EXPECT_NEAR(p.sample.activation, ActivationAfter(p.t, e, u0), kTightError)
          << "e = " << e << ", t = " << p.t;
    }
    EXPECT_LT(run.trajectory.back().sample.activation, e + 0.02);
  }
}

TEST(ActivationDynamics, PulseTrainFollowsTheClosedFormAcrossEveryEdge) {
  // 10 ms pulses every 0.2 s from 0.1 s, as the twitches scenario. Each edge is a stop time,
  // and the implicit step that ends on it must see the excitation before the edge (the one
  // after it once cost the fall after each pulse 2e-5 at rtol 1e-6, 8e-5 at 1e-5)
  const double start = 0.1, period = 0.2, width = 0.01;
  SolverOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-9;
  Simulation simulation;
  const RunResult run = simulation.Run(
      ExcitedActuator(Excitation(Waveform::Pulses(start, period, width, 0.0, 1.0), 0.0)), options,
      Span(1.0, 5e-4));
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  // the closed form piece by piece: rise over each pulse, fall until the next one
  double u_edge = 0.0, edge = start;  // the last edge passed and u there
  bool high = true;                   // the excitation after it
  for (const TrajectoryPoint& p : run.trajectory) {
    if (p.t < start) {
      EXPECT_EQ(p.sample.activation, 0.0);
      continue;
    }
    while (p.t >= edge + (high ? width : period - width) - 1e-12) {
      u_edge = ActivationAfter(high ? width : period - width, high ? 1.0 : 0.0, u_edge);
      edge += high ? width : period - width;
      high = !high;
    }
    if (p.t == edge) continue;  // on an edge: the output may show either side's value
    const double expected = ActivationAfter(p.t - edge, high ? 1.0 : 0.0, u_edge);
    // a few rtol of u's range: the error at each edge is the error of a few steps
    EXPECT_NEAR(p.sample.activation, expected, 5e-6) << "t = " << p.t;
  }
  EXPECT_GT(edge, 0.9);  // every pulse was passed
}

TEST(ActivationDynamics, InitialActivationDefaultsToTheExcitationAtTheStart) {
  // a ramp from 0.2 at t = 0 to 0.6 at t = 1, a run from t = 0.5: u(0.5) = e(0.5) = 0.4
  const ActuatorSystem system = ExcitedActuator(Excitation(Waveform::Ramp(0.0, 1.0, 0.2, 0.6)));
  RunRequest request = Span(0.6, 1e-2);
  request.t_start = 0.5;
  Simulation simulation;
  const RunResult run = simulation.Run(system, Tight(), request);
  ASSERT_FALSE(run.trajectory.empty());
  EXPECT_DOUBLE_EQ(run.trajectory.front().sample.activation, 0.4);
}

// ---- the kink at e = u -------------------------------------------------------------------------

// u(t) by classical Runge-Kutta with a fixed step: an integration of the equation of
// docs/model.md section 8 written out again here, sharing no code with the simulator.
double RungeKuttaActivation(const std::function<double(double)>& e, double u0, double t,
                            double step) {
  const auto rate = [&](double s, double u) {
    const double shape = 0.5 + 1.5 * u;
    return e(s) > u ? (e(s) - u) / (kTauAct * shape) : (e(s) - u) * shape / kTauDeact;
  };
  double u = u0;
  const int steps = static_cast<int>(std::ceil(t / step));
  const double h = t / steps;
  for (int i = 0; i < steps; ++i) {
    const double s = i * h;
    const double k1 = rate(s, u);
    const double k2 = rate(s + h / 2, u + h / 2 * k1);
    const double k3 = rate(s + h / 2, u + h / 2 * k2);
    const double k4 = rate(s + h, u + h * k3);
    u += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return u;
}

TEST(ActivationDynamics, ActivationCatchingAFallingExcitationCrossesTheKink) {
  // e falls from 1 to 0 over 0.1 s; u rises from 0 until it meets e, where udot = 0 and the
  // slope of udot in u jumps, then falls behind it
  const Waveform ramp = Waveform::Ramp(0.0, 0.1, 1.0, 0.0);
  Simulation simulation;
  const RunResult run =
      simulation.Run(ExcitedActuator(Excitation(ramp, 0.0)), Tight(), Span(0.2, 1e-3));
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  int crossings = 0;
  for (std::size_t k = 1; k < run.trajectory.size(); ++k) {
    const ActuatorSample& before = run.trajectory[k - 1].sample;
    const ActuatorSample& after = run.trajectory[k].sample;
    crossings += before.activation < before.excitation && after.activation > after.excitation;
  }
  EXPECT_EQ(crossings, 1);
  for (const TrajectoryPoint& p : run.trajectory) {
    // RK4 at 1 us: a global error of order h^4 / tau^4 = 1e-17 on the smooth parts, and the
    // kink, crossed once, costs O(h^2) times a slope jump of ~100/s times |e - u| = O(h)
    const double reference =
        RungeKuttaActivation([&](double s) { return ramp.Evaluate(s); }, 0.0, p.t, 1e-6);
    EXPECT_NEAR(p.sample.activation, reference, kTightError) << "t = " << p.t;
  }
}

// ---- the Jacobian -------------------------------------------------------------------------

using testing::AwayFromKinks;
using testing::Dense;
using testing::ExpectJacobianMatchesDifferences;
using testing::PatternMask;

// Two free nodes between a wall and a prescribed crank: two actuators with activation
// dynamics (from the wall, and between the nodes), one without (to the crank), a spring and a
// damper. States: x_a, v_a, x_b, v_b, u_wall_a, u_a_b.
NetworkSystem MixedNetwork() {
  const auto model = testing::SharedCanonicalModel();
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Free("a", 0.2, 0.1), Node::Free("b", 0.3, 0.2),
       Node::Prescribed("crank", Waveform::Sine(0.3, 0.005, 2.0))},
      {Element::Actuator("wall_a", "wall", "a", model,
                         Excitation(Waveform::Sine(0.5, 0.4, 3.0), 0.2)),
       Element::Actuator("a_b", "a", "b", model, Excitation(Waveform::Ramp(0.0, 1.0, 0.1, 0.9))),
       Element::Actuator("b_crank", "b", "crank", model, Waveform::Constant(0.5)),
       Element::Spring("spring", "a", "b", 30.0, 0.1), Element::Damper("damper", "wall", "b", 2.0)},
      {{"a", Load::Constant(3.0)}});
}

TEST(ActivationDynamics, StatesFollowTheNodesInElementOrder) {
  const NetworkSystem system = MixedNetwork();
  EXPECT_EQ(system.state_size(), 6);
  EXPECT_EQ(system.activation_count(), 2);
  EXPECT_EQ(system.ActivationStateIndex(0), 4);
  EXPECT_EQ(system.ActivationStateIndex(1), 5);
  EXPECT_EQ(system.ActivationStateIndex(2), -1);
  EXPECT_EQ(system.ActivationStateIndex(3), -1);
  std::vector<double> y(6);
  system.InitialState(0.5, y.data());
  // 0.5: the ramp at t = 0.5
  EXPECT_THAT(y, ElementsAre(0.1, 0.0, 0.2, 0.0, 0.2, DoubleEq(0.5)));
  // one kink per activation state, where e = u
  int excitation_kinks = 0;
  for (const NetworkSystem::Kink& kink : system.kinks()) {
    excitation_kinks += kink.kind == NetworkSystem::Kink::kExcitation;
  }
  EXPECT_EQ(excitation_kinks, 2);
}

TEST(ActivationDynamics, JacobianMatchesCentralDifferencesOnItsPatternAndNothingLiesOutside) {
  const NetworkSystem system = MixedNetwork();
  const JacobianPattern& pattern = system.jacobian_pattern();
  const int n = system.state_size();
  ASSERT_EQ(pattern.size, n);
  const std::vector<bool> in_pattern = PatternMask(system);
  for (int j = 0; j < n; ++j) EXPECT_TRUE(in_pattern[Dense(n, j, j)]) << "diagonal " << j;
  // u of wall_a moves the accelerations of a (its `to`, row 1) only: the wall has no state
  EXPECT_TRUE(in_pattern[Dense(n, 1, 4)]);
  EXPECT_FALSE(in_pattern[Dense(n, 3, 4)]);
  // u of a_b moves both a and b
  EXPECT_TRUE(in_pattern[Dense(n, 1, 5)]);
  EXPECT_TRUE(in_pattern[Dense(n, 3, 5)]);

  std::mt19937 random(20240612);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return lo + (hi - lo) * uniform(random); };
  constexpr double kStep = 1e-7;  // [m], [m/s] and [-]
  int states = 0;
  while (states < 200) {
    const double t = in(0.0, 1.0);
    const double xa = in(0.08, 0.12), xb = xa + in(0.08, 0.12);
    // velocities small and large against eps = 1e-3 m/s, where g_eps bends hardest
    const double scale = uniform(random) < 0.5 ? 2e-3 : 0.5;
    const std::vector<double> y = {xa,           in(-scale, scale), xb, in(-scale, scale),
                                   in(0.0, 1.0), in(0.0, 1.0)};
    // a difference straddling a kink (e = u among them) measures neither side's slope
    if (!AwayFromKinks(system, t, y, 100.0 * kStep)) continue;
    ++states;

    ExpectJacobianMatchesDifferences(system, t, y, kStep);
  }
}

// ---- a network with two actuators with activation dynamics ---------------------------------

// A 1 kg mass between two canonical actuators, each 0.1 m long at the start: the flexor's
// excitation 0.8 from u = 0.1, the extensor's 0.2 from u = 0.9, so one activates while the
// other deactivates and the mass moves towards the flexor's wall.
NetworkSystem Antagonists(Waveform flexor, Waveform extensor) {
  const auto model = testing::SharedCanonicalModel();
  return NetworkSystem(
      {Node::Fixed("wall_a", 0.0), Node::Free("load", 1.0, 0.1), Node::Fixed("wall_b", 0.2)},
      {Element::Actuator("flexor", "wall_a", "load", model, std::move(flexor)),
       Element::Actuator("extensor", "load", "wall_b", model, std::move(extensor))});
}

Element WithDynamics(Element actuator, double e, double u0) {
  actuator.excitation = Excitation(Waveform::Constant(e), u0);
  return actuator;
}

TEST(ActivationDynamics, TwoActuatorsInANetworkEachFollowTheirClosedForm) {
  const NetworkSystem instantaneous = Antagonists(Waveform::Constant(0.0), Waveform::Constant(0.0));
  const NetworkSystem system(instantaneous.nodes(),
                             {WithDynamics(instantaneous.elements()[0], 0.8, 0.1),
                              WithDynamics(instantaneous.elements()[1], 0.2, 0.9)});
  NetworkRunRequest request;
  request.t_end = 0.3;
  request.output_interval = 1e-3;
  Simulation simulation;
  const NetworkRunResult run = simulation.Run(system, Tight(), request);
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    const double t = run.times[k];
    EXPECT_NEAR(run.samples[k].elements[0].activation, ActivationAfter(t, 0.8, 0.1), kTightError);
    EXPECT_NEAR(run.samples[k].elements[1].activation, ActivationAfter(t, 0.2, 0.9), kTightError);
    EXPECT_EQ(run.samples[k].elements[0].excitation, 0.8);
    EXPECT_EQ(run.samples[k].elements[1].excitation, 0.2);
  }
  // the flexor won: the mass moved towards wall_a
  EXPECT_LT(run.samples.back().position[1], 0.1 - 1e-3);

  // the same network with the closed-form activations given as instantaneous activations
  // (tables every 50 us): the mechanics reads the activation state, so the motions agree
  std::vector<TablePoint> flexor, extensor;
  for (int i = 0; i <= 6000; ++i) {
    const double t = 0.3 * i / 6000;
    flexor.push_back({t, ActivationAfter(t, 0.8, 0.1)});
    extensor.push_back({t, ActivationAfter(t, 0.2, 0.9)});
  }
  const NetworkRunResult tabled = simulation.Run(
      Antagonists(Waveform::Table(flexor), Waveform::Table(extensor)), Tight(), request);
  ASSERT_EQ(tabled.stats.status, RunStatus::kCompleted) << tabled.stats.message;
  ASSERT_EQ(tabled.times.size(), run.times.size());
  for (std::size_t k = 0; k < run.times.size(); ++k) {
    // the tables' linear interpolation errs by h^2 |u''| / 8 <= (5e-5)^2 2e4 / 8 = 6e-6 in u
    // in the first milliseconds, where u'' is largest, and by 1e-7 after them: a force error
    // of dT/du du <= 100 N x 1e-7 = 1e-5 N, against the ~1e3 N s/m the canonical velocity
    // curve resists with near rest, drifts the mass by 1e-8 m/s, 3e-9 m over the run; 1e-7 m
    // allows for the start (reading e instead of u would move it by millimetres)
    EXPECT_NEAR(tabled.samples[k].position[1], run.samples[k].position[1], 1e-7)
        << "t = " << run.times[k];
  }
}

TEST(ActivationDynamics, NetworkCsvHasTheExcitationAfterTheActivationOfDynamicActuatorsOnly) {
  const NetworkSystem mixed = MixedNetwork();
  Scenario scenario;  // the mixed network as a scenario: its CSV's columns
  scenario.nodes = mixed.nodes();
  scenario.elements = mixed.elements();
  const std::vector<std::string> columns = RunColumns(scenario, mixed).names();
  const auto at = [&](const std::string& name) {
    return std::find(columns.begin(), columns.end(), name) - columns.begin();
  };
  EXPECT_EQ(at("wall_a.excitation"), at("wall_a.activation") + 1);
  EXPECT_EQ(at("a_b.excitation"), at("a_b.activation") + 1);
  EXPECT_EQ(at("b_crank.tension_passive"), at("b_crank.activation") + 1);
  EXPECT_EQ(at("b_crank.excitation"), static_cast<long>(columns.size()));  // none
}

// ---- the twitch scenario ------------------------------------------------------------------------

double LargestStep(const std::vector<TrajectoryPoint>& trajectory,
                   double (*of)(const ActuatorSample&)) {
  double largest = 0.0;
  for (std::size_t k = 1; k < trajectory.size(); ++k) {
    largest = std::max(largest, std::abs(of(trajectory[k].sample) - of(trajectory[k - 1].sample)));
  }
  return largest;
}

double Tension(const ActuatorSample& s) { return s.tension.total; }
double Activation(const ActuatorSample& s) { return s.activation; }

TEST(ActivationDynamics, TwitchScenarioRisesAndFallsWithoutJumps) {
  const Scenario twitches = LoadScenario(testing::ScenarioPath("twitches.yaml"));
  const std::optional<ExcitationInput>& excitation = twitches.elements[kActuatorElement].excitation;
  ASSERT_TRUE(excitation.has_value());
  const RunResult run = testing::RunActuator(twitches);
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const double interval = twitches.output.interval;

  // |udot| <= |e - u| / (tau_act (0.5 + 1.5 u)) <= 1 / (0.5 tau_act) while activating and
  // |e - u| (0.5 + 1.5 u) / tau_deact <= 2 / tau_deact while deactivating, whichever larger
  const ActivationDynamics& d = excitation->dynamics;
  const double fastest = std::max(1.0 / (0.5 * d.tau_activation), 2.0 / d.tau_deactivation);
  EXPECT_LE(LargestStep(run.trajectory, Activation), fastest * interval);

  // the same pulses as an instantaneous activation jump the tension by most of a twitch
  // from one sample to the next; through the dynamics u moves at most fastest * interval
  // (a fifteenth) per sample, and the tension with it
  Scenario instantaneous = twitches;
  Element& actuator = instantaneous.elements[kActuatorElement];
  actuator.activation = excitation->signal;
  actuator.excitation.reset();
  const RunResult jumps = testing::RunActuator(instantaneous);
  ASSERT_EQ(jumps.stats.status, RunStatus::kCompleted) << jumps.stats.message;
  const double jump = LargestStep(jumps.trajectory, Tension);
  EXPECT_GT(jump, 50.0);
  EXPECT_LT(LargestStep(run.trajectory, Tension), 0.2 * jump);

  // the first twitch: u = 0 until the pulse at 0.1 s, the closed-form rise under e = 1 for
  // 10 ms, then the closed-form fall under e = 0
  const double rise_end = 0.11;
  const double peak = ActivationAfter(rise_end - 0.1, 1.0, 0.0);
  for (const TrajectoryPoint& p : run.trajectory) {
    if (p.t > 0.3) break;
    const double expected = p.t <= 0.1        ? 0.0
                            : p.t <= rise_end ? ActivationAfter(p.t - 0.1, 1.0, 0.0)
                                              : ActivationAfter(p.t - rise_end, 0.0, peak);
    // the file's rtol = 1e-6: the global error a few rtol, as for kTightError (8e-7 is seen)
    EXPECT_NEAR(p.sample.activation, expected, 1e-5) << "t = " << p.t;
  }
}

// ---- the two scenario forms -------------------------------------------------------------------

// scenarios/twitches.yaml written as a network (docs/model.md 7.4): ground, tip, actuator and
// damper, the two loads on the tip.
constexpr const char* kTwitchNetwork = R"(name: twitch_network
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians:
        - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
        - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
        - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
nodes:
  - {name: ground, fixed: 0.0}
  - {name: tip, mass: 0.1, position: 0.1}
elements:
  - {name: actuator, type: actuator, from: ground, to: tip, model: muscle,
     excitation: {type: pulses, start: 0.1, period: 0.2, width: 0.01, low: 0.0, high: 1.0},
     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}
  - {name: damper, type: damper, from: ground, to: tip, damping: 20.0}
loads:
  - {node: tip, type: constant, value: 20.0}
  - {node: tip, type: spring, stiffness: 500.0, anchor: 0.1}
time: {start: 0.0, end: 1.0}
output: {file: twitches_network.csv, interval: 0.0005}
)";

TEST(ActivationDynamics, SingleActuatorAndNetworkFormsGiveTheSameTrajectory) {
  const RunResult single =
      testing::RunActuator(LoadScenario(testing::ScenarioPath("twitches.yaml")));
  const Scenario network_scenario =
      LoadScenario(testing::WriteTempFile("network.yaml", kTwitchNetwork));
  Simulation simulation;
  const NetworkRunResult network =
      simulation.Run(network_scenario.Build(), network_scenario.solver, network_scenario.Request());
  ASSERT_EQ(single.stats.status, RunStatus::kCompleted) << single.stats.message;
  ASSERT_EQ(network.stats.status, RunStatus::kCompleted) << network.stats.message;
  ASSERT_EQ(single.trajectory.size(), network.times.size());
  // both run the one network of docs/model.md 7.4 (with activation dynamics the single
  // actuator has no right-hand side of its own) with the same settings: the same operations
  // on the same numbers, so the same bits
  for (std::size_t k = 0; k < network.times.size(); ++k) {
    const ActuatorSample& s = single.trajectory[k].sample;
    const ElementSample& e = network.samples[k].elements[0];
    ASSERT_EQ(single.trajectory[k].t, network.times[k]);
    EXPECT_EQ(s.length, e.length) << "t = " << network.times[k];
    EXPECT_EQ(s.activation, e.activation) << "t = " << network.times[k];
    EXPECT_EQ(s.excitation, e.excitation) << "t = " << network.times[k];
    EXPECT_EQ(s.tension.total, e.tension) << "t = " << network.times[k];
  }
}

// The CSV of scenarios/twitches.yaml (a single actuator with activation dynamics) with rows
// at the times `times`, the actuator's activation and excitation set, every other value 0.
std::string TwitchCsv(const std::vector<double>& times, double activation, double excitation) {
  const Scenario twitches = LoadScenario(testing::ScenarioPath("twitches.yaml"));
  const RunColumns columns(twitches, twitches.Build());
  NetworkSample sample;  // the network of docs/model.md 7.4: 2 nodes, 3 elements
  sample.position = sample.velocity = sample.load = {0.0, 0.0};
  sample.elements.resize(3);
  sample.elements[kActuatorElement].activation = activation;
  sample.elements[kActuatorElement].excitation = excitation;
  std::string csv = CsvHeader(columns) + "\n";
  std::vector<double> row(columns.size());
  for (double t : times) {
    columns.Fill(t, sample, row.data());
    AppendCsvRow(csv, columns, row.data());
    csv += "\n";
  }
  return csv;
}

TEST(ActivationDynamics, SingleActuatorCsvHasTheExcitationRightAfterTheActivation) {
  const std::string csv = TwitchCsv({0.25}, 0.5, 0.75);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "t,length,shortening_velocity,activation,excitation,tension_passive,tension_active,"
            "tension_total,load,phase");
  EXPECT_THAT(csv, HasSubstr("\n0.25,0,0,0.5,0.75,0,"));
}

TEST(ActivationDynamics, PlotsDrawTheExcitationDashedBesideTheActivation) {
  PlotOptions options;
  options.output = "x.png";
  const std::string single = testing::WriteTempFile("single.csv", TwitchCsv({0.0, 0.1}, 0.0, 1.0));
  const std::string script = TrajectoryPlotScript(ReadCsv(single), options);
  EXPECT_THAT(script, HasSubstr("$trajectory using 1:9 with lines lw 1 dt 2"));
  EXPECT_THAT(script, HasSubstr("title 'excitation'"));
  EXPECT_THAT(script, HasSubstr("\n0 0 0 0 0 0 0 0 1\n"));  // its inline column 9

  const std::string network = testing::WriteTempFile(
      "network.csv", "t,load.position,m.activation,m.excitation\n0,0.1,0.2,1\n0.1,0.1,0.3,1\n");
  EXPECT_THAT(NetworkPlotScript(ReadCsv(network), options),
              HasSubstr("$network using 1:4 with lines lw 1 dt 2 title 'm excitation'"));
}

// ---- overrides and sweeps reach the new keys ----------------------------------------------------

TEST(ActivationDynamics, SetReachesEveryKeyOfTheSingleActuatorForm) {
  const Scenario s = LoadScenario(
      testing::ScenarioPath("twitches.yaml"),
      {"activation_dynamics.tau_activation=0.02", "activation_dynamics.tau_deactivation=0.07",
       "initial.activation=0.3", "excitation.high=0.6"});
  const std::optional<ExcitationInput>& input = s.elements[kActuatorElement].excitation;
  ASSERT_TRUE(input.has_value());
  EXPECT_EQ(input->dynamics.tau_activation, 0.02);
  EXPECT_EQ(input->dynamics.tau_deactivation, 0.07);
  EXPECT_EQ(input->initial_activation.value_or(-1.0), 0.3);
  EXPECT_EQ(input->signal.high, 0.6);
}

TEST(ActivationDynamics, SetReachesEveryKeyOfANetworkActuator) {
  const Scenario spec =
      LoadScenario(testing::WriteTempFile("network.yaml", kTwitchNetwork),
                   {"elements[0].activation_dynamics.tau_deactivation=0.08",
                    "elements[0].initial_activation=0.25", "elements[0].excitation.width=0.02"});
  const std::optional<ExcitationInput>& input = spec.elements[0].excitation;
  ASSERT_TRUE(input.has_value());
  EXPECT_EQ(input->dynamics.tau_activation, 0.015);
  EXPECT_EQ(input->dynamics.tau_deactivation, 0.08);
  EXPECT_EQ(input->initial_activation.value_or(-1.0), 0.25);
  EXPECT_EQ(input->signal.width, 0.02);
}

TEST(ActivationDynamics, SweepAxesReachTheNewKeysOfBothForms) {
  const std::string base = testing::WriteTempFile(
      "base.yaml", testing::ReadFile(testing::ScenarioPath("twitches.yaml")));
  const SweepPlan single = LoadSweep(testing::WriteTempFile(
      "sweep.yaml", "base: " + std::filesystem::path(base).filename().string() +
                        "\nparameters:\n  activation_dynamics.tau_activation: [0.01, 0.03]\n"
                        "metrics: [peak_tension]\n"));
  const std::vector<Scenario>& points = single.spec.scenarios;
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].elements[kActuatorElement].excitation->dynamics.tau_activation, 0.01);
  EXPECT_EQ(points[1].elements[kActuatorElement].excitation->dynamics.tau_activation, 0.03);

  const std::string network = testing::WriteTempFile("network.yaml", kTwitchNetwork);
  const SweepPlan swept = LoadSweep(testing::WriteTempFile(
      "network_sweep.yaml", "base: " + std::filesystem::path(network).filename().string() +
                                "\nparameters:\n  elements[0].initial_activation: [0.1, 0.2]\n"
                                "metrics: [peak_tension]\n"));
  const std::vector<Scenario>& network_points = swept.spec.scenarios;
  ASSERT_EQ(network_points.size(), 2u);
  EXPECT_EQ(network_points[0].elements[0].excitation->initial_activation.value_or(-1.0), 0.1);
  EXPECT_EQ(network_points[1].elements[0].excitation->initial_activation.value_or(-1.0), 0.2);
}

// ---- validation in code ------------------------------------------------------------------------

TEST(ActivationDynamics, RejectsTimeConstantsOutsideTheirRangeAndAnActivationOutsideZeroOne) {
  const auto path_of = [](const std::function<void()>& make) -> std::string {
    try {
      make();
    } catch (const ParameterError& e) {
      return e.path();
    }
    return "accepted";
  };
  ExcitationInput input = Excitation(Waveform::Constant(0.5));
  input.dynamics.tau_activation = 0.0;
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "activation_dynamics.tau_activation");
  input.dynamics.tau_activation = kTauAct;
  input.dynamics.tau_deactivation = std::nan("");
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "activation_dynamics.tau_deactivation");
  input.dynamics.tau_deactivation = 11.0;
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "activation_dynamics.tau_deactivation");
  input.dynamics.tau_deactivation = kTauDeact;
  input.initial_activation = 1.5;
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "initial.activation");
  EXPECT_EQ(
      path_of([&] { Element::Actuator("m", "a", "b", testing::SharedCanonicalModel(), input); }),
      "initial_activation");
  input.initial_activation.reset();
  input.signal = Waveform::Step(0.1, 0.0, 1.2);
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "excitation.after");
  input.signal = Waveform::Constant(0.5);
  EXPECT_EQ(path_of([&] { ExcitedActuator(input); }), "accepted");
}

}  // namespace
}  // namespace musclesim
