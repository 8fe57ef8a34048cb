// Private: a scenario prepared for a run with forward sensitivities (docs/model.md 10): the
// network it integrates, and each parameter path resolved into its right-hand-side
// derivative (closed form for a tension model's parameters, else a difference quotient over
// the scenario rebuilt at nearby values) and its initial sensitivity.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/actuator.h"
#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/io/sensitivity_run.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

struct SensitivitySetup {
  std::string source;                             // the scenario file
  std::string name;                               // the scenario's name
  std::shared_ptr<const ActuatorSystem> actuator;  // a single actuator's; null for a network
  std::shared_ptr<const NetworkSystem> system;     // what is integrated
  SolverOptions solver;
  NetworkRunRequest request;
  std::string output_file;                         // output.file
  std::optional<double> phase_tolerance;           // the CSV's v_tol [m/s]
  std::vector<std::string> paths;
  std::vector<double> values;                      // each parameter's value in the scenario
  std::vector<DerivativeSource> sources;
  std::vector<std::unique_ptr<ParameterDerivative>> derivatives;
  std::vector<SensitivityParameter> parameters;    // point into `derivatives`
};

// Loads `path` with `overrides` and resolves `parameters` (dotted paths; the scenario's own
// `sensitivities:` list comes after them, repeats dropped). `where` names each of
// `parameters` in messages ("--sensitivity"). Throws InputError for a bad file or override,
// and for a path that names no number of the dynamics, a value that cannot move (an integer),
// or a parameter that moves an input breakpoint.
SensitivitySetup PrepareSensitivities(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      const std::vector<std::string>& parameters);

}  // namespace musclesim
