// From a scenario to a trajectory in one call, for code that has a scenario file (or a
// ScenarioSpec read from one and changed in code) and wants the result as data.
#pragma once

#include <string>
#include <vector>

#include "musclesim/dynamics/actuator.h"
#include "musclesim/io/scenario.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// The actuator system a scenario describes. Throws ParameterError if fields changed in code
// break a rule (the reader has validated everything it read).
ActuatorSystem BuildSystem(const ScenarioSpec& spec);

// Integrates `spec` on a new Simulation: BuildSystem, then Simulation::Run with the
// scenario's solver options and request. A solver failure is a result (stats.status
// kFailed), not an exception.
RunResult RunScenario(const ScenarioSpec& spec);

// LoadScenario(path, overrides) then RunScenario. Throws InputError for a bad file or
// override (file:line:column, key, value, rule).
RunResult RunScenarioFile(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace musclesim
