// Private helpers for reading validated values out of a parsed document (document.h). Every error
// they raise names the dotted key path, the value, the file:line:column and the broken rule:
//   model.velocity.n = 0 (scenarios/x.yaml:7:8): must be an integer >= 1
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/document.h"

namespace musclesim::yaml {

// Where values come from: the file name printed in messages, and what a message says where
// a node has no file position (one given by an override, or a document built in code).
struct Source {
  std::string file;
  std::string unplaced = "override";
};

// Throws InputError for `path` at `node`'s position (an empty path: the document's top level).
[[noreturn]] void Fail(const Source& source, const Document& node, const std::string& path,
                       const std::string& value, const std::string& rule);

// Where a node sits: the file, line and column (1-based), or the source's label for a node
// without a position.
InputPlace Place(const Source& source, const Document& node);
InputPlace Place(const Source& source, TextPosition position);

// "file:line:column" of a node (1-based), or the bare file name without a position.
std::string Location(const Source& source, const Document& node);

// The node's text as written, for messages ("[1, 2]", "abc", "~"): one line of at most
// 120 characters, a longer one cut with "...".
std::string Describe(const Document& node);

// Requires `node` to be a map whose keys are all in `allowed` or `extra`, the keys listed
// after them: a block read by a shared reader inside a map that adds keys of its own (a
// network load's `node` and `direction`).
void RequireMap(const Source& source, const Document& node, const std::string& path,
                std::initializer_list<const char*> allowed,
                std::initializer_list<const char*> extra = {});
void RequireMap(const Source& source, const Document& node, const std::string& path,
                const std::vector<std::string>& allowed);

// A key that must be present in a map.
const Document& Required(const Source& source, const Document& map, const std::string& path,
                         const char* key);

std::string Join(const std::string& path, const std::string& key);

double ReadNumber(const Source& source, const Document& node, const std::string& path);

// A number within `range` (NaN never is); its message states the range and why.
double ReadNumberIn(const Source& source, const Document& node, const std::string& path,
                    const InputRange& range);
// The number at `map[key]` within `range`, or `fallback` when the key is absent.
double ReadOptionalNumberIn(const Source& source, const Document& map, const std::string& path,
                            const char* key, const InputRange& range, double fallback);
// The number at `map[key]` (its path `path.key`), or `fallback` when the key is absent.
double ReadOptionalNumber(const Source& source, const Document& map, const std::string& path,
                          const char* key, double fallback);
int ReadInteger(const Source& source, const Document& node, const std::string& path);
bool ReadBool(const Source& source, const Document& node, const std::string& path);
std::string ReadString(const Source& source, const Document& node, const std::string& path);
// The required key `key` of the map `item` (at `path`) as a plain name, of letters, digits, _
// and -: a part's own name heads CSV columns ("load.position"), so that the header stays one
// comma-separated line whose names split at their last dot.
std::string ReadPlainName(const Source& source, const Document& item, const std::string& path,
                          const std::string& key);
// A sequence of numbers, optionally of an exact length (0: any length).
std::vector<double> ReadNumbers(const Source& source, const Document& node, const std::string& path,
                                std::size_t exact_length = 0);

// Re-throws a ParameterError raised while validating the block at `block` (whose key path
// is `block_path`) as an InputError placed at the deepest node its path reaches.
[[noreturn]] void Relocate(const Source& source, const Document& block,
                           const std::string& block_path, const ParameterError& error);

// Runs `check` (a Validate, or the Parse of a name) and re-throws its ParameterError as
// Relocate does, placed under `node` (key path `path`).
template <typename Check>
void ValidateAt(const Source& source, const Document& node, const std::string& path, Check check) {
  try {
    check();
  } catch (const ParameterError& error) {
    Relocate(source, node, path, error);
  }
}

// Parses a YAML file; a missing file, a directory, a syntax error, a key given twice in one
// map, a key that is not a plain name or a second document is an InputError.
Document LoadFile(const std::string& path);
// The two halves of LoadFile: the file's text (ReadInputFile: a regular file of at most
// kMaxInputBytes), and that text parsed
// and checked as LoadFile says (`path` for messages).
std::string ReadText(const std::string& path);
Document Parse(const std::string& path, const std::string& text);

}  // namespace musclesim::yaml
