// Test helper: the closed-loop networks of scenarios/{force_regulation, position_tracking,
// stiffness_modulation}.yaml built in code, each with the file's parameters, so that a test
// can compare the file with its function here and vary a setting the file fixes.
#pragma once

#include <memory>
#include <vector>

#include "support/canonical_actuator.h"
#include "support/canonical_networks.h"

namespace musclesim::testing {

// scenarios/force_regulation.yaml: the canonical actuator (wall at 0 to a 0.05 kg tip at
// 0.1 m) pulls on a transducer spring (1e5 N/m, slack at the start) anchored at 0.2 m. A PI
// controller measures the actuator's tension and drives its excitation through activation
// dynamics (both time constants 30 ms). `reference`: in the file, a step from 0 to 33 N at
// 0.05 s, where the activation settles near 1/3.
inline constexpr double kForceKp = 0.005, kForceKi = 0.15;  // 1/N, 1/(N s)

inline NetworkExperiment ForceRegulation(Waveform reference = Waveform::Step(0.05, 0.0, 33.0)) {
  const ActivationDynamics dynamics{0.03, 0.03};
  std::vector<Controller> controllers = {
      Controller::Pid("force", {"muscle", "", MeasuredQuantity::kTension}, std::move(reference),
                      {kForceKp, kForceKi, 0.0}, "muscle")};
  return {
      NetworkSystem(
          {Node::Fixed("wall", 0.0), Node::Free("tip", 0.05, 0.1), Node::Fixed("anchor", 0.2)},
          {Element::ControlledActuator("muscle", "wall", "tip", SharedCanonicalModel(), dynamics),
           Element::Spring("transducer", "tip", "anchor", 1e5, 0.1)},
          {}, std::move(controllers)),
      Span(1.0, 1e-3), Tolerances(1e-10, 1e-12)};
}

// The antagonist pair of scenarios/{position_tracking, stiffness_modulation}.yaml: the
// canonical actuator's curves with a linear tension-velocity curve (n = 1, v_max = 1 m/s) for
// some damping of its own; `flexor` from a wall at 0 to a 1 kg load at 0.07 m, `extensor` from
// the load to a wall at 0.14 m, both driven by one controller measuring the load's position:
// the extensor takes level + c, the flexor level - c, so positive gains move the load toward
// a reference above it.
inline std::shared_ptr<const TensionModel> PairModel() {
  ModelParams p = CanonicalModel();
  p.velocity = {1.0, 1, 1e-3};
  return std::make_shared<const TensionModel>(p);
}

inline NetworkSystem ControlledPair(Waveform reference, PidGains gains, Waveform level,
                                    std::vector<NodeLoad> loads = {}) {
  return NetworkSystem(
      {Node::Fixed("wall_a", 0.0), Node::Free("load", 1.0, 0.07), Node::Fixed("wall_b", 0.14)},
      {Element::ControlledActuator("flexor", "wall_a", "load", PairModel()),
       Element::ControlledActuator("extensor", "load", "wall_b", PairModel())},
      std::move(loads),
      {Controller::CoContracting("position", {"", "load", MeasuredQuantity::kPosition},
                                 std::move(reference), gains,
                                 {"extensor", "flexor", std::move(level)})});
}

// scenarios/position_tracking.yaml: the load follows 0.07 + 0.005 sin(2 pi t) m under PID
// control at co-contraction 0.3, for 3 s.
inline constexpr double kTrackKp = 250.0, kTrackKi = 10000.0, kTrackKd = 4.0;

inline NetworkExperiment PositionTracking() {
  return {ControlledPair(Waveform::Sine(0.07, 0.005, 1.0), {kTrackKp, kTrackKi, kTrackKd},
                         Waveform::Constant(0.3)),
          Span(3.0, 1e-3), Tolerances(1e-8, 1e-12)};
}

// scenarios/stiffness_modulation.yaml: the load held at 0.07 m by proportional-derivative
// control (no integral, so the pair's stiffness shows) while the co-contraction level steps
// 0.1, 0.4, 0.7 at 0, 1, 2 s, and a 2 N force pulls the load for 0.4 s from 0.5 s into each
// level.
inline constexpr double kStiffKp = 20.0, kStiffKd = 1.0, kStiffPulse = 2.0;

inline NetworkExperiment StiffnessModulation() {
  return {ControlledPair(
              Waveform::Constant(0.07), {kStiffKp, 0.0, kStiffKd},
              Waveform::Table({{0.0, 0.1}, {0.999, 0.1}, {1.0, 0.4}, {1.999, 0.4}, {2.0, 0.7}}),
              {{"load", Load::Force(Waveform::Pulses(0.5, 1.0, 0.4, 0.0, kStiffPulse))}}),
          Span(3.0, 1e-3), Tolerances(1e-8, 1e-12)};
}

}  // namespace musclesim::testing
