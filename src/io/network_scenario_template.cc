#include "musclesim/io/network_scenario_template.h"

#include "io/network_scenario_reader.h"
#include "io/yaml_override.h"

namespace musclesim {

struct NetworkScenarioTemplate::Parsed {
  YAML::Node root;
};

NetworkScenarioTemplate::NetworkScenarioTemplate(const std::string& path)
    : NetworkScenarioTemplate(path, yaml::ReadText(path)) {}

NetworkScenarioTemplate::NetworkScenarioTemplate(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)),
      parsed_(std::make_unique<Parsed>(Parsed{yaml::Parse(path_, text_)})) {}

NetworkScenarioTemplate::~NetworkScenarioTemplate() = default;

std::unique_ptr<NetworkScenarioTemplate> NetworkScenarioTemplate::Copy() const {
  return std::unique_ptr<NetworkScenarioTemplate>(new NetworkScenarioTemplate(path_, text_));
}

NetworkScenarioSpec NetworkScenarioTemplate::Instantiate(
    const std::vector<std::string>& overrides) const {
  const yaml::Source src{path_};
  if (overrides.empty()) return ReadNetworkScenario(src, parsed_->root);
  // as ScenarioTemplate::Instantiate: the overrides go into a clone, which is fast but keeps
  // no file positions, so a failing scenario is read again from its text parsed afresh for
  // a message with file:line:column (and --set for the overridden nodes)
  try {
    YAML::Node root = YAML::Clone(parsed_->root);
    for (const std::string& text : overrides) yaml::ApplyOverride(root, text, path_);
    return ReadNetworkScenario(src, root);
  } catch (const InputError&) {
    YAML::Node root = yaml::Parse(path_, text_);
    for (const std::string& text : overrides) yaml::ApplyOverride(root, text, path_);
    return ReadNetworkScenario(src, root);
  }
}

}  // namespace musclesim
