// LoadScenario and ScenarioTemplate: the file parsed once, its form told by its top-level
// keys, the overrides (`--set`) applied to the document before it is read, so that an override
// is validated exactly as the file's own value would be.
#include "musclesim/io/readers/scenario_yaml.h"

#include "io/readers/scenario_readers.h"
#include "io/readers/yaml_override.h"

namespace musclesim {

namespace {

ScenarioForm FormOf(const Document& root) {
  return root.IsMap() && root["nodes"] ? ScenarioForm::kNetwork : ScenarioForm::kActuator;
}

Scenario Read(const yaml::Source& src, const Document& root) {
  return FormOf(root) == ScenarioForm::kNetwork ? ReadNetworkScenario(src, root)
                                                : ReadActuatorScenario(src, root);
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
  const yaml::Source src{path_, overrides.label};
  if (overrides.texts.empty()) return Read(src, *document_);
  // overrides must not touch the template, so they go into a copy, whose values keep their
  // file positions (the overridden ones, which have none, say the overrides' label)
  Document root = *document_;
  yaml::ApplyOverrides(root, overrides, path_);
  return Read(src, root);
}

Scenario ReadScenario(const Document& document, const std::string& name,
                      const Overrides& overrides) {
  if (document.IsNull() || (document.IsMap() && document.size() == 0)) {
    throw InputError(name + ": the document is empty");
  }
  const yaml::Source src{name, name};
  if (overrides.texts.empty()) return Read(src, document);
  Document root = document;
  yaml::ApplyOverrides(root, overrides, name);
  return Read(src, root);
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
  Document root = yaml::Parse(name, yaml::ReadText(path));
  yaml::ApplyOverrides(root, overrides, name);
  return Read(yaml::Source{name, overrides.label}, root);
}

}  // namespace musclesim
