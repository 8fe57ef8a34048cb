// Private: what identifies a sweep, so that `--resume` continues only the sweep that wrote
// PATH.partial. Three 64-bit digests (FNV-1a; they detect edits, not deliberate forgeries):
// the base scenario file's bytes, the points (mode, samples, seed and every axis), and what
// a row holds (the metrics and their options, a network's metric element among them). The
// partial file's first line carries them:
//   # sweep base=0123456789abcdef points=... metrics=...
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "musclesim/sweep/sweep.h"

namespace musclesim {

// FNV-1a over the bytes of `text`.
std::uint64_t Digest(std::string_view text);

struct SweepSignature {
  std::uint64_t base = 0;     // SweepSpec::base_digest [-]
  std::uint64_t points = 0;   // mode, samples, seed and the axes [-]
  std::uint64_t metrics = 0;  // the metrics and metric_options [-]

  static SweepSignature Of(const SweepSpec& spec);
  // The line above, without a newline; Parse reads it back (nullopt for anything else).
  std::string Line() const;
  static std::optional<SweepSignature> Parse(const std::string& line);
  // What differs from `other`, in words ("the base scenario and the axes"); empty if nothing.
  std::string Differences(const SweepSignature& other) const;
};

}  // namespace musclesim
