// Test helper: the canonical experiments of scenarios/{isometric,concentric,eccentric}.yaml
// built in code (the same actuator, inputs, loads, time span and solver settings), so that
// tests of the solver reach it without reading a scenario file.
#pragma once

#include <memory>
#include <optional>

#include "musclesim/solver/simulation.h"

namespace musclesim::testing {

// The 10 cm muscle-like actuator the scenarios share: f_iso = 100 N, a passive element
// slack up to 0.105 m, three non-negative Gaussians fitted to the sarcomere trapezoid,
// v_max = 1 m/s, n = 3, eps = 1e-3 m/s.
inline ModelParams CanonicalModel() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {1.0, 100.0, 0.105};
  p.active_length = {0.095,
                     0.105,
                     1.0,
                     {{0.35188944617853268, 20635.199147929347, 0.073556703926583866},
                      {2.2575025981825489, 4125.1402656159307, 0.097194271247335401},
                      {1.3136662819543681, 3009.3607405177986, 0.1301541244400391}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

// A model whose f_L is almost flat over any motion of a few centimetres (one Gaussian 1 m
// wide) and with no passive tension (k_p = 0): with u = 0 it pulls nothing (docs/model.md
// section 5), and an isotonic run under it reaches a true steady velocity.
inline ModelParams FlatModel() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {0.0, 100.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{1.0, 1.0, 0.1}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

// One experiment: the system, its run and its solver settings.
struct Experiment {
  ActuatorSystem system;
  RunRequest request;
  SolverOptions options;

  RunResult Run() const {
    Simulation simulation;
    return simulation.Run(system, options, request);
  }
};

inline std::shared_ptr<const TensionModel> SharedCanonicalModel() {
  return std::make_shared<const TensionModel>(CanonicalModel());
}

// Fully activated at 0.05 s, when a step `load` [N] (a force pulling it longer) comes on;
// mass 0.1 kg, from rest at 0.1 m, 0.5 s recorded every 1 ms.
inline Experiment Isotonic(double load, std::optional<double> min_length,
                           std::optional<double> max_length) {
  ActuatorParams actuator;
  actuator.mass = 0.1;
  actuator.rest_length = 0.1;
  RunRequest request;
  request.t_end = 0.5;
  request.length = 0.1;
  request.output_interval = 1e-3;
  request.min_length = min_length;
  request.max_length = max_length;
  SolverOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-9;
  return {ActuatorSystem(SharedCanonicalModel(), actuator, Waveform::Step(0.05, 0.0, 1.0),
                         {Load::Force(Waveform::Step(0.05, 0.0, load))}),
          request, options};
}

// scenarios/concentric.yaml: a 40 N load, limits at 0.06 and 0.2 m.
inline Experiment Concentric() { return Isotonic(40.0, 0.06, 0.2); }

// scenarios/eccentric.yaml: a 150 N load, a limit at 0.2 m.
inline Experiment Eccentric() { return Isotonic(150.0, std::nullopt, 0.2); }

// scenarios/isometric.yaml: pulling on a 1e5 N/m transducer anchored at 0.1 m, activated at
// 0.05 s; rtol 1e-6, atol 1e-10.
inline Experiment Isometric() {
  ActuatorParams actuator;
  actuator.mass = 0.1;
  RunRequest request;
  request.t_end = 0.5;
  request.length = 0.1;
  request.output_interval = 1e-3;
  SolverOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-10;
  return {ActuatorSystem(SharedCanonicalModel(), actuator, Waveform::Step(0.05, 0.0, 1.0),
                         {Load::Spring(1e5, 0.1)}),
          request, options};
}

}  // namespace musclesim::testing
