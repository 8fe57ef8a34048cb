#include "musclesim/core/key_path.h"

#include <charconv>

namespace musclesim {

std::optional<std::vector<KeyPathStep>> SplitKeyPath(const std::string& path) {
  std::vector<KeyPathStep> steps;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '[') {
      const std::size_t close = path.find(']', pos);
      if (close == std::string::npos || close == pos + 1) return std::nullopt;
      const std::string digits = path.substr(pos + 1, close - pos - 1);
      if (digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
      std::size_t index = 0;
      const auto [end, error] =
          std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (error != std::errc() || end != digits.data() + digits.size() ||
          index > kMaxKeyPathIndex) {
        return std::nullopt;
      }
      steps.push_back({"", index});
      pos = close + 1;
      if (pos < path.size() && path[pos] == '.') ++pos;
    } else {
      const std::size_t end = path.find_first_of(".[", pos);
      const std::string key = path.substr(pos, end - pos);
      if (key.empty()) return std::nullopt;
      steps.push_back({key, 0});
      // a dot separates keys; a "[" starts the next step itself
      pos = end == std::string::npos ? path.size() : (path[end] == '.' ? end + 1 : end);
    }
  }
  return steps;
}

}  // namespace musclesim
