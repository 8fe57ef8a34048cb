// Private: the dotted key paths that name one value in a YAML document, such as
// "model.velocity.n" or "load[0].value". `--set` takes them from the user and ParameterError
// reports them; both are read by the one parser here.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace musclesim::yaml {

// One step down a document: a map key, or a sequence index when `key` is empty.
struct KeyPathStep {
  std::string key;         // map key; empty for an index
  std::size_t index = 0;   // sequence index (0-based) when `key` is empty
};

// Splits "a.b[2].c" into {a}, {b}, {[2]}, {c}. A dot on either side of an index is
// optional and one trailing dot is ignored. Returns nullopt for a malformed path: an empty
// key ("a..b", ".a"), an index that is empty or not decimal digits, or an unclosed "[".
// The empty path has no steps. An index too large for std::size_t throws std::out_of_range.
std::optional<std::vector<KeyPathStep>> SplitKeyPath(const std::string& path);

}  // namespace musclesim::yaml
