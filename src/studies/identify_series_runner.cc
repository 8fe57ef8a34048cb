// The runner identification uses on a scenario file: RunWithSensitivities. On its own so that
// code handing identification another model (tests' closed forms) does not link the solver's
// sensitivities.
#include "musclesim/studies/identify_series.h"

namespace musclesim {

SensitivityRunner ScenarioSensitivityRunner(std::string scenario,
                                            std::vector<std::string> overrides) {
  return [scenario = std::move(scenario), base = std::move(overrides)](
             const std::vector<std::string>& more, const std::vector<std::string>& parameters,
             const std::vector<double>& times) {
    std::vector<std::string> all = base;
    all.insert(all.end(), more.begin(), more.end());
    return RunWithSensitivities(scenario, all, parameters, times);
  };
}

}  // namespace musclesim
