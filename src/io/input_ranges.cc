#include "musclesim/io/input_ranges.h"

#include "musclesim/errors.h"

namespace musclesim {

std::string InputRange::Rule() const {
  const std::string bounds =
      min_exclusive ? "must be > " + FormatNumber(min) + " and <= " + FormatNumber(max)
                    : "must be from " + FormatNumber(min) + " to " + FormatNumber(max);
  return bounds + " [" + unit + "]: " + why;
}

}  // namespace musclesim
