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
  std::string file;             // CSV path, relative to the working directory; "-": stdout
  double interval = 0.0;        // [s] between rows; 0 with every_step
  bool every_step = false;      // `interval: steps`: a row per internal step
  std::optional<double> phase_tolerance;  // v_tol [m/s]; default: model.velocity.epsilon
};

struct ScenarioSpec {
  std::string name;
  std::string source;           // the file it came from
  ModelSpec model;
  ActuatorParams actuator;
  double initial_length = 0.0;            // [m]
  double initial_lengthening_rate = 0.0;  // [m/s]
  Waveform activation;
  std::vector<Load> loads;
  double t_start = 0.0, t_end = 1.0;      // [s]
  SolverOptions solver;
  OutputSpec output;
  std::optional<double> min_length, max_length;  // [m]

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
