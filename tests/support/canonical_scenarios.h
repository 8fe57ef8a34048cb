// Test helper: scenarios/concentric.yaml as a Scenario built in code (the same model, actuator,
// inputs, load, time span, solver, output and limits, every number as the file writes it), so
// that tests of the scenario layer, sweeps and identification reach a scenario without reading
// a file, and can compare it with the file read.
#pragma once

#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/scenario.h"
#include "support/canonical_actuator.h"

namespace musclesim::testing {

// scenarios/concentric.yaml's keys, as the single-actuator form holds them.
inline ActuatorScenarioSpec ConcentricSpec() {
  ActuatorScenarioSpec spec;
  spec.name = "concentric_isotonic";
  spec.source = "<concentric in code>";
  spec.model.params = CanonicalModel();
  spec.actuator.mass = 0.1;
  spec.actuator.rest_length = 0.1;
  spec.initial_length = 0.1;
  spec.activation = Waveform::Step(0.05, 0.0, 1.0);
  spec.loads = {Load::Force(Waveform::Step(0.05, 0.0, 40.0))};
  spec.t_end = 0.5;
  spec.solver.rtol = 1e-6;
  spec.solver.atol = 1e-9;
  spec.output.file = "concentric.csv";
  spec.output.interval = 1e-3;
  spec.min_length = 0.06;
  spec.max_length = 0.2;
  return spec;
}

// The same as the network of docs/model.md 7.4.
inline Scenario ConcentricScenario() { return MakeActuatorScenario(ConcentricSpec()); }

}  // namespace musclesim::testing
