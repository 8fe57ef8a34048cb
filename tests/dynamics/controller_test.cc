// Feedback controllers in the network core (docs/model.md section 11): the Jacobian with the
// feedback terms against central differences and against CVODE's own difference quotients,
// the integral's conditional integration (no wind-up, no stall along a bound), and the
// refusals of NetworkSystem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "musclesim/core/errors.h"
#include "support/control_networks.h"
#include "support/difference_jacobian.h"

namespace musclesim {
namespace {

using testing::AwayFromKinks;
using testing::ExpectJacobianMatchesDifferences;
using testing::NetworkExperiment;

// The states y(t) of a run at `times`.
std::vector<std::vector<double>> StatesAt(const NetworkExperiment& experiment,
                                          std::vector<double> times) {
  struct Keep : NetworkSink {
    int n;
    std::vector<std::vector<double>> states;
    explicit Keep(int size) : n(size) {}
    void Record(double, const NetworkSample&) override {}
    bool RecordState(double, const double* y) override {
      states.emplace_back(y, y + n);
      return true;
    }
  } keep(experiment.system.state_size());
  NetworkRunRequest request = experiment.request;
  request.output_times = std::move(times);
  Simulation simulation;
  const RunStats stats = simulation.Run(experiment.system, experiment.options, request, keep);
  EXPECT_EQ(stats.status, RunStatus::kCompleted) << stats.message;
  return keep.states;
}

// A controlled actuator without activation dynamics whose own length is held by PD control
// (more activation shortens it: negative gains), and a spring whose tension a second,
// PI, controller regulates through another actuator: length and tension measures, kd and
// ki, on one network.
NetworkExperiment LengthAndSpringLoops() {
  const auto model = testing::SharedCanonicalModel();
  std::vector<Controller> controllers = {
      Controller::Pid("length", {"muscle", "", MeasuredQuantity::kLength},
                      Waveform::Sine(0.099, 0.002, 2.0), {-200.0, 0.0, -5.0}, "muscle"),
      Controller::Pid("spring_force", {"spring", "", MeasuredQuantity::kTension},
                      Waveform::Constant(5.0), {0.01, 0.5, 0.0}, "helper")};
  controllers[0].feedforward = Waveform::Constant(0.3);
  return {NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("tip", 0.1, 0.1),
                         Node::Free("end", 0.2, 0.2), Node::Fixed("far", 0.31)},
                        {Element::ControlledActuator("muscle", "wall", "tip", model),
                         Element::Spring("spring", "tip", "end", 2000.0, 0.1),
                         Element::ControlledActuator("helper", "end", "far", model),
                         Element::Damper("damper", "tip", "end", 5.0)},
                        {{"tip", Load::Constant(10.0)}}, std::move(controllers)),
          testing::Span(1.0, 1e-3), testing::Tolerances(1e-10, 1e-12)};
}

// Central differences of size 1e-7 see each side of a kink only 1e-7 (in y's units) from it.
constexpr double kStep = 1e-7;
constexpr double kKinkMargin = 1e-5;

void ExpectJacobianAlongRun(const NetworkExperiment& experiment, std::vector<double> times) {
  const std::vector<std::vector<double>> states = StatesAt(experiment, times);
  ASSERT_EQ(states.size(), times.size());
  int checked = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!AwayFromKinks(experiment.system, times[i], states[i], kKinkMargin)) continue;
    ExpectJacobianMatchesDifferences(experiment.system, times[i], states[i], kStep);
    ++checked;
  }
  EXPECT_GE(checked, static_cast<int>(times.size()) / 2) << "most states near a kink";
}

TEST(ControllerJacobian, ForceLoopThroughActivationDynamicsMatchesDifferences) {
  ExpectJacobianAlongRun(testing::ForceRegulation(), {0.06, 0.08, 0.12, 0.2, 0.35, 0.7});
}

TEST(ControllerJacobian, CoContractingPairWithDerivativeMatchesDifferences) {
  ExpectJacobianAlongRun(testing::PositionTracking(), {0.03, 0.2, 0.45, 0.8, 1.3, 2.6});
}

TEST(ControllerJacobian, LengthAndTensionLoopsWithoutActivationDynamicsMatchDifferences) {
  ExpectJacobianAlongRun(LengthAndSpringLoops(), {0.05, 0.15, 0.3, 0.55, 0.9});
}

TEST(ControllerJacobian, InsideTheIntegralsFadeBandMatchesDifferences) {
  // the force loop with an unreachable reference: err > 0, and z set so that c sits in the
  // middle of the band below 1, where zdot = err (1 - c) / band
  const NetworkExperiment experiment = testing::ForceRegulation(Waveform::Constant(200.0));
  std::vector<double> y = StatesAt(testing::ForceRegulation(), {0.7}).front();
  const NetworkSystem& system = experiment.system;
  NetworkSample sample;
  system.Observe(0.7, y.data(), sample);
  const double error = sample.controllers[0].reference - sample.controllers[0].measured;
  const int z = system.IntegralStateIndex(0);
  y[z] = (1.0 - 0.5 * kIntegralFadeBand - testing::kForceKp * error) / testing::kForceKi;
  std::vector<double> rate(y.size());
  system.RightHandSide(0.7, y.data(), rate.data());
  // halfway into the band the integral runs at half speed: the band is really entered
  EXPECT_NEAR(rate[z], 0.5 * error, 1e-9 * error);
  ExpectJacobianMatchesDifferences(system, 0.7, y, kStep);
}

TEST(ControllerJacobian, AnalyticAndCvodesDifferenceQuotientRunsAgree) {
  for (const NetworkExperiment& base :
       {testing::ForceRegulation(), testing::PositionTracking(), LengthAndSpringLoops()}) {
    NetworkExperiment quotient = base;
    quotient.options.jacobian = JacobianKind::kDifferenceQuotient;
    quotient.options.linear_solver = LinearSolverKind::kDense;
    const NetworkRunResult analytic = base.Run();
    const NetworkRunResult differenced = quotient.Run();
    ASSERT_EQ(analytic.stats.status, RunStatus::kCompleted) << analytic.stats.message;
    ASSERT_EQ(differenced.stats.status, RunStatus::kCompleted) << differenced.stats.message;
    ASSERT_EQ(analytic.times.size(), differenced.times.size());
    for (std::size_t i = 0; i < analytic.times.size(); ++i) {
      for (std::size_t node = 0; node < analytic.samples[i].position.size(); ++node) {
        // both meet rtol 1e-10 on positions of order 0.1 m; the global error is a few
        // hundred times the local one
        EXPECT_NEAR(analytic.samples[i].position[node], differenced.samples[i].position[node], 1e-8)
            << "t = " << analytic.times[i];
      }
    }
  }
}

// ---- conditional integration -----------------------------------------------------------

TEST(ControllerIntegral, StopsAtTheBoundInsteadOfWindingUp) {
  // 200 N is beyond the actuator (f_iso = 100 N): the excitation saturates at 1 for 0.5 s;
  // then the reference drops to 20 N, which the loop reaches again
  const NetworkExperiment experiment = testing::ForceRegulation(Waveform::Step(0.5, 200.0, 20.0));
  const int z = experiment.system.IntegralStateIndex(0);
  std::vector<double> times;
  for (double t = 0.1; t < 0.5; t += 0.05) times.push_back(t);
  const std::vector<std::vector<double>> states = StatesAt(experiment, times);
  for (std::size_t i = 0; i < states.size(); ++i) {
    NetworkSample sample;
    experiment.system.Observe(times[i], states[i].data(), sample);
    const ControllerSample& c = sample.controllers[0];
    // saturated: the excitation within the integral's fade band of its bound
    EXPECT_GT(c.output, 1.0 - kIntegralFadeBand) << "t = " << times[i];
    // and the integral has not pushed the command past it: kp err + ki z <= 1, where an
    // integral winding up would reach ki * 0.4 s * 100 N = 6
    const double command = testing::kForceKp * c.error + testing::kForceKi * states[i][z];
    EXPECT_LE(command, 1.0 + 1e-9) << "t = " << times[i];
  }
  // so the drop to 20 N is followed within the loop's settling time (0.3 s), not after
  // unwinding 0.4 s of 100 N of error
  const NetworkRunResult run = experiment.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  EXPECT_NEAR(run.samples.back().controllers[0].measured, 20.0, 0.01);
}

TEST(ControllerIntegral, SlidesAlongItsBoundWithoutStalling) {
  // a reference the actuator can just not reach: the excitation settles at its bound with
  // the integral in its fade band, not chattering between integrating and frozen
  const NetworkExperiment experiment = testing::ForceRegulation(Waveform::Constant(100.2));
  const NetworkRunResult run = experiment.Run();
  ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  // a chattering integral would need a restart per switch: thousands over 1 s
  EXPECT_LT(run.stats.steps, 3000);
  const NetworkSample& last = run.samples.back();
  EXPECT_GT(last.controllers[0].output, 1.0 - kIntegralFadeBand);
  EXPECT_GT(last.controllers[0].error, 0.0);
}

// ---- refusals ---------------------------------------------------------------------------

// The ParameterError path NetworkSystem throws for `controllers`, with the pair's actuators.
std::string PathOfRefusal(std::vector<Controller> controllers, bool dynamics = false) {
  const auto model = testing::PairModel();
  const auto actuator = [&](const char* name, const char* from, const char* to) {
    return dynamics ? Element::ControlledActuator(name, from, to, model, ActivationDynamics{})
                    : Element::ControlledActuator(name, from, to, model);
  };
  try {
    NetworkSystem(
        {Node::Fixed("wall_a", 0.0), Node::Free("load", 1.0, 0.07), Node::Fixed("wall_b", 0.14)},
        {actuator("flexor", "wall_a", "load"), actuator("extensor", "load", "wall_b"),
         Element::Spring("spring", "wall_a", "load", 10.0, 0.07)},
        {}, std::move(controllers));
  } catch (const ParameterError& e) {
    return e.path();
  }
  return "accepted";
}

Controller Drive(const char* name, Measurement measure, const char* actuator) {
  return Controller::Pid(name, std::move(measure), Waveform::Constant(0.07), {1.0, 0.0, 0.0},
                         actuator);
}

TEST(ControllerRefusals, NameWhatBreaksWhichRule) {
  const Measurement position{"", "load", MeasuredQuantity::kPosition};
  const Measurement flexor_tension{"flexor", "", MeasuredQuantity::kTension};
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("b", position, "extensor")}),
            "accepted");
  // the same actuator twice, an undriven one, a spring driven, an unknown one
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("b", position, "flexor")}),
            "controllers[1].drives");
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor")}), "elements[1].name");
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("b", position, "spring")}),
            "controllers[1].drives");
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("b", position, "nothing")}),
            "controllers[1].drives");
  // measures: a fixed node, an unknown element
  EXPECT_EQ(PathOfRefusal({Drive("a", {"", "wall_a", MeasuredQuantity::kPosition}, "flexor"),
                           Drive("b", position, "extensor")}),
            "controllers[0].measure.node");
  EXPECT_EQ(PathOfRefusal({Drive("a", {"bone", "", MeasuredQuantity::kLength}, "flexor"),
                           Drive("b", position, "extensor")}),
            "controllers[0].measure.element");
  // algebraic loops: its own tension, or another controller's actuator's, without
  // activation dynamics; with them both are states and fine
  EXPECT_EQ(PathOfRefusal({Drive("a", flexor_tension, "flexor"), Drive("b", position, "extensor")}),
            "controllers[0].measure.element");
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("b", flexor_tension, "extensor")}),
            "controllers[1].measure.element");
  EXPECT_EQ(
      PathOfRefusal({Drive("a", flexor_tension, "flexor"), Drive("b", flexor_tension, "extensor")},
                    true),
      "accepted");
  // a derivative gain on a tension; names shared
  Controller derivative = Drive("a", {"spring", "", MeasuredQuantity::kTension}, "flexor");
  derivative.gains.kd = 0.1;
  EXPECT_EQ(PathOfRefusal({derivative, Drive("b", position, "extensor")}),
            "controllers[0].gains.kd");
  EXPECT_EQ(PathOfRefusal({Drive("a", position, "flexor"), Drive("a", position, "extensor")}),
            "controllers[1].name");
}

TEST(ControllerRefusals, ActuatorWithItsOwnActivationIsNotDriven) {
  const auto model = testing::PairModel();
  try {
    NetworkSystem({Node::Fixed("wall", 0.0), Node::Free("load", 1.0, 0.07)},
                  {Element::Actuator("muscle", "wall", "load", model, Waveform::Constant(0.2))}, {},
                  {Drive("a", {"", "load", MeasuredQuantity::kPosition}, "muscle")});
    FAIL() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "controllers[0].drives");
    EXPECT_NE(e.rule().find("activation of its own"), std::string::npos) << e.rule();
  }
}

}  // namespace
}  // namespace musclesim
