// A scenario: the model, the actuator, the inputs, the solver and the output of one run,
// read from YAML (README "Scenario files") and validated before anything runs.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/actuator.h"
#include "musclesim/io/model_yaml.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

struct OutputSpec {
  std::string file;             // CSV path [-], relative to the working directory; "-": stdout
  double interval = 0.0;        // time between rows [s]; 0 with every_step
  bool every_step = false;      // `interval: steps`: a row per internal step [-]
  std::optional<double> phase_tolerance;  // v_tol [m/s]; default: model.velocity.epsilon
};

struct ScenarioSpec {
  std::string name;                       // the scenario's name, for messages [-]
  std::string source;                     // the file it came from [-]
  ModelSpec model;                        // units as in ModelParams
  ActuatorParams actuator;                // units as in ActuatorParams
  double initial_length = 0.0;            // x(t_start) [m], > 0
  double initial_lengthening_rate = 0.0;  // dx/dt at t_start [m/s]
  Waveform activation;                    // u(t) [-], within [0, 1]; unused with excitation
  // activation dynamics (docs/model.md section 8): the activation is a state driven by this
  // excitation, the top-level keys `excitation` and `activation_dynamics` and
  // `initial.activation`; nullopt when the file gives `activation`
  std::optional<ExcitationInput> excitation;
  std::vector<Load> loads;                // units as in Load
  double t_start = 0.0, t_end = 1.0;      // the simulated interval [s], t_end > t_start
  SolverOptions solver;                   // units as in SolverOptions
  OutputSpec output;                      // units as in OutputSpec
  std::optional<double> min_length, max_length;  // stop when x leaves them [m]
  // `sensitivities:` the dotted paths of the parameters whose forward sensitivities a run
  // adds to its CSV (docs/model.md 10), and where each was given (file:line:column)
  std::vector<std::string> sensitivities, sensitivities_at;

  RunRequest Request() const;
  double PhaseTolerance() const;
};

// Reads and validates `path`, applying each "dotted.path=value" override first (as
// `--set` gives them: a scalar at an existing path, or a new key in an existing map).
// Throws InputError naming file:line:column (or --set), key, value and rule.
ScenarioSpec LoadScenario(const std::string& path, const std::vector<std::string>& overrides = {});

// A scenario file read and parsed once, from which many scenarios are made by overrides
// (a sweep's points). Not shared between threads: each thread makes its own Copy().
class ScenarioTemplate {
 public:
  // Throws InputError if the file cannot be read or is not YAML.
  explicit ScenarioTemplate(const std::string& path);
  ~ScenarioTemplate();
  ScenarioTemplate(const ScenarioTemplate&) = delete;
  ScenarioTemplate& operator=(const ScenarioTemplate&) = delete;

  // An independent template parsed from the same text.
  std::unique_ptr<ScenarioTemplate> Copy() const;

  // The scenario with `overrides` applied, validated as LoadScenario does.
  ScenarioSpec Instantiate(const std::vector<std::string>& overrides) const;
  const std::string& path() const { return path_; }

 private:
  ScenarioTemplate(std::string path, std::string text);
  struct Parsed;
  std::string path_;
  std::string text_;
  std::unique_ptr<Parsed> parsed_;
};

}  // namespace musclesim
