// A point or vector of space: x, y, z [m, or the vector's unit].
#pragma once

#include <array>

namespace musclesim {

using Coordinates = std::array<double, 3>;

}  // namespace musclesim
