// Private: the rigid-body library's side of a Skeleton (src/skeleton/pinocchio_skeleton.cc,
// or src/skeleton/skeleton_unavailable.cc in a build without it).
#pragma once

#include <memory>
#include <vector>

#include "musclesim/dynamics/skeleton.h"

namespace musclesim {

// The library's model of validated parts: `joints` in an order where every parent comes
// before its children.
std::unique_ptr<Skeleton::Model, Skeleton::ModelDeleter> BuildSkeletonModel(
    const std::vector<Body>& bodies, const std::vector<Joint>& joints, const Coordinates& gravity);

}  // namespace musclesim
