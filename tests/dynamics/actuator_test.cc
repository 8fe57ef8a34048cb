#include "musclesim/dynamics/actuator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "musclesim/core/errors.h"

#include "support/numeric.h"

namespace musclesim {
namespace {

ModelParams Model() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {1.0, 100.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{2.0, 4000.0, 0.1}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

ActuatorSystem System() {
  Waveform activation;
  activation.kind = WaveformKind::kConstant;
  activation.value = 0.7;
  Load force;
  force.force.kind = WaveformKind::kSine;
  force.force.offset = 30.0;
  force.force.amplitude = 5.0;
  force.force.frequency = 2.0;
  Load spring{LoadKind::kSpring, {}, 200.0, 0.12, 0.0, 9.81};
  Load weight{LoadKind::kMass, {}, 0.0, 0.0, 2.0, 9.81};
  return ActuatorSystem(Model(), {0.1, 3.0, 50.0, 0.1}, activation, {force, spring, weight});
}

TEST(Actuator, AccelerationIsNewtonsLawOfMotionSection6) {
  const ActuatorSystem system = System();
  const TensionModel model(Model());
  const double t = 0.3, x = 0.107, xdot = -0.02;
  const double load = 30.0 + 5.0 * std::sin(2 * M_PI * 2.0 * t) + 200.0 * (0.12 - x) + 2.0 * 9.81;
  const double expected =
      (load - model.Evaluate(x, -xdot, 0.7).total - 3.0 * xdot - 50.0 * (x - 0.1)) / (0.1 + 2.0);
  EXPECT_NEAR(system.Acceleration(t, x, xdot), expected, 1e-12 * std::abs(expected));
  EXPECT_DOUBLE_EQ(system.effective_mass(), 2.1);
  EXPECT_NEAR(system.Observe(t, x, xdot).load, load, 1e-12 * load);
}

TEST(Actuator, JacobianMatchesFiniteDifferences) {
  const ActuatorSystem system = System();
  for (double x : {0.09, 0.1, 0.11}) {
    for (double xdot : {-0.3, -0.0005, 0.0, 0.002, 0.4}) {
      const ActuatorSystem::JacobianRow row = system.Jacobian(0.2, x, xdot);
      const double by_x = testing::CentralDifference(
          [&](double y) { return system.Acceleration(0.2, y, xdot); }, x, 1e-7);
      const double by_rate = testing::CentralDifference(
          [&](double w) { return system.Acceleration(0.2, x, w); }, xdot, 1e-8);
      EXPECT_NEAR(row.by_length, by_x, 1e-5 * std::max(1.0, std::abs(by_x)));
      EXPECT_NEAR(row.by_rate, by_rate, 1e-5 * std::max(1.0, std::abs(by_rate)));
    }
  }
}

TEST(Actuator, SystemsShareOneImmutableModel) {
  const auto model = std::make_shared<const TensionModel>(Model());
  const ActuatorSystem a(model, {0.1, 0.0, 0.0, 0.0}, Waveform::Constant(1.0),
                         {Load::Constant(30.0)});
  const ActuatorSystem b(model, {0.5, 0.0, 0.0, 0.0}, Waveform::Constant(0.5),
                         {Load::Spring(200.0, 0.12), Load::Mass(2.0)});
  EXPECT_EQ(&a.model(), model.get());
  EXPECT_EQ(&b.model(), model.get());
  // the network form (docs/model.md 7.4) points at the same model too: no copy anywhere
  EXPECT_EQ(a.network().elements()[0].model.get(), model.get());
  EXPECT_EQ(b.network().elements()[0].model.get(), model.get());
  // each system's own inputs: m xddot = F - T(x, v, u) with its mass, load and activation
  const double x = 0.1, xdot = -0.01;
  EXPECT_NEAR(a.Acceleration(0.0, x, xdot), (30.0 - model->Evaluate(x, -xdot, 1.0).total) / 0.1,
              1e-9);
  EXPECT_NEAR(b.Acceleration(0.0, x, xdot),
              (200.0 * (0.12 - x) + 2.0 * 9.81 - model->Evaluate(x, -xdot, 0.5).total) / 2.5, 1e-9);
}

TEST(Actuator, LoadFactoriesRejectBrokenLoads) {
  EXPECT_THROW(Load::Spring(-1.0, 0.1), ParameterError);
  EXPECT_THROW(Load::Mass(0.0), ParameterError);
  EXPECT_THROW(Load::Constant(std::nan("")), ParameterError);
}

}  // namespace
}  // namespace musclesim
