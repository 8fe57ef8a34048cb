// Runs of the canonical networks (tests/support/canonical_networks.h, the systems of
// scenarios/{mass_spring_damper, antagonist_pair, musculotendon_isokinetic,
// millard_benchmark, chain}.yaml) against closed forms, a linearisation, a force balance,
// a static equilibrium and the energy balance of docs/model.md 7.5.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "musclesim/solver/simulation.h"
#include "support/canonical_networks.h"

namespace musclesim {
namespace {

using testing::NetworkExperiment;

int NodeIndex(const NetworkSystem& system, const std::string& name) {
  const int i = system.FindNode(name);
  EXPECT_GE(i, 0) << name;
  return i;
}

int ElementIndex(const NetworkSystem& system, const std::string& name) {
  const int e = system.FindElement(name);
  EXPECT_GE(e, 0) << name;
  return e;
}

NetworkRunResult RunCompleted(const NetworkExperiment& experiment) {
  NetworkRunResult run = experiment.Run();
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  return run;
}

// ---- (a) mass, spring and damper: the damped oscillator's closed form --------------------

// x(t) and xdot(t) of m xddot = F - k (x - l0) - c xdot, released at rest at x0.
struct Oscillator {
  double m, k, c, l0, force, x0;

  void At(double t, double& x, double& xdot) const {
    const double equilibrium = l0 + force / k;
    const double a = x0 - equilibrium;
    const double w0 = std::sqrt(k / m);
    const double zeta = c / (2.0 * std::sqrt(k * m));
    if (zeta < 1.0) {
      // e^(-zeta w0 t) (a cos wd t + b sin wd t), b from xdot(0) = 0
      const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
      const double b = zeta * w0 * a / wd;
      const double decay = std::exp(-zeta * w0 * t);
      const double cs = std::cos(wd * t), sn = std::sin(wd * t);
      x = equilibrium + decay * (a * cs + b * sn);
      xdot = decay * (-zeta * w0 * (a * cs + b * sn) + wd * (b * cs - a * sn));
    } else {
      // c1 e^(r1 t) + c2 e^(r2 t), c1 + c2 = a, r1 c1 + r2 c2 = 0
      const double root = w0 * std::sqrt(zeta * zeta - 1.0);
      const double r1 = -zeta * w0 + root, r2 = -zeta * w0 - root;
      const double c1 = -r2 * a / (r1 - r2), c2 = a - c1;
      x = equilibrium + c1 * std::exp(r1 * t) + c2 * std::exp(r2 * t);
      xdot = c1 * r1 * std::exp(r1 * t) + c2 * r2 * std::exp(r2 * t);
    }
  }
};

void ExpectClosedForm(double damping) {
  const NetworkExperiment experiment = testing::MassSpringDamper(damping);
  const NetworkRunResult run = RunCompleted(experiment);
  ASSERT_EQ(run.times.size(), 2001u);  // 2 s every 1 ms
  const int load = NodeIndex(experiment.system, "load");
  const Oscillator exact{testing::kMsdMass,       testing::kMsdStiffness, damping,
                         testing::kMsdRestLength, testing::kMsdLoad,      testing::kMsdStart};
  for (std::size_t i = 0; i < run.times.size(); ++i) {
    double x, xdot;
    exact.At(run.times[i], x, xdot);
    // at rtol 1e-12, atol 1e-14 the global error over 2 s (three periods) is some hundred
    // local errors of 1e-12 * 0.12 m, about 1e-11 m; 1e-8 m leaves a wide margin and still
    // fails on any error of the assembly (a wrong sign moves the mass by centimetres)
    EXPECT_NEAR(run.samples[i].position[load], x, 1e-8) << run.times[i];
    // the velocity's scale is the position's times w0 = 10 /s
    EXPECT_NEAR(run.samples[i].velocity[load], xdot, 1e-7) << run.times[i];
  }
}

TEST(NetworkSimulation, MassSpringDamperFollowsTheUnderdampedClosedForm) {
  ExpectClosedForm(testing::kMsdDamping);  // damping ratio 0.05
}

TEST(NetworkSimulation, MassSpringDamperFollowsTheOverdampedClosedForm) {
  ExpectClosedForm(20.0);  // damping ratio 2
}

// ---- (b) antagonist pair: equilibrium midway, and the frequency of co-contraction ---------

TEST(NetworkSimulation, AntagonistPairMidwayStaysStill) {
  const NetworkExperiment experiment = testing::AntagonistPair(testing::kPairHalfSpan);
  const NetworkRunResult run = RunCompleted(experiment);
  const int load = NodeIndex(experiment.system, "load");
  for (std::size_t i = 0; i < run.times.size(); ++i) {
    // both actuators are exactly 0.07 m long (0.14 - 0.07 is exact in binary) and evaluate
    // one model, so their tensions cancel to the last bit and the mass does not move at
    // all; 1e-12 m allows for rounding only (a tension added with the wrong sign would
    // move it by centimetres)
    EXPECT_NEAR(run.samples[i].position[load], testing::kPairHalfSpan, 1e-12) << run.times[i];
  }
}

TEST(NetworkSimulation, AntagonistPairOscillatesAtTheLinearisedFrequency) {
  const NetworkExperiment experiment = testing::AntagonistPair();
  const NetworkRunResult run = RunCompleted(experiment);
  const int load = NodeIndex(experiment.system, "load");

  // the linearisation about the midpoint from the model's curves, not from the network's
  // Jacobian: moving the mass by d lengthens the flexor and shortens the extensor by d, so
  // the restoring force is 2 dT/dl d and the damping force 2 (-dT/dv) d' (v = -dl/dt)
  const TensionModel model(testing::AntagonistModel());
  const TensionSample at = model.Evaluate(testing::kPairHalfSpan, 0.0, testing::kPairActivation);
  const double k_pair = 2.0 * at.d_length, c_pair = -2.0 * at.d_velocity;
  const double m = testing::kPairMass;
  const double w0 = std::sqrt(k_pair / m);
  const double zeta = c_pair / (2.0 * std::sqrt(k_pair * m));
  // damping small enough: it lowers the frequency by the factor sqrt(1 - zeta^2), by less
  // than 2e-5
  ASSERT_LT(0.5 * zeta * zeta, 2e-5);

  // zero crossings of x - midpoint, each by linear interpolation between samples 0.1 ms
  // apart (x'' is nearly 0 at a crossing: the interpolation's error is below 1e-9 s)
  std::vector<double> crossings;
  for (std::size_t i = 0; i + 1 < run.times.size(); ++i) {
    const double d0 = run.samples[i].position[load] - testing::kPairHalfSpan;
    const double d1 = run.samples[i + 1].position[load] - testing::kPairHalfSpan;
    if ((d0 < 0.0) != (d1 < 0.0)) {
      crossings.push_back(run.times[i] + (run.times[i + 1] - run.times[i]) * d0 / (d0 - d1));
    }
  }
  ASSERT_GE(crossings.size(), 20u);  // ten periods of 0.36 s in 4 s
  // the crossings of a damped oscillation are half a damped period apart, exactly
  const double measured = std::numbers::pi * static_cast<double>(crossings.size() - 1) /
                          (crossings.back() - crossings.front());
  // sqrt(k_pair / m) to the damping's shift zeta^2 / 2 (1.0e-5) and 1e-6 for the rest: the
  // cubic term of the pair's force, 1e-5 m out on curves some 1e-2 m wide, shifts the
  // frequency by about (1e-5 / 1e-2)^2; the solver's phase error at rtol 1e-10 is smaller
  EXPECT_NEAR(measured, w0, (0.5 * zeta * zeta + 1e-6) * w0);
  // and the damped frequency itself, to that 1e-6
  EXPECT_NEAR(measured, w0 * std::sqrt(1.0 - zeta * zeta), 1e-6 * w0);
}

// ---- (c) musculotendon unit: force balance at the junction ------------------------------

TEST(NetworkSimulation, MusculotendonJunctionBalancesTendonMuscleAndInertia) {
  const NetworkExperiment experiment = testing::MusculotendonIsokinetic();
  const NetworkRunResult run = RunCompleted(experiment);
  const int junction = NodeIndex(experiment.system, "junction");
  const int muscle = ElementIndex(experiment.system, "muscle");
  const int tendon = ElementIndex(experiment.system, "tendon");
  const double h = experiment.request.output_interval;
  const double passive_slack = testing::CanonicalModel().passive.slack_length;
  const auto v = [&](std::size_t i) { return run.samples[i].velocity[junction]; };
  const auto stretched = [&](std::size_t i) {
    return run.samples[i].elements[muscle].length > passive_slack;
  };

  double largest_inertia = 0.0;
  int checked = 0;
  for (std::size_t i = 2; i + 2 < run.times.size(); ++i) {
    const double t = run.times[i];
    // the junction's acceleration has kinks where the end's velocity jumps (0.2 s, 0.5 s)
    // and where the muscle crosses its passive slack length: no difference straddles one
    if (std::abs(t - 0.2) < 3.0 * h || std::abs(t - 0.5) < 3.0 * h) continue;
    if (stretched(i - 2) != stretched(i + 2)) continue;
    // m a = T_tendon - T_muscle: the tendon pulls the junction along +x, the muscle back
    const double gap =
        run.samples[i].elements[tendon].tension - run.samples[i].elements[muscle].tension;
    const double inertia = testing::kJunctionMass * (v(i + 1) - v(i - 1)) / (2.0 * h);
    // the central difference's error is h^2 v''' / 6, v''' from the five samples around;
    // twice that, plus 1e-6 N for tensions of states that CVODE interpolated to within
    // rtol 1e-10 (3e-11 m of tendon at 1e4 N/m, 1e-11 m/s at dT/dv ~ 1e4 N s/m: 3e-7 N)
    const double third =
        (v(i + 2) - 2.0 * v(i + 1) + 2.0 * v(i - 1) - v(i - 2)) / (2.0 * h * h * h);
    const double tolerance = 2.0 * testing::kJunctionMass * h * h / 6.0 * std::abs(third) + 1e-6;
    EXPECT_NEAR(inertia, gap, tolerance) << t;
    largest_inertia = std::max(largest_inertia, std::abs(inertia));
    ++checked;
  }
  EXPECT_GT(checked, 5900);  // of 6001 samples, all but those near a kink
  // the inertia term matters (it reaches 0.1 N as the stretch starts), far above the
  // tolerance's floor: the check is more than T_tendon = T_muscle
  EXPECT_GT(largest_inertia, 1e-2);
}

// ---- (d) chain: every segment settles at the length where T(l, 0, u) = F -----------------

// The length where T(l, 0, u) = force: bisection on the model over [0.14, 0.17] m, where
// T(l, 0, 0.2) increases (the passive slope outgrows the falling f_L).
double EquilibriumLength(const TensionModel& model, double u, double force) {
  double lo = 0.14, hi = 0.17;
  EXPECT_LT(model.Evaluate(lo, 0.0, u).total, force);
  EXPECT_GT(model.Evaluate(hi, 0.0, u).total, force);
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (model.Evaluate(mid, 0.0, u).total < force ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Every actuator's length in sample k of a chain's run, in the chain's order.
std::vector<double> SegmentLengths(const NetworkExperiment& experiment, const NetworkRunResult& run,
                                   std::size_t k) {
  std::vector<double> lengths;
  const std::vector<Element>& elements = experiment.system.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (elements[e].kind == ElementKind::kActuator) {
      lengths.push_back(run.samples[k].elements[e].length);
    }
  }
  return lengths;
}

TEST(NetworkSimulation, ChainSettlesWithEverySegmentAtTheStaticEquilibrium) {
  const double l_star = EquilibriumLength(TensionModel(testing::CanonicalModel()),
                                          testing::kChainActivation, testing::kChainLoad);
  ASSERT_GT(std::abs(l_star - testing::kChainStart), 5e-3);  // the chain has to move
  for (int n : {1, 10, 50}) {
    std::vector<double> dense_transient;
    for (LinearSolverKind solver : {LinearSolverKind::kDense, LinearSolverKind::kBand,
                                    LinearSolverKind::kSparse, LinearSolverKind::kSmall}) {
      if (solver == LinearSolverKind::kSmall && 2 * n > kSmallSystemMaxSize) continue;
      SCOPED_TRACE("n = " + std::to_string(n) + ", " + std::string(ToString(solver)));
      const NetworkExperiment experiment = testing::Chain(n, solver);
      const NetworkRunResult run = RunCompleted(experiment);
      EXPECT_EQ(run.stats.linear_solver, solver);
      const std::vector<double> settled = SegmentLengths(experiment, run, run.times.size() - 1);
      ASSERT_EQ(settled.size(), static_cast<std::size_t>(n));
      // after 5 s (80 time constants) nothing is left of the start; a settled state is
      // held within the solver's error weight rtol |x| <= 1e-8 * 7.5 m on positions, so
      // within 1.5e-7 m on their differences
      for (double l : settled) EXPECT_NEAR(l, l_star, 1.5e-7);
      // at 0.5 s, still moving (the 50 segments are 1e-3 m short of l*), the three linear
      // solvers give one trajectory: each is within its global error, some rtol (1e-8)
      // times the 7.5 m of the last position
      const std::vector<double> transient = SegmentLengths(experiment, run, 1);
      if (dense_transient.empty()) dense_transient = transient;
      for (std::size_t i = 0; i < transient.size(); ++i) {
        EXPECT_NEAR(transient[i], dense_transient[i], 1e-7) << "segment " << i + 1;
      }
    }
  }
}

// ---- (e) energy balance of docs/model.md 7.5 ---------------------------------------------

// Integral of T dl from the slack length: a linear tendon's k (l - l_s)^2 / 2.
double TendonEnergy(double l) {
  const double stretch = std::max(0.0, l - testing::kTendonSlack);
  return 0.5 * testing::kTendonStiffness * stretch * stretch;
}

// Integral of T_p dl of docs/model.md section 2 from the slack length x0:
// k_p ((e^(alpha s) - 1) / alpha - s) with s = l - x0 > 0.
double PassiveEnergy(const PassiveParams& p, double l) {
  const double s = std::max(0.0, l - p.slack_length);
  return p.k_p * (std::expm1(p.alpha * s) / p.alpha - s);
}

struct EnergyRecord {
  double t;       // [s]
  double energy;  // E_kin + E_el [J]
  double power;   // P_prescribed - P_damper - P_active [W]
};

// The terms of the balance at every recorded point of the musculotendon unit: a few numbers
// per point instead of its samples.
class EnergySink final : public NetworkSink {
 public:
  explicit EnergySink(const NetworkSystem& system)
      : junction_(NodeIndex(system, "junction")),
        end_(NodeIndex(system, "end")),
        muscle_(ElementIndex(system, "muscle")),
        tendon_(ElementIndex(system, "tendon")),
        damper_(ElementIndex(system, "fibre_damping")) {}

  void Record(double t, const NetworkSample& s) override {
    const double v = s.velocity[junction_];
    const ElementSample& muscle = s.elements[muscle_];
    const ElementSample& tendon = s.elements[tendon_];
    const ElementSample& damper = s.elements[damper_];
    const double energy = 0.5 * testing::kJunctionMass * v * v + TendonEnergy(tendon.length) +
                          PassiveEnergy(passive_, muscle.length);
    // the tendon pulls `end` with -T: moving it at p'(t) delivers T p'(t)
    const double delivered = tendon.tension * s.velocity[end_];
    const double dissipated =
        testing::kMillardFibreDamping * damper.lengthening_rate * damper.lengthening_rate;
    const double absorbed = muscle.parts.active * muscle.lengthening_rate;
    records.push_back({t, energy, delivered - dissipated - absorbed});
  }

  std::vector<EnergyRecord> records;

 private:
  int junction_, end_, muscle_, tendon_, damper_;
  PassiveParams passive_ = testing::CanonicalModel().passive;
};

double Trapezoid(const std::vector<EnergyRecord>& r) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    sum += 0.5 * (r[i + 1].t - r[i].t) * (r[i].power + r[i + 1].power);
  }
  return sum;
}

// Simpson's rule on pairs of unequal steps (the parabola through three points); a last odd
// step by the trapezoid rule.
double Simpson(const std::vector<EnergyRecord>& r) {
  double sum = 0.0;
  std::size_t i = 0;
  for (; i + 2 < r.size(); i += 2) {
    const double h0 = r[i + 1].t - r[i].t, h1 = r[i + 2].t - r[i + 1].t, h = h0 + h1;
    sum += h / 6.0 *
           ((2.0 - h1 / h0) * r[i].power + h * h / (h0 * h1) * r[i + 1].power +
            (2.0 - h0 / h1) * r[i + 2].power);
  }
  if (i + 1 < r.size()) sum += 0.5 * (r[i + 1].t - r[i].t) * (r[i].power + r[i + 1].power);
  return sum;
}

TEST(NetworkSimulation, MillardBenchmarkBalancesEnergy) {
  NetworkExperiment experiment = testing::MillardBenchmark();
  experiment.request.output_interval = 0.0;  // every internal step: the quadrature's grid
  EnergySink sink(experiment.system);
  Simulation simulation;
  const RunStats stats =
      simulation.Run(experiment.system, experiment.options, experiment.request, sink);
  ASSERT_EQ(stats.status, RunStatus::kCompleted) << stats.message;
  const std::vector<EnergyRecord>& r = sink.records;
  ASSERT_GT(r.size(), 1000u);

  const double change = r.back().energy - r.front().energy;
  const double supplied = Simpson(r);
  double throughput = 0.0;  // integral of |P| dt [J]
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    throughput += 0.5 * (r[i + 1].t - r[i].t) * (std::abs(r[i].power) + std::abs(r[i + 1].power));
  }
  // Simpson's rule on CVODE's steps errs by less than its distance from the trapezoid rule
  // (that distance estimates the trapezoid's error, O(h^2) where Simpson's is O(h^4): 1e-5
  // J against some 1e-8 J here); the solution itself is off by its global error, at most a
  // hundred times rtol (1e-8) of the energy passed through
  const double tolerance =
      std::abs(supplied - Trapezoid(r)) + 100.0 * experiment.options.rtol * throughput;
  EXPECT_NEAR(change, supplied, tolerance);
  // a balance worth checking: the tolerance is a small part of the energy passed through
  EXPECT_LT(tolerance, 1e-4 * throughput);
}

}  // namespace
}  // namespace musclesim
