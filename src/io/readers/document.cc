#include "musclesim/io/readers/document.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "io/readers/document_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/core/errors.h"
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

Document Document::Text(std::string value, bool quoted) {
  Document d;
  d.kind_ = Kind::kText;
  d.text_ = std::move(value);
  d.quoted_ = quoted;
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

Document* Document::Find(const std::string& key) {
  return const_cast<Document*>(static_cast<const Document&>(*this).Find(key));
}

void Document::Set(const std::string& key, Document value) {
  kind_ = Kind::kMap;
  if (Document* held = Find(key)) {
    *held = std::move(value);
    return;
  }
  Append(key, TextPosition{}, std::move(value));
}

void Document::Append(std::string key, TextPosition at, Document value) {
  kind_ = Kind::kMap;
  keys_.push_back(std::move(key));
  key_positions_.push_back(at);
  items_.push_back(std::move(value));
}

bool Document::IsScalar() const {
  return kind_ == Kind::kBool || kind_ == Kind::kNumber || kind_ == Kind::kText;
}

const Document& Document::Absent() {
  static const Document absent = [] {
    Document d;
    d.kind_ = Kind::kAbsent;
    return d;
  }();
  return absent;
}

const Document& Document::operator[](std::size_t index) const {
  return kind_ == Kind::kList && index < items_.size() ? items_[index] : Absent();
}

const Document& Document::operator[](const std::string& key) const {
  if (kind_ != Kind::kMap) return Absent();
  const Document* found = Find(key);
  return found != nullptr ? *found : Absent();
}

namespace {

TextPosition PositionOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {};
  return {mark.line, mark.column};
}

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

std::string Document::Scalar() const {
  switch (kind_) {
    case Kind::kBool: return bool_ ? "true" : "false";
    case Kind::kNumber: return NumberText(*this);
    case Kind::kText: return text_;
    default: return "";
  }
}

bool DecodeNumber(const std::string& text, double& value) {
  return YAML::convert<double>::decode(YAML::Node(text), value);
}

bool DecodeBool(const std::string& text, bool& value) {
  return YAML::convert<bool>::decode(YAML::Node(text), value);
}

YAML::Node ToYaml(const Document& d) {
  switch (d.kind()) {
    case Document::Kind::kAbsent: return YAML::Node();
    case Document::Kind::kNull: return YAML::Node(YAML::NodeType::Null);
    case Document::Kind::kBool:
    case Document::Kind::kNumber: return YAML::Node(d.Scalar());
    case Document::Kind::kText: {
      YAML::Node scalar(d.text());
      if (d.quoted()) scalar.SetTag("!");  // as a parsed quoted scalar: written back quoted
      return scalar;
    }
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

namespace {

// The walk of a yaml-cpp tree into a Document. yaml-cpp shares an aliased node rather than
// copying it, so the walk refuses what sharing hides: an alias inside the value it names (a
// cycle, endless as a tree) and aliases of aliases that multiply a short text into millions
// of values.
class TreeCopy {
 public:
  explicit TreeCopy(const std::string& file) : file_(file) {}

  Document Copy(const YAML::Node& node, const std::string& path) {
    for (const YAML::Node& open : open_) {
      if (open.is(node)) Refuse(node, path, "an alias inside the value it names (a cycle)");
    }
    if (++values_ > kMaxValues) {
      Refuse(node, path,
             "the document's aliases expand it past " + std::to_string(kMaxValues) +
                 " values; a musclesim file holds far fewer");
    }
    Document d;
    open_.push_back(node);
    if (node.IsScalar()) {
      d = Document::Text(node.Scalar(), node.Tag() == "!");
    } else if (node.IsSequence()) {
      std::vector<Document> items;
      items.reserve(node.size());
      for (const YAML::Node& item : node) {
        items.push_back(Copy(item, path + "[" + std::to_string(items.size()) + "]"));
      }
      d = Document::List(std::move(items));
    } else if (node.IsMap()) {
      d = Document::Map({});
      for (const auto& entry : node) {
        const std::string key = entry.first.Scalar();
        d.Append(key, PositionOf(entry.first),
                 Copy(entry.second, path.empty() ? key : path + "." + key));
      }
    }
    open_.pop_back();
    d.set_position(PositionOf(node));
    return d;
  }

 private:
  static constexpr long kMaxValues = 1'000'000;

  [[noreturn]] void Refuse(const YAML::Node& node, const std::string& path,
                           const std::string& rule) const {
    const TextPosition at = PositionOf(node);
    std::optional<InputPlace> place;
    if (at.known()) place = InputPlace{file_, at.line + 1, at.column + 1};
    throw InputError(InputFault{place, path, std::nullopt, rule});
  }

  const std::string& file_;
  std::vector<YAML::Node> open_;  // the maps and lists being copied, outermost first
  long values_ = 0;
};

}  // namespace

Document FromYaml(const YAML::Node& node, const std::string& file) {
  return TreeCopy(file).Copy(node, "");
}

Document ParseDocument(const std::string& name, const std::string& text) {
  return yaml::Parse(name, text);
}

}  // namespace musclesim
