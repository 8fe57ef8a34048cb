#include "io/readers/yaml_fields.h"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "musclesim/core/key_path.h"
#include "musclesim/io/readers/input_file.h"
#include "io/readers/document_yaml.h"
#include "io/readers/yaml_document_check.h"

namespace musclesim::yaml {

InputPlace Place(const Source& source, TextPosition position) {
  // none: an override's value, or a document built in code
  if (!position.known()) return {source.unplaced};
  return {source.file, position.line + 1, position.column + 1};
}

InputPlace Place(const Source& source, const Document& node) {
  return Place(source, node.position());
}

std::string Location(const Source& source, const Document& node) {
  return PlaceText(Place(source, node));
}

std::string Describe(const Document& node) {
  if (!node.IsDefined() || node.IsNull()) return "~";
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << ToYaml(node);
  // a message is one line, and a long list is shown by its start
  std::string text = out.c_str();
  for (char& c : text) c = c == '\n' ? ' ' : c;
  constexpr std::size_t kLongest = 120;
  if (text.size() > kLongest) text = text.substr(0, kLongest - 3) + "...";
  return text;
}

void Fail(const Source& source, const Document& node, const std::string& path,
          const std::string& value, const std::string& rule) {
  throw InputError(InputFault{Place(source, node), path, value, rule});
}

std::string Join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

void RequireMap(const Source& source, const Document& node, const std::string& path,
                const std::vector<std::string>& allowed) {
  if (!node.IsMap()) {
    Fail(source, node, path, Describe(node), "must be a map of keys");
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string& key = node.key(i);
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (const std::string& name : allowed) list.append(list.empty() ? "" : ", ").append(name);
    throw InputError(InputFault{Place(source, node.key_position(i)), Join(path, key), std::nullopt,
                                "unknown key; allowed here: " + list});
  }
}

void RequireMap(const Source& source, const Document& node, const std::string& path,
                std::initializer_list<const char*> allowed,
                std::initializer_list<const char*> extra) {
  std::vector<std::string> keys(allowed.begin(), allowed.end());
  keys.insert(keys.end(), extra.begin(), extra.end());
  RequireMap(source, node, path, keys);
}

const Document& Required(const Source& source, const Document& map, const std::string& path,
                         const char* key) {
  const Document& node = map[key];
  if (!node.IsDefined()) {
    throw InputError(
        InputFault{Place(source, map), Join(path, key), std::nullopt, "missing required key"});
  }
  return node;
}

double ReadNumber(const Source& source, const Document& node, const std::string& path) {
  double value = 0.0;
  if (node.kind() == Document::Kind::kNumber) return node.number();
  if (node.kind() != Document::Kind::kText || !DecodeNumber(node.text(), value)) {
    Fail(source, node, path, Describe(node), "must be a number");
  }
  return value;
}

double ReadOptionalNumber(const Source& source, const Document& map, const std::string& path,
                          const char* key, double fallback) {
  return map[key] ? ReadNumber(source, map[key], Join(path, key)) : fallback;
}

double ReadNumberIn(const Source& source, const Document& node, const std::string& path,
                    const InputRange& range) {
  const double value = ReadNumber(source, node, path);
  if (!range.Contains(value)) Fail(source, node, path, Describe(node), range.Rule());
  return value;
}

double ReadOptionalNumberIn(const Source& source, const Document& map, const std::string& path,
                            const char* key, const InputRange& range, double fallback) {
  return map[key] ? ReadNumberIn(source, map[key], Join(path, key), range) : fallback;
}

int ReadInteger(const Source& source, const Document& node, const std::string& path) {
  const double value = ReadNumber(source, node, path);
  if (!(std::abs(value) <= 1e9) || value != std::floor(value)) {
    Fail(source, node, path, Describe(node), "must be an integer");
  }
  return static_cast<int>(value);
}

bool ReadBool(const Source& source, const Document& node, const std::string& path) {
  bool value = false;
  if (node.kind() == Document::Kind::kBool) return node.bool_value();
  if (node.kind() != Document::Kind::kText || !DecodeBool(node.text(), value)) {
    Fail(source, node, path, Describe(node), "must be true or false");
  }
  return value;
}

std::string ReadString(const Source& source, const Document& node, const std::string& path) {
  if (!node.IsScalar()) Fail(source, node, path, Describe(node), "must be a text value");
  return node.Scalar();
}

std::string ReadPlainName(const Source& source, const Document& item, const std::string& path,
                          const std::string& key) {
  const Document& node = Required(source, item, path, key.c_str());
  const std::string name = ReadString(source, node, Join(path, key));
  bool plain = !name.empty();
  for (const char c : name) {
    plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '-');
  }
  if (!plain) {
    Fail(source, node, Join(path, key), name.empty() ? "\"\"" : Describe(node),
         "must be a plain name of letters, digits, _ and - (it heads CSV columns such "
         "as name.position)");
  }
  return name;
}

std::vector<double> ReadNumbers(const Source& source, const Document& node, const std::string& path,
                                std::size_t exact_length) {
  if (!node.IsSequence()) Fail(source, node, path, Describe(node), "must be a list of numbers");
  if (exact_length != 0 && node.size() != exact_length) {
    Fail(source, node, path, Describe(node),
         "must be a list of exactly " + std::to_string(exact_length) + " numbers");
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < node.size(); ++i) {
    values.push_back(ReadNumber(source, node[i], path + "[" + std::to_string(i) + "]"));
  }
  return values;
}

namespace {

// The node at steps[i..] below `node`, or the deepest one that exists on the way.
const Document& Deepest(const Document& node, const std::vector<KeyPathStep>& steps,
                        std::size_t i) {
  if (i == steps.size()) return node;
  const KeyPathStep& step = steps[i];
  if (step.key.empty()) {
    if (!node.IsSequence() || step.index >= node.size()) return node;
    return Deepest(node[step.index], steps, i + 1);
  }
  if (!node.IsMap() || !node[step.key].IsDefined()) return node;
  return Deepest(node[step.key], steps, i + 1);
}

}  // namespace

void Relocate(const Source& source, const Document& block, const std::string& block_path,
              const ParameterError& error) {
  // the library writes these paths well formed; a malformed one still points at the block
  const auto steps = SplitKeyPath(error.path());
  Fail(source, steps ? Deepest(block, *steps, 0) : block, Join(block_path, error.path()),
       error.value(), error.rule());
}

namespace {

InputPlace MarkPlace(const std::string& file, const YAML::Mark& mark) {
  return {file, mark.line + 1, mark.column + 1};
}

}  // namespace

std::string ReadText(const std::string& path) { return ReadInputFile(path, "a YAML file"); }

Document Parse(const std::string& path, const std::string& text) {
  try {
    YAML::Node root = YAML::Load(text);
    // an empty document has no position; say so here rather than at an unplaced node
    if (!root.IsDefined() || root.IsNull()) {
      throw InputError(InputFault{InputPlace{path}, "", std::nullopt, "the file is empty"});
    }
    CheckDocument(path, text);
    return FromYaml(root, path);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(InputFault{MarkPlace(path, e.mark), "", std::nullopt, TooDeep(e.depth())});
  } catch (const YAML::ParserException& e) {
    throw InputError(
        InputFault{MarkPlace(path, e.mark), "", std::nullopt, "YAML syntax error: " + e.msg});
  }
}

Document LoadFile(const std::string& path) { return Parse(path, ReadText(path)); }

}  // namespace musclesim::yaml
