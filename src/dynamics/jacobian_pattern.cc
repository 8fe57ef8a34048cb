#include "musclesim/dynamics/jacobian_pattern.h"

#include <algorithm>

namespace musclesim {

int JacobianPattern::ColumnOf(int entry) const {
  // the last column starting at or before the entry
  const auto it = std::upper_bound(column_starts.begin(), column_starts.end(), entry);
  return static_cast<int>(it - column_starts.begin()) - 1;
}

}  // namespace musclesim
