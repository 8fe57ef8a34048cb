#include "io/readers/yaml_document_check.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <sstream>
#include <unordered_map>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"

namespace musclesim::yaml {

namespace {

InputPlace Place(const std::string& path, const YAML::Mark& mark) {
  return {path, mark.line + 1, mark.column + 1};
}

// The parse events of one document, with the open maps and lists on a stack. Events never
// expand aliases, so a document that aliases itself or multiplies nodes costs no more than
// its text.
class DocumentChecker : public YAML::EventHandler {
 public:
  explicit DocumentChecker(const std::string& path) : path_(path) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { Value(mark, nullptr); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Value(mark, nullptr); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string& value) override {
    Value(mark, &value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    Open(mark, false);
  }
  void OnSequenceEnd() override { open_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    Open(mark, true);
  }
  void OnMapEnd() override { open_.pop_back(); }

 private:
  struct Collection {
    bool is_map = false;
    std::string path;                                  // key path of this map or list
    std::size_t items = 0;                             // list items seen so far
    bool expecting_key = true;                         // maps alternate key, value
    std::string key;                                   // the key of the value to come
    std::unordered_map<std::string, YAML::Mark> keys;  // every key so far, where given
  };

  // A scalar (`value`) or a null or alias (nullptr) at `mark`.
  void Value(const YAML::Mark& mark, const std::string* value) {
    if (!open_.empty() && open_.back().is_map && open_.back().expecting_key) {
      Collection& map = open_.back();
      if (value == nullptr) KeyNotAName(mark, "empty or an alias");
      RequirePrintable(Join(map.path, *value), mark, *value);
      const auto [seen, inserted] = map.keys.emplace(*value, mark);
      if (!inserted) {
        throw InputError(InputFault{Place(path_, mark), Join(map.path, *value), std::nullopt,
                                    "duplicate key: already given at line " +
                                        std::to_string(seen->second.line + 1) + ", column " +
                                        std::to_string(seen->second.column + 1) +
                                        "; a map holds each key once"});
      }
      map.key = *value;
      map.expecting_key = false;
      return;
    }
    const std::string at = ChildPath();
    if (value != nullptr) RequirePrintable(at, mark, *value);
  }

  // Names and values end up in messages and on the terminal: a control character (an escape
  // sequence that recolours or clears the screen, a bell) is refused where it is read.
  void RequirePrintable(const std::string& at, const YAML::Mark& mark,
                        const std::string& text) const {
    const std::size_t i = FirstControlCharacter(text);
    if (i == std::string::npos) return;
    throw InputError(InputFault{
        Place(path_, mark), at, text,
        "holds the control character " +
            PrintableText(text.substr(i, static_cast<unsigned char>(text[i]) == 0xc2 ? 2 : 1)) +
            " at byte " + std::to_string(i + 1) +
            "; names and values are printable text (a tab or a newline is allowed)"});
  }

  void Open(const YAML::Mark& mark, bool is_map) {
    if (!open_.empty() && open_.back().is_map && open_.back().expecting_key) {
      KeyNotAName(mark, is_map ? "a map" : "a list");
    }
    Collection next;
    next.is_map = is_map;
    next.path = ChildPath();
    open_.push_back(std::move(next));
  }

  // The key path of the value now starting inside the innermost collection; advances it.
  std::string ChildPath() {
    if (open_.empty()) return "";
    Collection& parent = open_.back();
    if (parent.is_map) {
      parent.expecting_key = true;
      return Join(parent.path, parent.key);
    }
    return parent.path + "[" + std::to_string(parent.items++) + "]";
  }

  [[noreturn]] void KeyNotAName(const YAML::Mark& mark, const std::string& what) const {
    const std::string& at = open_.back().path;
    throw InputError(InputFault{Place(path_, mark), at, std::nullopt,
                                "a key is " + what + "; keys must be plain names"});
  }

  static std::string Join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  const std::string& path_;
  std::vector<Collection> open_;
};

// Counts the documents of a stream and remembers where the second starts.
class DocumentCounter : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
  YAML::Mark start;
};

}  // namespace

std::string TooDeep(int depth) {
  return "YAML nesting " + std::to_string(depth) +
         " levels deep, past the reader's limit: a musclesim file nests a few levels (a list "
         "of maps of maps)";
}

void CheckDocument(const std::string& path, const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentChecker checker(path);
  parser.HandleNextDocument(checker);
  // YAML::Load reads the first document only: a second would be ignored without a word
  DocumentCounter counter;
  try {
    if (parser.HandleNextDocument(counter)) {
      throw InputError(InputFault{Place(path, counter.start), "", std::nullopt,
                                  "a second YAML document (after ---); a file holds one document"});
    }
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(InputFault{Place(path, e.mark), "", std::nullopt, TooDeep(e.depth())});
  } catch (const YAML::ParserException& e) {
    throw InputError(
        InputFault{Place(path, e.mark), "", std::nullopt, "YAML syntax error: " + e.msg});
  }
}

}  // namespace musclesim::yaml
