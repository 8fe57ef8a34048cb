// Paths and name lists in a network's error messages ("elements[2].to"; "the nodes are: a, b").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace musclesim {

inline std::string Entry(const char* list, std::size_t i, const char* key) {
  return std::string(list) + "[" + std::to_string(i) + "]." + key;
}

template <typename Part>
std::string KnownNames(const std::vector<Part>& parts) {
  std::string names;
  for (const Part& p : parts) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

}  // namespace musclesim
