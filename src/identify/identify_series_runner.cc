// The runner identification uses on a scenario: RunWithSensitivities on copies of it. On its
// own so that code handing identification another model (tests' closed forms) does not link
// the solver's sensitivities.
#include "musclesim/identify/identify_series.h"

#include "musclesim/scenario/parameter.h"

namespace musclesim {

namespace {

// `scenario` with values[i] set at parameters[i].
Scenario With(const Scenario& scenario, const std::vector<std::string>& parameters,
              const std::vector<double>& values) {
  Scenario moved = scenario;
  std::vector<Parameter> handles;
  for (const std::string& path : parameters) handles.push_back(moved.parameter(path));
  SetParameters(moved, handles, values);
  return moved;
}

}  // namespace

SensitivityRunner ScenarioSensitivityRunner(Scenario scenario) {
  return [base = std::move(scenario)](
             const std::vector<std::string>& parameters, const std::vector<double>& values,
             const std::vector<double>& times, const std::vector<double>& sizes) {
    if (values.empty()) return RunWithSensitivities(base, parameters, times, sizes);
    return RunWithSensitivities(With(base, parameters, values), parameters, times, sizes);
  };
}

Scenario EstimatedScenario(const Scenario& scenario, const SeriesIdentification& fit) {
  std::vector<std::string> paths;
  std::vector<double> estimates;
  for (const SeriesParameterResult& p : fit.parameters) {
    paths.push_back(p.path);
    estimates.push_back(p.estimate);
  }
  return With(scenario, paths, estimates);
}

}  // namespace musclesim
