#include "musclesim/io/writers/scenario_rewrite.h"

#include <yaml-cpp/yaml.h>

#include "io/readers/document_yaml.h"
#include "io/readers/yaml_fields.h"
#include "io/readers/yaml_override.h"

namespace musclesim {

namespace {

std::string Emit(const YAML::Node& root, const std::vector<std::string>& header) {
  YAML::Emitter out;
  out << root;
  std::string text;
  for (const std::string& line : header) text += line.empty() ? "#\n" : "# " + line + "\n";
  return text + out.c_str() + "\n";
}

}  // namespace

std::string RewriteScenario(const std::string& path, const Overrides& overrides,
                            const std::vector<std::string>& header) {
  YAML::Node root = yaml::Parse(path, yaml::ReadText(path));
  yaml::ApplyOverrides(root, overrides, path);
  return Emit(root, header);
}

std::string RewriteScenario(const Document& document, const std::string& name,
                            const Overrides& overrides, const std::vector<std::string>& header) {
  YAML::Node root = ToYaml(document);
  yaml::ApplyOverrides(root, overrides, name);
  return Emit(root, header);
}

}  // namespace musclesim
