// Runs through v = 0 with an asymmetric tension-velocity curve (docs/model.md section 9):
// the kink is a root function where the integrator restarts, and the trajectory agrees with
// a tight-tolerance run and with the steady velocities the curve's formulas give.
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/solver/simulation.h"
#include "support/canonical_actuator.h"

namespace musclesim {
namespace {

constexpr double kVMaxE = 0.5, kLimit = 1.8;  // m/s, -
constexpr int kNE = 2;

// The flat model of the solver tests (f_L ~ 1 over the motion, no passive tension), its
// eccentric branch with v_max_e = 0.5 m/s, n_e = 2, L = 1.8: slopes at rest -100 and
// -1414 per m/s (eps = 1e-3), a kink.
ModelParams AsymmetricFlatModel() {
  ModelParams p = testing::FlatModel();
  p.velocity.eccentric = {kVMaxE, kNE, kLimit};
  return p;
}

// Fully active from rest at 0.1 m, mass 0.01 kg; the load steps from 40 N (shortening) to
// 140 N (lengthening) at 0.1 s: one crossing of v = 0 there, after the one at the start.
testing::Experiment LoadReversal(const ModelParams& model, double rtol, double interval) {
  ActuatorParams actuator;
  actuator.mass = 0.01;
  RunRequest request;
  request.t_end = 0.3;
  request.length = 0.1;
  request.output_interval = interval;
  SolverOptions options;
  options.rtol = rtol;
  options.atol = 1e-3 * rtol;
  return {ActuatorSystem(model, actuator, Waveform::Constant(1.0),
                         {Load::Force(Waveform::Step(0.1, 40.0, 140.0))}),
          request, options};
}

TEST(EccentricSimulation, AnActuatorWithAKinkedCurveHasALengtheningRateKink) {
  const auto kinks = [](const ModelParams& model) {
    int count = 0;
    const ActuatorSystem system(model, ActuatorParams{}, Waveform::Constant(1.0), {});
    for (const NetworkSystem::Kink& k : system.network().kinks()) {
      count += k.kind == NetworkSystem::Kink::kLengtheningRate && k.level == 0.0;
    }
    return count;
  };
  EXPECT_EQ(kinks(AsymmetricFlatModel()), 1);
  EXPECT_EQ(kinks(testing::FlatModel()), 0);
  ModelParams limit_only = testing::FlatModel();
  limit_only.velocity.eccentric.limit = kLimit;  // the slopes at rest stay equal
  EXPECT_EQ(kinks(limit_only), 0);
}

TEST(EccentricSimulation, LoadReversalAgreesWithATightReference) {
  const RunResult run = LoadReversal(AsymmetricFlatModel(), 1e-8, 1e-3).Run();
  const RunResult reference = LoadReversal(AsymmetricFlatModel(), 1e-12, 1e-3).Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  ASSERT_EQ(reference.stats.status, RunStatus::kCompleted) << reference.stats.message;
  ASSERT_EQ(run.trajectory.size(), reference.trajectory.size());
  double error = 0.0;
  bool shortened = false, lengthened = false;
  for (std::size_t i = 0; i < run.trajectory.size(); ++i) {
    const ActuatorSample& a = run.trajectory[i].sample;
    const ActuatorSample& b = reference.trajectory[i].sample;
    error = std::max(error, std::abs(a.length - b.length) / b.length);
    shortened |= b.shortening_velocity > 0.1;
    lengthened |= b.shortening_velocity < -0.01;
  }
  EXPECT_TRUE(shortened && lengthened) << "the run must cross v = 0";
  // the global error CVODE leaves is a modest multiple of rtol (0.2 to 0.4 rtol in the
  // canonical runs); 100 rtol bounds it with room, and the reference's own is 1e-4 of that
  EXPECT_LT(error, 100 * 1e-8);
}

// The shortening velocity where f_iso f_L(x) g(v) = load, g written out from section 9,
// by bisection (g is decreasing).
double SteadyVelocity(double f_iso_f_l, double load) {
  const auto g = [](double v) {
    const double eps = 1e-3;
    const double phi_c = v * std::pow(v * v + eps * eps, (1.0 / 3.0 - 1.0) / 2.0);
    if (v >= 0) return 1.0 - phi_c;  // v_max = 1 m/s, n = 3
    const double psi =
        -v * std::pow(v * v + eps * eps, (1.0 / kNE - 1.0) / 2.0) / std::pow(kVMaxE, 1.0 / kNE);
    return 1.0 + (kLimit - 1.0) * std::tanh(psi / (kLimit - 1.0));
  };
  double lo = -10.0, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f_iso_f_l * g(mid) > load ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(EccentricSimulation, SettlesWhereTheEccentricBranchBalancesTheLoad) {
  const testing::Experiment experiment = LoadReversal(AsymmetricFlatModel(), 1e-10, 1e-3);
  const RunResult run = experiment.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const TensionModel& model = experiment.system.model();
  int checked = 0;
  for (const TrajectoryPoint& p : run.trajectory) {
    const bool settled = (p.t > 0.05 && p.t < 0.1) || p.t > 0.15;  // 1e-3 s transients
    if (!settled) continue;
    const double load = p.t < 0.1 ? 40.0 : 140.0;
    const double f_iso_f_l = 100.0 * model.active_length().Evaluate(p.sample.length).value;
    const double expected = SteadyVelocity(f_iso_f_l, load);
    // what is left is inertia, m dv/dt / (dT/dv), and the solver's error at rtol 1e-10:
    // 1e-5 relative leaves a margin of a hundred (as in the solver's own isotonic tests)
    EXPECT_NEAR(p.sample.shortening_velocity, expected, 1e-5 * std::abs(expected)) << p.t;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  // lengthening at the end: the eccentric branch, not the mirrored concentric one, is what
  // balanced 140 N (the mirrored one would give v = -(0.4)^3 = -0.064 m/s)
  EXPECT_LT(run.trajectory.back().sample.shortening_velocity, 0.0);
}

// The recorded points of every internal step (output interval 0) closest to v = 0 after
// the reversal: a restart at the kink records the root itself.
double ClosestToRest(const ModelParams& model) {
  const RunResult run = LoadReversal(model, 1e-8, 0.0).Run();
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  double closest = INFINITY;
  for (const TrajectoryPoint& p : run.trajectory) {
    if (p.t > 0.1) closest = std::min(closest, std::abs(p.sample.shortening_velocity));
  }
  return closest;
}

TEST(EccentricSimulation, TheIntegratorRestartsAtTheKink) {
  // CVODE locates a root to about 100 ulps of t; v changes at 1e4 m/s^2 there (140 N - 100 N
  // on 0.01 kg), so the recorded root has |v| below 1e-9 m/s. Without a kink no step lands
  // that close: the symmetric curve's steps straddle v = 0 by far more
  EXPECT_LT(ClosestToRest(AsymmetricFlatModel()), 1e-9);
  EXPECT_GT(ClosestToRest(testing::FlatModel()), 1e-7);
}

}  // namespace
}  // namespace musclesim
