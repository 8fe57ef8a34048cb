// Reading scenario files (docs/guide/scenarios.md) into a Scenario (scenario/scenario.h),
// validated before anything runs. A file with a top-level `nodes:` key is a network
// (docs/model.md 7); any other is the single actuator, read as the network of section 7.4.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "musclesim/io/readers/document.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

// Reads and validates `path`, applying `overrides` first (io/readers/document.h). Checks
// everything a run would: for a network, names unique, references resolved, every free node
// joined to a fixed or prescribed node, every controller fitting the network, every element
// longer than zero at the start, the limits against the elements' initial lengths. Throws
// InputError naming file:line:column (or the overrides' label), key path, value and rule.
Scenario LoadScenario(const std::string& path, const Overrides& overrides = {});
// The same, the file named `name` in messages (the path as a user gave it, when `path` is
// that path made absolute).
Scenario LoadScenario(const std::string& path, const Overrides& overrides, const std::string& name);

// LoadScenario's scenario and its system, built once: what a run reads. A network's reader
// builds the system to check how the parts fit; this hands it on rather than dropping it.
LoadedScenario LoadBuiltScenario(const std::string& path, const Overrides& overrides,
                                 const std::string& name);

// The single-actuator file `path` as written (MakeActuatorScenario's input: the old form's
// own fields), read and validated as LoadScenario does; InputError for a network file.
ActuatorScenarioSpec LoadActuatorScenarioSpec(const std::string& path,
                                              const Overrides& overrides = {});

// Reads the scenario `document` (io/readers/document.h), built in code, with `overrides` applied,
// as LoadScenario reads a file; `name` names it in messages ("<dict>"), which cannot give lines.
Scenario ReadScenario(const Document& document, const std::string& name,
                      const Overrides& overrides = {});
// The same with its system, built once (LoadBuiltScenario).
LoadedScenario ReadBuiltScenario(const Document& document, const std::string& name,
                                 const Overrides& overrides = {});

// A scenario file read and parsed once, from which many scenarios are made by overrides (a
// sweep's points whose axes are not numbers). Its document is never changed once parsed, so
// threads may instantiate from one template, and a Copy() shares it.
class ScenarioTemplate {
 public:
  // Throws InputError if the file cannot be read or is not YAML.
  explicit ScenarioTemplate(const std::string& path);
  ScenarioTemplate(const ScenarioTemplate&) = delete;
  ScenarioTemplate& operator=(const ScenarioTemplate&) = delete;

  // A template of the same document, shared rather than parsed again.
  std::unique_ptr<ScenarioTemplate> Copy() const;

  // The scenario with `overrides` applied, validated as LoadScenario does.
  Scenario Instantiate(const Overrides& overrides) const;
  // The same, with the system reading built (a network's; null for the single actuator,
  // whose reader builds none).
  LoadedScenario InstantiateLoaded(const Overrides& overrides) const;
  const std::string& path() const { return path_; }
  // How the file is written (a network: a top-level `nodes:` key).
  ScenarioForm form() const { return form_; }
  // Whether the file lists `sensitivities:`.
  bool has_sensitivities() const;

 private:
  ScenarioTemplate(std::string path, std::shared_ptr<const Document> document);
  std::string path_;
  std::shared_ptr<const Document> document_;
  ScenarioForm form_ = ScenarioForm::kActuator;
};

}  // namespace musclesim
