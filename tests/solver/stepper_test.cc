// Stepper: a network driven piece by piece from outside against one-shot runs of the same
// system (Simulation::Run), an input set between pieces against the same input as a
// waveform, and an external sampled PID against the network's own continuous one.
#include "musclesim/solver/stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "musclesim/core/errors.h"
#include "support/canonical_networks.h"

namespace musclesim {
namespace {

using testing::AntagonistModel;

// The test rig: `muscle` (AntagonistModel, f_iso = 100 N) from a wall at 0 pulls a 0.1 kg
// `load` starting at rest at 0.1 m against a transducer `spring` (1000 N/m, slack at the
// start) and a `damper` (10 N s/m) in parallel to a wall at 0.2 m: the load's mode rings at
// sqrt(1000 / 0.1) = 100 rad/s with a damping ratio near 0.5. The spring's tension is what
// the loops measure.
constexpr double kMass = 0.1, kStiffness = 1000.0, kDamping = 10.0;
constexpr ActivationDynamics kDynamics{0.015, 0.05};

NetworkSystem Rig(Element muscle, std::vector<Controller> controllers = {}) {
  return NetworkSystem(
      {Node::Fixed("wall", 0.0), Node::Free("load", kMass, 0.1), Node::Fixed("wall_b", 0.2)},
      {std::move(muscle), Element::Spring("spring", "load", "wall_b", kStiffness, 0.1),
       Element::Damper("damper", "load", "wall_b", kDamping)},
      {}, std::move(controllers));
}

std::shared_ptr<const TensionModel> Model() {
  return std::make_shared<const TensionModel>(AntagonistModel());
}

NetworkSystem WithActivation(Waveform activation) {
  return Rig(Element::Actuator("muscle", "wall", "load", Model(), std::move(activation)));
}

NetworkSystem WithExcitation(Waveform excitation) {
  return Rig(Element::Actuator("muscle", "wall", "load", Model(),
                               ExcitationInput{std::move(excitation), kDynamics, 0.0}));
}

// A PI loop on the spring's tension (kd must be 0 on a tension) through activation dynamics.
// The plant from excitation to tension is about G / (tau s + 1), G = f_iso f_L near 60 N,
// tau = 15 to 50 ms: ki = 1 / (G 50 ms) gives a closed loop near 50 ms, and kp = ki tau
// cancels the lag's pole; the excitation stays within (0.05, 0.5), clear of the clamps.
constexpr double kReference = 15.0;  // [N]
constexpr PidGains kGains{0.01, 0.3, 0.0};

NetworkSystem WithController() {
  return Rig(Element::ControlledActuator("muscle", "wall", "load", Model(), kDynamics, 0.0),
             {Controller::Pid("loop", {"spring", "", MeasuredQuantity::kTension},
                              Waveform::Constant(kReference), kGains, "muscle")});
}

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-12;
  return options;
}

// The one-shot run of `system` over [0, t_end], a row every millisecond.
NetworkRunResult OneShot(const NetworkSystem& system, double t_end, double interval = 1e-3) {
  NetworkRunRequest request;
  request.t_end = t_end;
  request.output_interval = interval;
  Simulation simulation;
  return simulation.Run(system, Tight(), request);
}

// Each state's scale over a run: the largest magnitude its rows reach, with the nodes'
// positions and velocities, the activation and the integral read from the samples.
struct Scales {
  double position = 0.0, velocity = 0.0, tension = 0.0;
};

Scales ScalesOf(const NetworkRunResult& run) {
  Scales s;
  for (const NetworkSample& sample : run.samples) {
    s.position = std::max(s.position, std::abs(sample.position[1]));
    s.velocity = std::max(s.velocity, std::abs(sample.velocity[1]));
    s.tension = std::max(s.tension, std::abs(sample.elements[1].tension));
  }
  return s;
}

// Two integrations of one system at rtol 1e-10 are each within their global error of the
// solution: over a second of a damped ring-down up to some hundreds of times the local
// tolerance, rtol |y| + atol (these agree within 100 of it); 1e3 of it is still far below
// any change an input makes (1e-7 of a 0.1 m position) and catches a restart that loses
// the state or the time.
constexpr double kAgreement = 1e3;

void ExpectSameRun(const NetworkRunResult& reference, Stepper& stepper, double t_end) {
  const Scales scale = ScalesOf(reference);
  const SolverOptions o = Tight();
  std::size_t row = 1;  // the row at 1 ms
  for (int k = 1; k <= static_cast<int>(std::lround(t_end / 1e-3)); ++k, ++row) {
    ASSERT_EQ(stepper.Advance(k * 1e-3), RunStatus::kCompleted) << stepper.message();
    ASSERT_LT(row, reference.times.size());
    ASSERT_EQ(stepper.time(), reference.times[row]);
    const NetworkSample& a = stepper.sample();
    const NetworkSample& b = reference.samples[row];
    ASSERT_NEAR(a.position[1], b.position[1], kAgreement * (o.rtol * scale.position + o.atol))
        << "t = " << stepper.time();
    ASSERT_NEAR(a.velocity[1], b.velocity[1], kAgreement * (o.rtol * scale.velocity + o.atol))
        << "t = " << stepper.time();
    // a tension is stiffness x position: its error scales with the position's
    ASSERT_NEAR(a.elements[1].tension, b.elements[1].tension,
                kAgreement * kStiffness * (o.rtol * scale.position + o.atol));
    ASSERT_NEAR(a.elements[0].activation, b.elements[0].activation, kAgreement * (o.rtol + o.atol));
  }
}

void ExpectSteppingReproducesRun(const NetworkSystem& system) {
  constexpr double kEnd = 1.0;
  const NetworkRunResult reference = OneShot(system, kEnd);
  ASSERT_EQ(reference.stats.status, RunStatus::kCompleted);
  Stepper stepper(system, Tight());
  ExpectSameRun(reference, stepper, kEnd);
  // (e) resuming keeps CVODE's step size across the calls: each millisecond's boundary cuts
  // at most one step short, and what follows grows back within a step or two, so the pieces
  // cost at most twice the run's steps plus one per call. Restarting on every call (order 1,
  // a first step a fraction of the piece) takes several steps per call and fails this (the
  // restarting stepper below shows it).
  const long calls = 1000;
  std::printf("one-shot steps %ld, stepped %ld over %ld calls\n", reference.stats.steps,
              stepper.stats().steps, calls);
  EXPECT_LT(stepper.stats().steps, 2 * reference.stats.steps + calls);
  EXPECT_GE(stepper.stats().steps, calls);  // every call steps at least once
  EXPECT_DOUBLE_EQ(stepper.stats().final_time, kEnd);
}

TEST(Stepper, MillisecondPiecesReproduceOneRunWithActuatorSpringAndDamper) {
  ExpectSteppingReproducesRun(WithActivation(Waveform::Constant(0.3)));
}

TEST(Stepper, MillisecondPiecesReproduceOneRunWithActivationDynamics) {
  ExpectSteppingReproducesRun(WithExcitation(Waveform::Constant(0.3)));
}

TEST(Stepper, MillisecondPiecesReproduceOneRunWithAController) {
  ExpectSteppingReproducesRun(WithController());
}

TEST(Stepper, RestartingOnEveryCallCostsMoreThanTheResumeBound) {
  // the same input set again before every call restarts the integrator each time: the
  // bound the resuming stepper meets above must not hold here, or it proves nothing
  const NetworkSystem system = WithActivation(Waveform::Constant(0.3));
  const NetworkRunResult reference = OneShot(system, 1.0);
  Stepper stepper(system, Tight());
  const long calls = 1000;
  for (int k = 1; k <= calls; ++k) {
    stepper.SetActivation("muscle", 0.3);
    ASSERT_EQ(stepper.Advance(k * 1e-3), RunStatus::kCompleted);
  }
  std::printf("one-shot steps %ld, restarting every call %ld\n", reference.stats.steps,
              stepper.stats().steps);
  EXPECT_GT(stepper.stats().steps, 2 * reference.stats.steps + calls);
}

// (b) an input set between pieces is the run's step waveform at that time.
void ExpectSetActivationIsAStep(NetworkSystem (*rig)(Waveform)) {
  constexpr double kEnd = 0.5;
  const NetworkRunResult reference = OneShot(rig(Waveform::Step(0.2, 0.3, 0.8)), kEnd);
  Stepper stepper(rig(Waveform::Constant(0.3)), Tight());
  const Scales scale = ScalesOf(reference);
  const SolverOptions o = Tight();
  for (int k = 1; k <= 500; ++k) {
    ASSERT_EQ(stepper.Advance(k * 1e-3), RunStatus::kCompleted);
    // set at 0.2 s, after that row's state: the sample there then shows the new input, as
    // the waveform's row at its edge does
    if (k == 200) stepper.SetActivation("muscle", 0.8);
    const NetworkSample& a = stepper.sample();
    const NetworkSample& b = reference.samples[static_cast<std::size_t>(k)];
    // as in ExpectSameRun
    ASSERT_NEAR(a.position[1], b.position[1], kAgreement * (o.rtol * scale.position + o.atol))
        << "t = " << stepper.time();
    ASSERT_NEAR(a.velocity[1], b.velocity[1], kAgreement * (o.rtol * scale.velocity + o.atol))
        << "t = " << stepper.time();
    ASSERT_NEAR(a.elements[0].activation, b.elements[0].activation, kAgreement * (o.rtol + o.atol));
  }
  EXPECT_EQ(stepper.system().elements()[0].kind, ElementKind::kActuator);
}

TEST(Stepper, SetActivationIsAStepOfTheActivation) { ExpectSetActivationIsAStep(WithActivation); }

TEST(Stepper, SetActivationIsAStepOfTheExcitation) { ExpectSetActivationIsAStep(WithExcitation); }

// (c) An external PI sampled every `period` with a zero-order hold: e_k = kp err_k + ki z_k,
// z_{k+1} = z_k + period err_k. Returns the largest difference of the spring's tension from
// the network's continuous loop at the common millisecond times over 0.3 s.
double SampledLoopDeviation(const NetworkRunResult& continuous, int per_millisecond) {
  const double period = 1e-3 / per_millisecond;
  Stepper stepper(WithExcitation(Waveform::Constant(0.0)), Tight());
  double integral = 0.0, deviation = 0.0;
  for (int k = 0; k < 300 * per_millisecond; ++k) {
    const double error = kReference - stepper.sample().elements[1].tension;
    const double command = kGains.kp * error + kGains.ki * integral;
    EXPECT_GT(command, 0.0);  // clear of the clamps, where both loops are linear in c
    EXPECT_LT(command, 1.0);
    stepper.SetActivation("muscle", std::clamp(command, 0.0, 1.0));
    integral += period * error;
    EXPECT_EQ(stepper.Advance((k + 1) * period), RunStatus::kCompleted);
    if ((k + 1) % per_millisecond == 0) {
      const auto row = static_cast<std::size_t>((k + 1) / per_millisecond);
      deviation = std::max(deviation, std::abs(stepper.sample().elements[1].tension -
                                               continuous.samples[row].elements[1].tension));
    }
  }
  return deviation;
}

TEST(Stepper, SampledPidConvergesToTheContinuousOneAtFirstOrder) {
  const NetworkRunResult continuous = OneShot(WithController(), 0.3);
  // the continuous loop settles on its reference, so the comparison is of a working loop
  EXPECT_NEAR(continuous.samples.back().elements[1].tension, kReference, 0.05 * kReference);
  const double at_1khz = SampledLoopDeviation(continuous, 1);
  const double at_4khz = SampledLoopDeviation(continuous, 4);
  std::printf("largest tension deviation: 1 kHz %.6g N, 4 kHz %.6g N, ratio %.4g\n", at_1khz,
              at_4khz, at_1khz / at_4khz);
  // a zero-order hold delays the command by half a period and the rectangle rule's integral
  // errs by O(period): the deviation is first order in the period, a quarter at 4 kHz. The
  // band allows the O(period^2) remainder (at 1 kHz against a 50 ms loop, a few per cent of
  // the leading term) and the solver's error (1e-8 N), far below either deviation
  EXPECT_GT(at_1khz / at_4khz, 3.5);
  EXPECT_LT(at_1khz / at_4khz, 4.5);
  // and at 1 kHz the sampled loop tracks the continuous one to a per cent of its reference
  EXPECT_LT(at_1khz, 0.01 * kReference);
}

// (d) refusals.
TEST(Stepper, RefusesATimeNotAfterItsOwn) {
  Stepper stepper(WithActivation(Waveform::Constant(0.3)), Tight());
  EXPECT_THROW(stepper.Advance(0.0), ParameterError);
  EXPECT_THROW(stepper.Advance(-1e-3), ParameterError);
  EXPECT_THROW(stepper.Advance(std::nan("")), ParameterError);
  EXPECT_THROW(stepper.Advance(HUGE_VAL), ParameterError);
  // finite but beyond what a step of CVODE resolves: past the time range, or a step of a
  // few roundoffs (which CVODE refuses as a tstop behind t)
  EXPECT_THROW(stepper.Advance(1e300), ParameterError);
  EXPECT_THROW(stepper.Advance(5e-324), ParameterError);
  EXPECT_THROW(stepper.Advance(1e-13), ParameterError);
  ASSERT_EQ(stepper.Advance(1e-3), RunStatus::kCompleted);
  EXPECT_THROW(stepper.Advance(1e-3 + 1e-16), ParameterError);
  EXPECT_THROW(stepper.Advance(1e-3), ParameterError);
  EXPECT_EQ(stepper.time(), 1e-3);  // a refusal changes nothing
  EXPECT_EQ(stepper.Advance(2e-3), RunStatus::kCompleted);
}

TEST(Stepper, RefusesAnInputItCannotSet) {
  Stepper open_loop(WithActivation(Waveform::Constant(0.3)), Tight());
  EXPECT_THROW(open_loop.SetActivation("biceps", 0.5), ParameterError);  // no such element
  EXPECT_THROW(open_loop.SetActivation("spring", 0.5), ParameterError);  // no actuator
  EXPECT_THROW(open_loop.SetActivation("muscle", 1.5), ParameterError);
  EXPECT_THROW(open_loop.SetActivation("muscle", -0.1), ParameterError);
  EXPECT_THROW(open_loop.SetActivation("muscle", std::nan("")), ParameterError);
  Stepper closed_loop(WithController(), Tight());
  EXPECT_THROW(closed_loop.SetActivation("muscle", 0.5), ParameterError);  // controlled
}

TEST(Stepper, EndsAtALimitAndRefusesToGoOn) {
  // at u = 0.8 the muscle pulls the load below 0.09 m within a few tens of milliseconds
  StepperStart start;
  start.limits = {{"muscle", 0.09, std::nullopt}};
  Stepper stepper(WithActivation(Waveform::Constant(0.8)), Tight(), start);
  RunStatus status = RunStatus::kCompleted;
  int k = 0;
  while (status == RunStatus::kCompleted && k < 1000) status = stepper.Advance(++k * 1e-3);
  ASSERT_EQ(status, RunStatus::kLimit) << stepper.message();
  // the state is where the limit was reached, inside the last piece
  EXPECT_NEAR(stepper.sample().elements[0].length, 0.09, 1e-9);  // the crossing's tolerance
  EXPECT_GT(stepper.time(), (k - 1) * 1e-3);
  EXPECT_LE(stepper.time(), k * 1e-3);
  EXPECT_NE(stepper.message().find("min_length"), std::string::npos);
  EXPECT_THROW(stepper.Advance(2.0), std::logic_error);
}

TEST(Stepper, RefusesABadStart) {
  StepperStart start;
  start.initial_state = {0.1};  // the rig has two states
  EXPECT_THROW(Stepper(WithActivation(Waveform::Constant(0.3)), Tight(), start), ParameterError);
  start.initial_state.clear();
  start.limits = {{"muscle", 0.2, std::nullopt}};  // above its initial length 0.1 m
  EXPECT_THROW(Stepper(WithActivation(Waveform::Constant(0.3)), Tight(), start), ParameterError);
}

}  // namespace
}  // namespace musclesim
