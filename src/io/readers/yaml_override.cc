#include "io/readers/yaml_override.h"

#include "musclesim/core/key_path.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"

namespace musclesim::yaml {

namespace {

// Blocks whose keys are all optional, so that a file may leave the block out entirely:
// an override of one of their keys creates the block. Any other missing map is a misspelt path.
bool IsOptionalBlock(const std::string& key) {
  return key == "eccentric";  // model.velocity.eccentric (docs/model.md section 9)
}

}  // namespace

void ApplyOverrides(Document& root, const Overrides& overrides, const std::string& file) {
  for (const std::string& text : overrides.texts) {
    ApplyOverride(root, text, file, overrides.label);
  }
}

void ApplyOverride(Document& root, const std::string& text, const std::string& file,
                   const std::string& label) {
  // messages are headed "LABEL KEY=VALUE: "; the fault names the key and value given
  const std::string head = label + " " + text + ": ";
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    throw InputError(head, InputFault{InputPlace{label}, "", text,
                                      "expected KEY=VALUE, e.g. model.velocity.n=4"});
  }
  const std::string path = text.substr(0, eq);
  const std::string value = text.substr(eq + 1);
  const auto fail = [&](const std::string& rule) {
    throw InputError(head, InputFault{InputPlace{label}, path, value, rule});
  };
  // names and values reach messages and the terminal, as a file's do (yaml_document_check.h)
  if (const std::size_t at = FirstControlCharacter(text); at != std::string::npos) {
    fail("holds a control character at byte " + std::to_string(at + 1) +
         "; names and values are printable text");
  }
  const auto split = SplitKeyPath(path);
  if (!split || split->empty()) {
    fail("'" + path +
         "' is not a dotted key path such as model.velocity.n or load[0].value (names "
         "joined by dots, list indices in brackets from 0 to 999999999)");
  }
  const std::vector<KeyPathStep>& steps = *split;
  Document* node = &root;
  std::string walked;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const KeyPathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    const std::string here = step.key.empty()
                                 ? walked + "[" + std::to_string(step.index) + "]"
                                 : (walked.empty() ? step.key : walked + "." + step.key);
    Document* next = nullptr;
    if (step.key.empty()) {
      if (node->IsMap() && walked == "load" && step.index == 0) {
        next = node;  // a single load written as a map is load[0]
      } else if (node->IsMap()) {
        const std::string map = walked.empty() ? "the file's top level" : walked;
        fail(map + " is a map, not a list, in " + file +
             ": an index on it has no meaning (name a key instead)");
      } else if (!node->IsSequence() || step.index >= node->size()) {
        fail(here + " does not exist in " + file);
      } else {
        next = &node->Item(step.index);
      }
      if (last) {
        if (!next->IsScalar()) {
          fail(here + " is a map or list; an override replaces single values only");
        }
        *next = Document::Text(value);
        return;
      }
    } else {
      if (!node->IsMap()) {
        fail((walked.empty() ? "the file" : walked) + " is not a map in " + file);
      }
      next = node->Find(step.key);
      if (last) {
        if (next != nullptr && !next->IsScalar() && !next->IsNull()) {
          fail(here + " is a map or list; an override replaces single values only");
        }
        node->Set(step.key, Document::Text(value));
        return;
      }
      if (next == nullptr) {
        if (!IsOptionalBlock(step.key)) fail(here + " does not exist in " + file);
        node->Set(step.key, Document::Map({}));  // filled by the steps below
        next = node->Find(step.key);
      }
    }
    node = next;
    walked = here;
  }
}

}  // namespace musclesim::yaml
