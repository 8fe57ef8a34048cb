#include "cli/arguments.h"

#include <charconv>
#include <cmath>

#include "musclesim/core/errors.h"

namespace musclesim::cli {

std::string Arguments::Value(const std::string& option, const std::string& fallback) const {
  const auto it = values.find(option);
  return it == values.end() ? fallback : it->second.back();
}

Arguments Parse(int argc, char** argv, int first, const std::set<std::string>& with_value,
                const std::set<std::string>& flags) {
  Arguments args;
  for (int i = first; i < argc; ++i) {
    std::string word = argv[i];
    if (word.size() < 2 || word[0] != '-') {
      args.positional.push_back(word);
      continue;
    }
    std::string value;
    bool inline_value = false;
    if (const auto eq = word.find('='); eq != std::string::npos && word.rfind("--", 0) == 0) {
      value = word.substr(eq + 1);
      word.resize(eq);
      inline_value = true;
    }
    if (flags.count(word) != 0) {
      if (inline_value) {
        throw UsageError(word + "=" + value + ": " + word + " is a flag and takes no value");
      }
      args.flags.insert(word);
    } else if (with_value.count(word) != 0) {
      if (!inline_value) {
        if (i + 1 >= argc) throw UsageError(word + " needs a value");
        value = argv[++i];
      }
      args.values[word].push_back(value);
    } else {
      throw UsageError("unknown option " + word + " (see --help)");
    }
  }
  return args;
}

namespace {

double ParseDouble(const std::string& option, const std::string& text) {
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw UsageError(option + " " + text + ": '" + text + "' is not a finite number");
  }
  return value;
}

}  // namespace

UniformGrid ParseGrid(const std::string& option, const std::string& text, const InputRange& range) {
  const auto first = text.find(':');
  const auto second = text.find(':', first == std::string::npos ? first : first + 1);
  if (first == std::string::npos || second == std::string::npos) {
    throw UsageError(option + " " + text + ": expected A:B:N (from, to, number of points)");
  }
  UniformGrid grid;
  grid.from = ParseDouble(option, text.substr(0, first));
  grid.to = ParseDouble(option, text.substr(first + 1, second - first - 1));
  const std::string count = text.substr(second + 1);
  const auto result = std::from_chars(count.data(), count.data() + count.size(), grid.count);
  if (result.ec != std::errc() || result.ptr != count.data() + count.size() || grid.count < 2 ||
      grid.count > 10000000) {
    throw UsageError(option + " " + text + ": N must be an integer from 2 to 10000000");
  }
  if (!(grid.from < grid.to)) {
    throw UsageError(option + " " + text + ": A must be less than B");
  }
  for (const double end : {grid.from, grid.to}) {
    if (!range.Contains(end)) {
      throw UsageError(option + " " + text + ": " + (end == grid.from ? "A" : "B") + " = " +
                       FormatNumber(end) + " " + range.Rule());
    }
  }
  return grid;
}

double ParseNumber(const std::string& option, const std::string& text, const InputRange& range) {
  const double value = ParseDouble(option, text);
  if (!range.Contains(value)) throw UsageError(option + " " + text + ": " + range.Rule());
  return value;
}

ForceLengthPreset ParsePreset(const std::string& option, const std::string& text) {
  try {
    return ParseForceLengthPreset(text);
  } catch (const ParameterError& e) {
    throw UsageError(option + " " + text + ": " + e.rule());
  }
}

std::vector<std::string> Arguments::List(const std::string& option) const {
  const auto found = values.find(option);
  return found == values.end() ? std::vector<std::string>{} : found->second;
}

}  // namespace musclesim::cli
