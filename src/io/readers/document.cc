#include "musclesim/io/readers/document.h"

#include <cmath>

#include "io/readers/document_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

Document Document::Bool(bool value) {
  Document d;
  d.kind_ = Kind::kBool;
  d.bool_ = value;
  return d;
}

Document Document::Number(double value) {
  Document d;
  d.kind_ = Kind::kNumber;
  d.number_ = value;
  return d;
}

Document Document::Integer(long long value) {
  Document d = Number(static_cast<double>(value));
  d.integer_ = true;
  d.text_ = std::to_string(value);  // exact, beyond 2^53 too
  return d;
}

Document Document::Text(std::string value) {
  Document d;
  d.kind_ = Kind::kText;
  d.text_ = std::move(value);
  return d;
}

Document Document::List(std::vector<Document> items) {
  Document d;
  d.kind_ = Kind::kList;
  d.items_ = std::move(items);
  return d;
}

Document Document::Map(std::vector<std::pair<std::string, Document>> entries) {
  Document d;
  d.kind_ = Kind::kMap;
  for (auto& [key, value] : entries) d.Set(key, std::move(value));
  return d;
}

const Document* Document::Find(const std::string& key) const {
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (keys_[i] == key) return &items_[i];
  }
  return nullptr;
}

void Document::Set(const std::string& key, Document value) {
  kind_ = Kind::kMap;
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (keys_[i] == key) {
      items_[i] = std::move(value);
      return;
    }
  }
  keys_.push_back(key);
  items_.push_back(std::move(value));
}

namespace {

// A number as a file would spell it: YAML's words for the non-finite ones, so that a reader
// names the rule they break.
std::string NumberText(const Document& d) {
  if (d.is_integer()) return d.text();
  const double value = d.number();
  if (std::isnan(value)) return ".nan";
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  return FormatNumber(value);
}

}  // namespace

YAML::Node ToYaml(const Document& d) {
  switch (d.kind()) {
    case Document::Kind::kNull: return YAML::Node(YAML::NodeType::Null);
    case Document::Kind::kBool: return YAML::Node(d.bool_value() ? "true" : "false");
    case Document::Kind::kNumber: return YAML::Node(NumberText(d));
    case Document::Kind::kText: return YAML::Node(d.text());
    case Document::Kind::kList: {
      YAML::Node list(YAML::NodeType::Sequence);
      for (const Document& item : d.items()) list.push_back(ToYaml(item));
      return list;
    }
    case Document::Kind::kMap: {
      YAML::Node map(YAML::NodeType::Map);
      for (std::size_t i = 0; i < d.keys().size(); ++i) map[d.keys()[i]] = ToYaml(d.items()[i]);
      return map;
    }
  }
  return YAML::Node();
}

Document FromYaml(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return Document();
  if (node.IsScalar()) return Document::Text(node.Scalar());
  if (node.IsSequence()) {
    std::vector<Document> items;
    for (const YAML::Node& item : node) items.push_back(FromYaml(item));
    return Document::List(std::move(items));
  }
  std::vector<std::pair<std::string, Document>> entries;
  for (const auto& entry : node) {
    entries.emplace_back(entry.first.Scalar(), FromYaml(entry.second));
  }
  return Document::Map(std::move(entries));
}

Document ParseDocument(const std::string& name, const std::string& text) {
  return FromYaml(yaml::Parse(name, text));
}

}  // namespace musclesim
