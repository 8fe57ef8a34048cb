#include "musclesim/core/input_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

double TimeScale(double t_start, double t_end) {
  return std::max({1.0, std::abs(t_start), std::abs(t_end)});
}

std::string InputRange::Bounds() const {
  // no bound above but the largest double: any finite number from min
  if (max == std::numeric_limits<double>::max() && !max_exclusive) {
    return (min_exclusive ? "> " : ">= ") + FormatNumber(min) + " and finite";
  }
  if (!min_exclusive && !max_exclusive) {
    return "from " + FormatNumber(min) + " to " + FormatNumber(max);
  }
  return (min_exclusive ? "> " : ">= ") + FormatNumber(min) +
         (max_exclusive ? " and < " : " and <= ") + FormatNumber(max);
}

std::string InputRange::Rule() const { return "must be " + Bounds() + " [" + unit + "]: " + why; }

void RequireInRange(std::string_view key, double value, const InputRange& range) {
  Require(range.Contains(value), key, value, range.Rule());
}

}  // namespace musclesim
