#include "io/readers/coordinates_yaml.h"

namespace musclesim {

std::string Indexed(std::string path, std::size_t i) {
  path.append("[").append(std::to_string(i)).append("]");
  return path;
}

std::string HasDimensions(int dimensions) {
  return "the scenario has dimensions: " + std::to_string(dimensions);
}

std::string CoordinateNames(int dimensions, const char* prefix) {
  std::string names = "[";
  for (int c = 0; c < dimensions; ++c) {
    names.append(c == 0 ? "" : ", ").append(prefix).push_back("xyz"[c]);
  }
  return names + "]";
}

FieldPoint ReadCoordinateList(const yaml::Source& src, const Document& node,
                              const std::string& path, int dimensions, const InputRange& range,
                              const char* prefix) {
  const auto d = static_cast<std::size_t>(dimensions);
  if (!node.IsSequence() || node.size() != d) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               "must be a list of " + std::to_string(d) + " numbers " +
                   CoordinateNames(dimensions, prefix) + ": " + HasDimensions(dimensions));
  }
  FieldPoint x{};
  for (std::size_t c = 0; c < d; ++c) {
    x[c] = yaml::ReadNumberIn(src, node[c], Indexed(path, c), range);
  }
  return x;
}

FieldPoint ReadPoint(const yaml::Source& src, const Document& node, const std::string& path,
                     int dimensions, const InputRange& range, const char* prefix) {
  if (dimensions > 1) return ReadCoordinateList(src, node, path, dimensions, range, prefix);
  if (node.IsSequence()) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               "must be a number in 1 dimension: a list of coordinates needs dimensions: 2 or 3 "
               "at the top level");
  }
  return {yaml::ReadNumberIn(src, node, path, range), 0.0, 0.0};
}

}  // namespace musclesim
