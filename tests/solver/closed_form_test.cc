// Trajectories the solver must reproduce against closed-form solutions of docs/model.md
// section 6, m_eff xddot = F_load(t, x) - T(x, -xdot, u(t)) - c xdot - k (x - l0), in cases
// where that equation is linear: the solver is checked against mathematics, not against
// CVODE itself. Systems are built in code.
#include "musclesim/solver/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "support/canonical_actuator.h"

namespace musclesim {
namespace {

// Every run here integrates at rtol 1e-12, atol 1e-14 (m and m/s). rtol applies to the
// length, ~0.1 m, while the motions are millimetres to centimetres, so errors relative to
// the motion's scale are larger: below 2e-10 in these runs, and ~1e-9 for the undamped
// oscillation, whose phase error grows period after period. 1e-8 of the motion's scale
// leaves a margin of ten, while any error in the equations (a sign, a factor, a missing
// term) shows as a difference of order one.
constexpr double kAgreement = 1e-8;

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  return options;
}

// A model that pulls nothing when u = 0 and k_p = 0: T = 0 (docs/model.md section 5).
ModelParams SlackModel() { return testing::FlatModel(); }

// Runs `system` from `length` at lengthening rate `rate` over [0, t_end], recording every
// `interval` and at t_end, and checks the grid and every recorded length and shortening
// velocity against x(t) and xdot(t), to kAgreement of `length_scale` [m] and `rate_scale`
// [m/s].
void ExpectTrajectory(const ActuatorSystem& system, double length, double rate, double t_end,
                      double interval, const std::function<double(double)>& x,
                      const std::function<double(double)>& xdot, double length_scale,
                      double rate_scale) {
  RunRequest request;
  request.t_end = t_end;
  request.length = length;
  request.lengthening_rate = rate;
  request.output_interval = interval;
  Simulation simulation;
  const RunResult run = simulation.Run(system, Tight(), request);
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  // rows at 0, interval, 2 interval, ... below t_end, and one at t_end: 1 + ceil(t_end /
  // interval), the quotient's rounding error (below 1e-12 here) kept off an exact multiple
  const auto rows = static_cast<std::size_t>(std::ceil(t_end / interval - 1e-6)) + 1;
  ASSERT_EQ(run.trajectory.size(), rows);
  for (std::size_t k = 0; k + 1 < rows; ++k) {
    // k interval, computed once: rounding only
    EXPECT_NEAR(run.trajectory[k].t, static_cast<double>(k) * interval, 1e-15 * t_end) << k;
  }
  EXPECT_EQ(run.trajectory.back().t, t_end);
  for (const TrajectoryPoint& p : run.trajectory) {
    EXPECT_NEAR(p.sample.length, x(p.t), kAgreement * length_scale) << "t = " << p.t;
    // v = -xdot (section 1)
    EXPECT_NEAR(p.sample.shortening_velocity, -xdot(p.t), kAgreement * rate_scale) << "t = " << p.t;
  }
}

// (a) u = 0, k_p = 0: a mass between a parallel spring and damper, released from rest at
// l0 + y0. With omega0 = sqrt(k / m) and zeta = c / (2 sqrt(k m)), y = x - l0 obeys
// y'' + 2 zeta omega0 y' + omega0^2 y = 0, y(0) = y0, y'(0) = 0.
struct Oscillator {
  double mass = 0.1;          // [kg]
  double stiffness = 1000.0;  // [N/m]: omega0 = 100 rad/s, a period of 63 ms
  double damping = 0.0;       // [N s/m]
  double rest_length = 0.1;   // [m]
  double start = 0.11;        // x(0) [m], 1 cm from the rest length

  ActuatorSystem System() const {
    return ActuatorSystem(SlackModel(), {mass, damping, stiffness, rest_length},
                          Waveform::Constant(0.0), {});
  }
  double omega0() const { return std::sqrt(stiffness / mass); }
  double zeta() const { return damping / (2.0 * std::sqrt(stiffness * mass)); }
};

TEST(ClosedForm, UnderDampedSpringDamperOscillation) {
  Oscillator o;
  o.damping = 2.0;  // zeta = 0.1
  const double y0 = o.start - o.rest_length, w0 = o.omega0(), z = o.zeta();
  const double wd = w0 * std::sqrt(1.0 - z * z), decay = z * w0;
  // y = y0 e^(-zeta w0 t) (cos wd t + (zeta w0 / wd) sin wd t)
  const auto x = [&](double t) {
    return o.rest_length +
           y0 * std::exp(-decay * t) * (std::cos(wd * t) + decay / wd * std::sin(wd * t));
  };
  // y' = -y0 (w0^2 / wd) e^(-zeta w0 t) sin wd t
  const auto xdot = [&](double t) {
    return -y0 * w0 * w0 / wd * std::exp(-decay * t) * std::sin(wd * t);
  };
  // eight periods, the amplitude falling by e^-5; scales: y0 and its peak rate w0 y0
  ExpectTrajectory(o.System(), o.start, 0.0, 0.5, 1e-3, x, xdot, y0, w0 * y0);
}

TEST(ClosedForm, OverDampedSpringDamperCreep) {
  Oscillator o;
  o.damping = 60.0;  // zeta = 3
  const double y0 = o.start - o.rest_length, w0 = o.omega0(), z = o.zeta();
  // roots r1,2 = -zeta w0 +- w0 sqrt(zeta^2 - 1); y = y0 (r2 e^(r1 t) - r1 e^(r2 t)) / (r2 - r1)
  const double r1 = -z * w0 + w0 * std::sqrt(z * z - 1.0);
  const double r2 = -z * w0 - w0 * std::sqrt(z * z - 1.0);
  const auto x = [&](double t) {
    return o.rest_length + y0 * (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1);
  };
  const auto xdot = [&](double t) {
    return y0 * r1 * r2 * (std::exp(r1 * t) - std::exp(r2 * t)) / (r2 - r1);
  };
  // 0.3 s is five slow time constants 1 / |r1| = 59 ms; scales: y0 and the peak creep rate,
  // below w0 y0 / (2 zeta)
  ExpectTrajectory(o.System(), o.start, 0.0, 0.3, 1e-3, x, xdot, y0, w0 * y0 / (2.0 * z));
}

// The critically damped return, recorded every `interval` over 0.1 s.
void ExpectCriticallyDampedReturn(double interval) {
  Oscillator o;
  o.damping = 20.0;  // zeta = 1
  const double y0 = o.start - o.rest_length, w0 = o.omega0();
  // y = y0 (1 + w0 t) e^(-w0 t), y' = -y0 w0^2 t e^(-w0 t)
  const auto x = [&](double t) { return o.rest_length + y0 * (1.0 + w0 * t) * std::exp(-w0 * t); };
  const auto xdot = [&](double t) { return -y0 * w0 * w0 * t * std::exp(-w0 * t); };
  ExpectTrajectory(o.System(), o.start, 0.0, 0.1, interval, x, xdot, y0, w0 * y0);
}

TEST(ClosedForm, CriticallyDampedReturn) { ExpectCriticallyDampedReturn(1e-4); }

// An output interval that does not divide the span: rows every 3 ms up to 99 ms, then the
// last at t_end = 0.1 s, each on the closed form.
TEST(ClosedForm, OutputGridThatDoesNotDivideTheSpanEndsAtItsEnd) {
  ExpectCriticallyDampedReturn(3e-3);
}

// (b) n = 1 makes g linear, g(v) = 1 - v / v_max exactly, whatever eps (docs/model.md
// section 4: phi_eps(v) = v for n = 1). With f_L = 1 over the motion and k_p = 0, a
// constant load F and activation u give, with v = -xdot,
//   m xddot = F - u f_iso (1 + xdot / v_max),
// linear in xdot: from rest, xdot(t) = xdot_inf (1 - exp(-t / tau)) with
//   tau = m v_max / (u f_iso),   xdot_inf = v_max (F / (u f_iso) - 1)
// (negative, shortening, for F < u f_iso), and
//   x(t) = x0 + xdot_inf (t - tau (1 - exp(-t / tau))).
// f_L is one Gaussian centred at x0 with precision b = 1e-6 / m^2 (sigma = 1), so
// f_L(x) = exp(-b (x - x0)^2 / 2) >= 1 - b dx^2 / 2: over the motions below (|dx| <= 12 mm)
// it departs from 1 by 7.2e-11 at most, a force error of 7.2e-11 u f_iso, at most 1.2e-10
// of the |F - u f_iso| that drives the motion: below kAgreement by a factor of 80.
struct Isotonic {
  double f_iso = 100.0;   // [N]
  double v_max = 1.0;     // [m/s]
  double epsilon = 1e-3;  // [m/s], irrelevant for n = 1
  double u = 1.0;         // activation [-]
  double load = 40.0;     // F [N]
  double mass = 0.1;      // [kg]: tau = 1 ms at u f_iso = 100 N
  double start = 0.1;     // x0 [m]

  ActuatorSystem System() const {
    ModelParams p;
    p.f_iso = f_iso;
    p.passive = {0.0, 100.0, 0.105};
    p.active_length = {0.095, 0.105, 1.0, {{1.0, 1e-6, start}}};
    p.velocity = {v_max, 1, epsilon};
    ActuatorParams actuator;
    actuator.mass = mass;
    return ActuatorSystem(p, actuator, Waveform::Constant(u), {Load::Constant(load)});
  }
  double tau() const { return mass * v_max / (u * f_iso); }
  double rate_limit() const { return v_max * (load / (u * f_iso) - 1.0); }

  void ExpectClosedForm() const {
    const double tau = this->tau(), w = rate_limit();
    const auto x = [&](double t) { return start + w * (t - tau * (1.0 - std::exp(-t / tau))); };
    const auto xdot = [&](double t) { return w * (1.0 - std::exp(-t / tau)); };
    // ten time constants; scales: the distance travelled and the terminal rate
    const double t_end = 10.0 * tau;
    ExpectTrajectory(System(), start, 0.0, t_end, tau / 20.0, x, xdot, std::abs(w) * t_end,
                     std::abs(w));
  }
};

TEST(ClosedForm, IsotonicShorteningWithLinearTensionVelocity) {
  Isotonic concentric;  // F = 40 N < f_iso: shortens towards 0.6 m/s
  concentric.ExpectClosedForm();
  Isotonic partial = concentric;  // half activation: tau doubles, 20 N of 50 N
  partial.u = 0.5;
  partial.load = 20.0;
  partial.ExpectClosedForm();
}

TEST(ClosedForm, IsotonicLengtheningWithLinearTensionVelocity) {
  Isotonic eccentric;  // F = 130 N > f_iso: lengthens towards 0.3 m/s, g unclipped above 1
  eccentric.load = 130.0;
  eccentric.ExpectClosedForm();
}

TEST(ClosedForm, EpsilonChangesNothingWhenNIsOne) {
  Isotonic wide;  // eps at its largest allowed value, v_max, above every velocity of the run
  wide.epsilon = wide.v_max;
  wide.ExpectClosedForm();
}

// (c) u = 0, k_p = 0, a hanging mass M on a spring load k_s to an anchor: the weight M g
// and the mass M join the actuator's (docs/model.md section 6), so
//   (m + M) xddot = M g + k_s (anchor - x),
// an undamped oscillation about x_eq = anchor + M g / k_s at omega = sqrt(k_s / (m + M)).
TEST(ClosedForm, HangingMassOnASpringOscillatesAboutItsEquilibrium) {
  const double m = 0.1, hanging = 2.0, gravity = 9.81, k_s = 4000.0, anchor = 0.09;
  const ActuatorSystem system(SlackModel(), {m, 0.0, 0.0, 0.0}, Waveform::Constant(0.0),
                              {Load::Mass(hanging, gravity), Load::Spring(k_s, anchor)});
  const double equilibrium = anchor + hanging * gravity / k_s;  // 0.0949 m
  const double omega = std::sqrt(k_s / (m + hanging)), start = 0.12;
  const double y0 = start - equilibrium;
  const auto x = [&](double t) { return equilibrium + y0 * std::cos(omega * t); };
  const auto xdot = [&](double t) { return -y0 * omega * std::sin(omega * t); };
  // seven periods of 144 ms, 2.5 cm either side of the equilibrium
  ExpectTrajectory(system, start, 0.0, 1.0, 1e-3, x, xdot, std::abs(y0), omega * std::abs(y0));
}

// (c) A free mass (u = 0, k_p = 0, no spring) launched at a lengthening rate w0 and pushed
// from t_s on by a step force F: x = x0 + w0 t + F (t - t_s)^2 / (2 m) after t_s. The step
// is a breakpoint at which the integrator must stop and restart (section 6): a step taken
// across it would smear the kink in xdot.
TEST(ClosedForm, StepForceOnAFreeMassStartsExactlyAtItsTime) {
  const double m = 0.5, force = 2.0, t_s = 0.0437, w0 = -0.05, x0 = 0.1;
  const ActuatorSystem system(SlackModel(), {m, 0.0, 0.0, 0.0}, Waveform::Constant(0.0),
                              {Load::Force(Waveform::Step(t_s, 0.0, force))});
  const auto after = [&](double t) { return std::max(0.0, t - t_s); };
  const auto x = [&](double t) { return x0 + w0 * t + force * after(t) * after(t) / (2.0 * m); };
  const auto xdot = [&](double t) { return w0 + force * after(t) / m; };
  // scales: the displacement the force makes by the end, 2.4 cm, and the rate it adds
  const double pushed = 0.2 - t_s;
  ExpectTrajectory(system, x0, w0, 0.2, 1e-3, x, xdot, force * pushed * pushed / (2.0 * m),
                   force * pushed / m);
}

// (c) The same free mass under a constant force reaching a length limit: it starts at rest
// and shortens with x = x0 - a t^2 / 2, a = F / m, so x reaches x_min at
// t* = sqrt(2 (x0 - x_min) / a). CVODE's root finding locates t* to ~1e-14 s.
TEST(ClosedForm, LengthLimitIsReachedAtTheClosedFormTime) {
  const double m = 0.2, force = -1.0, x0 = 0.1, x_min = 0.08;
  const ActuatorSystem system(SlackModel(), {m, 0.0, 0.0, 0.0}, Waveform::Constant(0.0),
                              {Load::Constant(force)});
  RunRequest request;
  request.t_end = 1.0;
  request.length = x0;
  request.min_length = x_min;
  Simulation simulation;
  const RunResult run = simulation.Run(system, Tight(), request);
  ASSERT_EQ(run.stats.status, RunStatus::kLimit) << run.stats.message;
  const double arrival = std::sqrt(2.0 * (x0 - x_min) / (-force / m));  // 0.0894 s
  // the root's time to 1e-8 of itself (see kAgreement); the length there to 1e-8 of the
  // 2 cm travelled
  EXPECT_NEAR(run.stats.final_time, arrival, kAgreement * arrival);
  EXPECT_NEAR(run.trajectory.back().sample.length, x_min, kAgreement * (x0 - x_min));
  EXPECT_NEAR(run.trajectory.back().sample.shortening_velocity, -force / m * arrival,
              kAgreement * (-force / m * arrival));
}

}  // namespace
}  // namespace musclesim
