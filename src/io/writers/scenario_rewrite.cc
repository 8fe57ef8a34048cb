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

Document RewrittenDocument(const std::string& path, const Overrides& overrides) {
  Document root = yaml::Parse(path, yaml::ReadText(path));
  yaml::ApplyOverrides(root, overrides, path);
  return root;
}

Document RewrittenDocument(const Document& document, const std::string& name,
                           const Overrides& overrides) {
  Document root = document;
  yaml::ApplyOverrides(root, overrides, name);
  return root;
}

std::string RewriteScenario(const std::string& path, const Overrides& overrides,
                            const std::vector<std::string>& header) {
  return Emit(ToYaml(RewrittenDocument(path, overrides)), header);
}

std::string RewriteScenario(const Document& document, const std::string& name,
                            const Overrides& overrides, const std::vector<std::string>& header) {
  return Emit(ToYaml(RewrittenDocument(document, name, overrides)), header);
}

}  // namespace musclesim
