// LoadScenario and ScenarioTemplate: the file parsed once, its form told by its top-level
// keys, the overrides (`--set`) applied to the document before it is read, so that an override
// is validated exactly as the file's own value would be.
#include "musclesim/io/readers/scenario_yaml.h"

#include "io/readers/scenario_readers.h"
#include "io/readers/yaml_override.h"

namespace musclesim {

namespace {

ScenarioForm FormOf(const Document& root) {
  return root.IsMap() && (root["nodes"] || root["bodies"] || root["joints"] || root["wraps"])
             ? ScenarioForm::kNetwork
             : ScenarioForm::kActuator;
}

// The scenario, and its system when reading built one (a network's reader does).
LoadedScenario Read(const yaml::Source& src, const Document& root) {
  if (FormOf(root) == ScenarioForm::kNetwork) return ReadNetworkScenario(src, root);
  return {ReadActuatorScenario(src, root), nullptr};
}

// `loaded` with its system, built now if reading built none.
LoadedScenario WithSystem(LoadedScenario loaded) {
  if (!loaded.system)
    loaded.system = std::make_shared<const NetworkSystem>(loaded.scenario.Build());
  return loaded;
}

// The document `root`, overridden in a copy when there are overrides, read.
LoadedScenario ReadOverridden(const yaml::Source& src, const Document& root,
                              const Overrides& overrides, const std::string& name) {
  if (overrides.texts.empty()) return Read(src, root);
  // overrides must not touch the caller's document, so they go into a copy, whose values keep
  // their positions (the overridden ones, which have none, say the overrides' label)
  Document copy = root;
  yaml::ApplyOverrides(copy, overrides, name);
  return Read(src, copy);
}

// The file `path` parsed, overridden and read; `name` names it in messages.
LoadedScenario LoadReadScenario(const std::string& path, const Overrides& overrides,
                                const std::string& name) {
  Document root = yaml::Parse(name, yaml::ReadText(path));
  yaml::ApplyOverrides(root, overrides, name);
  return Read(yaml::Source{name, overrides.label}, root);
}

}  // namespace

ScenarioTemplate::ScenarioTemplate(const std::string& path)
    : ScenarioTemplate(path, std::make_shared<const Document>(yaml::LoadFile(path))) {}

ScenarioTemplate::ScenarioTemplate(std::string path, std::shared_ptr<const Document> document)
    : path_(std::move(path)), document_(std::move(document)), form_(FormOf(*document_)) {}

std::unique_ptr<ScenarioTemplate> ScenarioTemplate::Copy() const {
  return std::unique_ptr<ScenarioTemplate>(new ScenarioTemplate(path_, document_));
}

bool ScenarioTemplate::has_sensitivities() const {
  return document_->IsMap() && (*document_)["sensitivities"].IsDefined();
}

Scenario ScenarioTemplate::Instantiate(const Overrides& overrides) const {
  return InstantiateLoaded(overrides).scenario;
}

LoadedScenario ScenarioTemplate::InstantiateLoaded(const Overrides& overrides) const {
  return ReadOverridden({path_, overrides.label}, *document_, overrides, path_);
}

LoadedScenario ReadBuiltScenario(const Document& document, const std::string& name,
                                 const Overrides& overrides) {
  if (document.IsNull() || (document.IsMap() && document.size() == 0)) {
    throw InputError(name + ": the document is empty");
  }
  return WithSystem(ReadOverridden({name, name}, document, overrides, name));
}

Scenario ReadScenario(const Document& document, const std::string& name,
                      const Overrides& overrides) {
  if (document.IsNull() || (document.IsMap() && document.size() == 0)) {
    throw InputError(name + ": the document is empty");
  }
  return ReadOverridden({name, name}, document, overrides, name).scenario;
}

ActuatorScenarioSpec LoadActuatorScenarioSpec(const std::string& path, const Overrides& overrides) {
  Document root = yaml::LoadFile(path);
  yaml::ApplyOverrides(root, overrides, path);
  if (FormOf(root) == ScenarioForm::kNetwork) {
    throw InputError(path + ": a network (it has nodes:), not the single-actuator form");
  }
  const yaml::Source src{path, overrides.label};
  ActuatorScenarioSpec spec = ReadActuatorScenarioSpec(src, root);
  yaml::ValidateAt(src, root, "", [&] { MakeActuatorScenario(spec); });
  return spec;
}

Scenario LoadScenario(const std::string& path, const Overrides& overrides) {
  return LoadScenario(path, overrides, path);
}

Scenario LoadScenario(const std::string& path, const Overrides& overrides,
                      const std::string& name) {
  return LoadReadScenario(path, overrides, name).scenario;
}

LoadedScenario LoadBuiltScenario(const std::string& path, const Overrides& overrides,
                                 const std::string& name) {
  return WithSystem(LoadReadScenario(path, overrides, name));
}

}  // namespace musclesim
