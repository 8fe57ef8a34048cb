// The dotted key paths that name one value in a YAML document, such as
// "model.velocity.n" or "load[0].value". `--set` takes them from the user and ParameterError
// reports them; both are read by the one parser here.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace musclesim {

// One step down a document: a map key, or a sequence index when `key` is empty.
struct KeyPathStep {
  std::string key;        // map key; empty for an index
  std::size_t index = 0;  // sequence index (0-based) when `key` is empty
};

// The largest index a path may hold [-]: no list in a file the program reads is longer (a
// waveform has at most 5 million points).
inline constexpr std::size_t kMaxKeyPathIndex = 999999999;

// Splits "a.b[2].c" into {a}, {b}, {[2]}, {c}. A dot on either side of an index is
// optional and one trailing dot is ignored. Returns nullopt for a malformed path: an empty
// key ("a..b", ".a"), an index that is empty, not decimal digits or above kMaxKeyPathIndex,
// or an unclosed "[". The empty path has no steps.
std::optional<std::vector<KeyPathStep>> SplitKeyPath(const std::string& path);

}  // namespace musclesim
