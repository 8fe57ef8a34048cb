#include "musclesim/io/run_scenario.h"

namespace musclesim {

ActuatorSystem BuildSystem(const ScenarioSpec& spec) {
  if (spec.excitation) {
    return ActuatorSystem(spec.model.params, spec.actuator, *spec.excitation, spec.loads);
  }
  return ActuatorSystem(spec.model.params, spec.actuator, spec.activation, spec.loads);
}

RunResult RunScenario(const ScenarioSpec& spec) {
  Simulation simulation;
  return simulation.Run(BuildSystem(spec), spec.solver, spec.Request());
}

RunResult RunScenarioFile(const std::string& path, const std::vector<std::string>& overrides) {
  return RunScenario(LoadScenario(path, overrides));
}

}  // namespace musclesim
