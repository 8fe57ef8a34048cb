#include "musclesim/core/enum_names.h"

namespace musclesim {

std::string MustBeOneOf(std::span<const std::string_view> names) {
  std::string rule = names.size() > 2 ? "must be one of " : "must be ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    // a list of two reads "a or b"; a longer one "a, b, c"
    if (i > 0) rule += names.size() == 2 ? " or " : ", ";
    rule += names[i];
  }
  return rule;
}

}  // namespace musclesim
