// A document held in memory: the tree every reader reads (null, booleans, numbers, text,
// lists, and maps keeping their keys' order), with the file position of each value and key.
// A YAML or JSON file is parsed into it at the edge (ParseDocument); the Python module builds
// one straight from a dict (scenario_from_dict, sweep, identify_series), so that both are read
// with the same rules and messages, and no text in between.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace musclesim {

// Where a value or key was written: its 0-based line and column, or none for one built in
// code or given by an override.
struct TextPosition {
  int line = -1;
  int column = -1;
  bool known() const { return line >= 0; }
};

class Document {
 public:
  // kAbsent: what a lookup of a missing key or index answers (never a value of a document)
  enum class Kind { kAbsent, kNull, kBool, kNumber, kText, kList, kMap };

  Document() = default;  // null
  static Document Bool(bool value);
  static Document Number(double value);
  static Document Integer(long long value);
  // A scalar as written in a file: its meaning (number, flag, name) is the reader's to tell.
  // `quoted`: written in quotes, kept so that a document written back keeps them.
  static Document Text(std::string value, bool quoted = false);
  static Document List(std::vector<Document> items);
  static Document Map(std::vector<std::pair<std::string, Document>> entries);

  Kind kind() const { return kind_; }
  bool bool_value() const { return bool_; }
  double number() const { return number_; }
  bool is_integer() const { return integer_; }  // a number given as an integer
  bool quoted() const { return quoted_; }
  const std::string& text() const { return text_; }
  const std::vector<Document>& items() const { return items_; }   // a list's
  const std::vector<std::string>& keys() const { return keys_; }  // a map's, in order
  // The value at `key` in a map, or nullptr.
  const Document* Find(const std::string& key) const;
  Document* Find(const std::string& key);
  // A map with `key` set to `value` (added last when absent).
  void Set(const std::string& key, Document value);
  // A map with `key` (which it must not hold yet, as a parser knows) added last, written at
  // `at`: no search, so that a long map is built in linear time.
  void Append(std::string key, TextPosition at, Document value);
  // A list's item `index` (which must exist), to be replaced.
  Document& Item(std::size_t index) { return items_[index]; }

  // Where this value, and a map's key `index`, were written.
  TextPosition position() const { return position_; }
  TextPosition key_position(std::size_t index) const { return key_positions_[index]; }
  void set_position(TextPosition position) { position_ = position; }

  // The readers' view, a tree walked by key and index where a missing one reads as absent.
  bool IsDefined() const { return kind_ != Kind::kAbsent; }
  explicit operator bool() const { return IsDefined(); }
  bool IsNull() const { return kind_ == Kind::kNull; }
  bool IsScalar() const;  // a flag, number or text
  bool IsSequence() const { return kind_ == Kind::kList; }
  bool IsMap() const { return kind_ == Kind::kMap; }
  // A scalar's text as a file would spell it (a number's shortest exact form, YAML's .nan
  // and .inf, true or false); empty for anything else.
  std::string Scalar() const;
  std::size_t size() const { return items_.size(); }  // a list's items or a map's entries
  const Document& operator[](std::size_t index) const;
  const Document& operator[](int index) const { return (*this)[static_cast<std::size_t>(index)]; }
  const Document& operator[](const std::string& key) const;
  const Document& operator[](const char* key) const { return (*this)[std::string(key)]; }
  // A list's items (a map's values, beside key(i)), for range-for.
  std::vector<Document>::const_iterator begin() const { return items_.begin(); }
  std::vector<Document>::const_iterator end() const { return items_.end(); }
  // A map's key `index`.
  const std::string& key(std::size_t index) const { return keys_[index]; }
  // The absent document that lookups answer.
  static const Document& Absent();

 private:
  Kind kind_ = Kind::kNull;
  bool bool_ = false;
  double number_ = 0.0;
  bool integer_ = false;
  bool quoted_ = false;
  std::string text_;
  std::vector<Document> items_;  // a list's items, or a map's values (keys_ beside them)
  std::vector<std::string> keys_;
  std::vector<TextPosition> key_positions_;
  TextPosition position_;
};

// The document YAML (or JSON) `text` holds; `name` names it in messages. Throws InputError
// for a syntax error, a key given twice or a second document, as the file readers do.
Document ParseDocument(const std::string& name, const std::string& text);

// The number a scalar's text spells in YAML (1, -2.5e3, .inf, .nan), if it spells one.
bool DecodeNumber(const std::string& text, double& value);
// The flag a scalar's text spells in YAML (true, false, yes, no, on, off), if it spells one.
bool DecodeBool(const std::string& text, bool& value);

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
