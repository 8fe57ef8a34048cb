#include "musclesim/core/input_ranges.h"

#include <algorithm>
#include <cmath>

#include "musclesim/core/errors.h"

namespace musclesim {

double TimeScale(double t_start, double t_end) {
  return std::max({1.0, std::abs(t_start), std::abs(t_end)});
}

std::string InputRange::Rule() const {
  const std::string bounds = min_exclusive
                                 ? "must be > " + FormatNumber(min) + " and <= " + FormatNumber(max)
                                 : "must be from " + FormatNumber(min) + " to " + FormatNumber(max);
  return bounds + " [" + unit + "]: " + why;
}

}  // namespace musclesim
