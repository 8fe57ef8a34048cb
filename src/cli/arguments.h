// Command-line parsing shared by the verbs: options with values, flags, positionals.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/io/writers/curves_csv.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/model/force_length_presets.h"

namespace musclesim::cli {

// A malformed command line (exit code 2).
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

struct Arguments {
  std::vector<std::string> positional;
  std::map<std::string, std::vector<std::string>> values;  // option -> every value given
  std::set<std::string> flags;

  bool Has(const std::string& option) const {
    return values.count(option) != 0 || flags.count(option) != 0;
  }
  // The option's last value, or `fallback` when absent.
  std::string Value(const std::string& option, const std::string& fallback = "") const;
  // Every value given to `option`, in order (none: empty).
  std::vector<std::string> List(const std::string& option) const;
};

// Parses argv[first..]. `with_value` lists options that take a value (both "--opt V" and
// "--opt=V"), `flags` options that take none ("--flag=V" is a UsageError); anything else
// starting with '-' (but "-" alone) is a UsageError.
Arguments Parse(int argc, char** argv, int first, const std::set<std::string>& with_value,
                const std::set<std::string>& flags);

// An evenly spaced grid "A:B:N": N >= 2 points from A to B inclusive, A < B, both within
// `range`. A malformed grid is a UsageError naming `option` and `text`.
UniformGrid ParseGrid(const std::string& option, const std::string& text, const InputRange& range);

// A number within `range` (NaN and infinities never are). A UsageError names `option`,
// `text` and the rule otherwise.
double ParseNumber(const std::string& option, const std::string& text, const InputRange& range);

// A standard force-length curve by name; an unknown name is a UsageError listing them all.
ForceLengthPreset ParsePreset(const std::string& option, const std::string& text);

}  // namespace musclesim::cli
