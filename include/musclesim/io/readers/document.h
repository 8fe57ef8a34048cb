// A document held in memory: the tree a YAML or JSON file parses into (null, booleans,
// numbers, text, lists, and maps keeping their keys' order), built in code so that the file
// readers read it with the same rules and messages as a file, and no text in between. The
// Python module builds one from a dict (scenario_from_dict, sweep, identify_series).
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace musclesim {

class Document {
 public:
  enum class Kind { kNull, kBool, kNumber, kText, kList, kMap };

  Document() = default;  // null
  static Document Bool(bool value);
  static Document Number(double value);  // written as its shortest exact text
  static Document Integer(long long value);
  static Document Text(std::string value);
  static Document List(std::vector<Document> items);
  static Document Map(std::vector<std::pair<std::string, Document>> entries);

  Kind kind() const { return kind_; }
  bool bool_value() const { return bool_; }
  double number() const { return number_; }
  bool is_integer() const { return integer_; }  // a number written without a point
  const std::string& text() const { return text_; }
  const std::vector<Document>& items() const { return items_; }   // a list's
  const std::vector<std::string>& keys() const { return keys_; }  // a map's, in order
  // The value at `key` in a map, or nullptr.
  const Document* Find(const std::string& key) const;
  // A map with `key` set to `value` (added last when absent).
  void Set(const std::string& key, Document value);

 private:
  Kind kind_ = Kind::kNull;
  bool bool_ = false;
  double number_ = 0.0;
  bool integer_ = false;
  std::string text_;
  std::vector<Document> items_;  // a list's items, or a map's values (keys_ beside them)
  std::vector<std::string> keys_;
};

// The document YAML (or JSON) `text` holds; `name` names it in messages. Throws InputError
// for a syntax error, a key given twice or a second document, as the file readers do.
Document ParseDocument(const std::string& name, const std::string& text);

// Values of a document replaced before it is read, each "dotted.path=value" (a scalar at an
// existing path, or a new key in an existing map), so that a replaced value is checked as
// the document's own would be. `label` is the caller's word for them in messages: "LABEL
// KEY=VALUE: rule" for one that does not apply, "KEY = VALUE (LABEL): rule" for a value
// that breaks a rule (the command line says "--set", a sweep "axis").
struct Overrides {
  Overrides(std::vector<std::string> given = {}, std::string word = "override")
      : texts(std::move(given)), label(std::move(word)) {}
  Overrides(std::initializer_list<std::string> given) : texts(given) {}

  std::vector<std::string> texts;
  std::string label = "override";
};

}  // namespace musclesim
