// Names of enum values, as YAML, the command line and output files write them, from one
// table per enum: each enum's source lists its {value, name} pairs once, in a constexpr
// array, and its ToString and Parse both read that table, so nothing can print a name that
// the reader would refuse.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "musclesim/core/errors.h"

namespace musclesim {

template <typename Enum>
struct EnumName {
  Enum value;
  std::string_view name;  // as written in files and on the command line
};

// The rule a ParameterError states for an unknown name: "must be a", "must be a or b",
// "must be one of a, b, c".
std::string MustBeOneOf(std::span<const std::string_view> names);

// The name of `value` in `table`, or "?" for a value it lacks (an out-of-range cast).
template <typename Enum, std::size_t N>
constexpr std::string_view ToString(const EnumName<Enum> (&table)[N], Enum value) {
  for (const EnumName<Enum>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "?";
}

// The value called `text` in `table`. Throws ParameterError(path, text, MustBeOneOf(names)),
// `path` being the key the name was read from ("method", "metrics").
template <typename Enum, std::size_t N>
Enum Parse(const EnumName<Enum> (&table)[N], std::string_view path, std::string_view text) {
  std::array<std::string_view, N> names;
  for (std::size_t i = 0; i < N; ++i) {
    if (table[i].name == text) return table[i].value;
    names[i] = table[i].name;
  }
  throw ParameterError(std::string(path), std::string(text), MustBeOneOf(names));
}

}  // namespace musclesim
