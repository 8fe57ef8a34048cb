// Paths and name lists in a network's error messages ("elements[2].to"; "the nodes are: a, b").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {

inline std::string Entry(const char* list, std::size_t i, const char* key) {
  return std::string(list) + "[" + std::to_string(i) + "]." + key;
}

// Validate(part), its ParameterError's path put under the part's list entry ("bodies[1].mass").
template <typename Part>
void ValidateEntry(const Part& part, const char* list, std::size_t i) {
  try {
    Validate(part);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string(list) + "[" + std::to_string(i) + "]." + e.path(), e.value(),
                         e.rule());
  }
}

template <typename Part>
std::string KnownNames(const std::vector<Part>& parts) {
  std::string names;
  for (const Part& p : parts) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

}  // namespace musclesim
