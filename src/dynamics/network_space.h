// Private: an element's path at one instant in a network in the plane or in space
// (docs/model.md 12), shared by the right-hand side (network_space.cc) and the Jacobian
// (space_jacobian.cc).
#pragma once

#include <array>

#include "dynamics/element_path.h"
#include "musclesim/dynamics/network.h"

namespace musclesim {

struct NetworkSystem::PathState {
  std::array<Point, kMaxPathPoints> position;  // q_j [m]
  std::array<Point, kMaxPathPoints> velocity;  // qdot_j [m/s]
  std::array<int, kMaxPathPoints> state;       // a free node's state index, else -1
  PathGeometry geometry;
  double length_rate = 0.0;  // ldot [m/s]
};

}  // namespace musclesim
