// Skeleton (skeleton.h): its parts validated and put in tree order; the rigid-body model is
// the backend's (skeleton_backend.h).
#include "musclesim/dynamics/skeleton.h"

#include <atomic>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include "dynamics/skeleton_backend.h"
#include "musclesim/core/errors.h"
#include "part_paths.h"

namespace musclesim {

SkeletonUnavailable::SkeletonUnavailable()
    : std::runtime_error(
          "this build of musclesim has no skeleton component: bodies and joints need Pinocchio "
          "(scripts/install-deps.sh installs it; CMake then builds musclesim_skeleton)") {}

Skeleton::Skeleton(std::vector<Body> bodies, std::vector<Joint> given, Coordinates gravity,
                   std::vector<WrapCylinder> wraps)
    : bodies_(std::move(bodies)),
      joints_(std::move(given)),
      wraps_(std::move(wraps)),
      gravity_(gravity) {
  const std::vector<Joint>& joints = joints_;
  for (std::size_t c = 0; c < 3; ++c) {
    Require(std::isfinite(gravity[c]), "gravity[" + std::to_string(c) + "]", gravity[c],
            "must be finite [m/s^2]");
  }
  std::unordered_map<std::string, std::size_t> body_index;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    ValidateEntry(bodies_[b], "bodies", b);
    if (!body_index.emplace(bodies_[b].name, b).second) {
      throw ParameterError(Entry("bodies", b, "name"), bodies_[b].name,
                           "must be unique among the bodies");
    }
  }
  // each body the child of exactly one joint, every parent known
  std::vector<int> joint_of(bodies_.size(), -1);
  std::unordered_map<std::string, std::size_t> joint_names, coordinate_names;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& joint = joints[j];
    ValidateEntry(joint, "joints", j);
    if (!joint_names.emplace(joint.name, j).second) {
      throw ParameterError(Entry("joints", j, "name"), joint.name,
                           "must be unique among the joints");
    }
    for (std::size_t k = 0; k < joint.coordinates.size(); ++k) {
      if (!coordinate_names.emplace(joint.coordinates[k].name, j).second) {
        throw ParameterError(Entry("joints", j, "coordinates") + "[" + std::to_string(k) + "].name",
                             joint.coordinates[k].name,
                             "must be unique among every joint's coordinates");
      }
    }
    const auto child = body_index.find(joint.child);
    if (child == body_index.end()) {
      throw ParameterError(Entry("joints", j, "child"), joint.child,
                           "names no body; the bodies are: " + KnownNames(bodies_));
    }
    if (joint.parent != kGroundBody && !body_index.count(joint.parent)) {
      throw ParameterError(
          Entry("joints", j, "parent"), joint.parent,
          "names no body (nor the ground); the bodies are: " + KnownNames(bodies_));
    }
    int& slot = joint_of[child->second];
    if (slot >= 0) {
      throw ParameterError(Entry("joints", j, "child"), joint.child,
                           "is already the child of joint " + joints[slot].name +
                               ": a body has one joint to its parent");
    }
    slot = static_cast<int>(j);
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (joint_of[b] < 0) {
      throw ParameterError(Entry("bodies", b, "name"), bodies_[b].name,
                           "is the child of no joint: join it to its parent or to the ground "
                           "(a weld fixes it)");
    }
  }
  // tree order: a joint once its parent is placed, in the given order otherwise; a joint
  // never placed has its own descendant as an ancestor
  std::vector<bool> placed_body(bodies_.size(), false), placed_joint(joints.size(), false);
  std::vector<Joint> tree;  // the joints in tree order
  while (tree.size() < joints.size()) {
    bool progress = false;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      if (placed_joint[j]) continue;
      const Joint& joint = joints[j];
      if (joint.parent != kGroundBody && !placed_body[body_index.at(joint.parent)]) continue;
      placed_joint[j] = true;
      placed_body[body_index.at(joint.child)] = true;
      tree.push_back(joint);
      progress = true;
    }
    if (progress) continue;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      if (placed_joint[j]) continue;
      throw ParameterError(Entry("joints", j, "parent"), joints[j].parent,
                           "is a descendant of the joint's own child " + joints[j].child +
                               ": the bodies must form a tree rooted at the ground");
    }
  }
  for (const Joint& joint : tree) {
    for (std::size_t k = 0; k < joint.coordinates.size(); ++k) {
      coordinates_.push_back(joint.coordinates[k]);
      rotational_.push_back(joint.kind == JointKind::kRevolute ||
                            (joint.kind == JointKind::kPlanar && k == 2));
    }
  }
  // the coordinates that move each body: its joint's, and its parent's
  moves_.assign(bodies_.size(), std::vector<bool>(coordinates_.size(), false));
  std::size_t first = 0;
  std::vector<std::size_t> first_coordinate;
  for (const Joint& joint : tree) {
    first_coordinate.push_back(first);
    first += joint.coordinates.size();
  }
  for (std::size_t j = 0; j < tree.size(); ++j) {  // parents come first
    const Joint& joint = tree[j];
    std::vector<bool>& moves = moves_[body_index.at(joint.child)];
    if (joint.parent != kGroundBody) moves = moves_[body_index.at(joint.parent)];
    for (std::size_t k = 0; k < joint.coordinates.size(); ++k)
      moves[first_coordinate[j] + k] = true;
  }
  for (std::size_t w = 0; w < wraps_.size(); ++w) {
    ValidateEntry(wraps_[w], "wraps", w);
    for (std::size_t v = 0; v < w; ++v) {
      if (wraps_[v].name == wraps_[w].name) {
        throw ParameterError(Entry("wraps", w, "name"), wraps_[w].name,
                             "must be unique among the wrap surfaces");
      }
    }
    const int body = FindBody(wraps_[w].body);
    if (body < -1) {
      throw ParameterError(
          Entry("wraps", w, "body"), wraps_[w].body,
          "names no body (nor the ground); the bodies are: " + KnownNames(bodies_));
    }
    wrap_bodies_.push_back(body);
  }
  static std::atomic<std::uint64_t> built{0};
  id_ = ++built;
  model_ = BuildSkeletonModel(bodies_, tree, gravity);
}

int Skeleton::FindCoordinate(std::string_view name) const {
  for (std::size_t k = 0; k < coordinates_.size(); ++k) {
    if (coordinates_[k].name == name) return static_cast<int>(k);
  }
  return -1;
}

int Skeleton::FindWrap(std::string_view name) const {
  for (std::size_t w = 0; w < wraps_.size(); ++w) {
    if (wraps_[w].name == name) return static_cast<int>(w);
  }
  return -1;
}

int Skeleton::FindBody(std::string_view name) const {
  if (name == kGroundBody) return -1;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].name == name) return static_cast<int>(b);
  }
  return -2;
}

void Skeleton::InitialState(double* q, double* u) const {
  for (std::size_t k = 0; k < coordinates_.size(); ++k) {
    q[k] = coordinates_[k].value;
    u[k] = coordinates_[k].speed;
  }
}

}  // namespace musclesim
