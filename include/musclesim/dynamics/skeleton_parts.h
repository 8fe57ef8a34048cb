// The parts of a skeleton (docs/model.md 15): rigid bodies and the joints that join each to
// its parent (the ground is the root). Plain data, validated by Validate; Skeleton
// (skeleton.h) builds them into a rigid-body model.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/core/coordinates.h"

namespace musclesim {

// The name that stands for the ground (the world frame) as a joint's parent or a point's body.
inline constexpr std::string_view kGroundBody = "ground";

// A rigid body: its mass, centre of mass and inertia about the centre of mass, in its own
// frame (which its joint places, `Joint::in_child`).
struct Body {
  std::string name;
  double mass = 1.0;             // [kg], > 0
  Coordinates center_of_mass{};  // [m], in the body's frame
  // Ixx, Iyy, Izz, Ixy, Ixz, Iyz about the centre of mass, along the body's axes [kg m^2]:
  // positive definite, and each principal moment at most the sum of the other two
  std::array<double, 6> inertia{};
};

// A frame fixed in a body: its origin and its orientation (a unit quaternion w, x, y, z).
struct Frame {
  Coordinates position{};                                 // [m]
  std::array<double, 4> orientation{1.0, 0.0, 0.0, 0.0};  // [-], unit
};

// revolute: rotation about `axis`; prismatic: translation along `axis`; planar: translation
// along the joint frame's x and y, then rotation about its z (three coordinates, in that
// order); weld: none, the child fixed in the parent.
enum class JointKind { kRevolute, kPrismatic, kPlanar, kWeld };
std::string_view ToString(JointKind kind);
JointKind ParseJointKind(std::string_view text);  // ParameterError("type")
// How many coordinates a joint of `kind` has.
int CoordinateCount(JointKind kind);

// One of a joint's coordinates: its value and speed at the start, and its damping, a
// generalized force -damping * speed (docs/model.md 15.4).
struct JointCoordinate {
  std::string name;      // unique among every joint's coordinates
  double value = 0.0;    // [rad] or [m]
  double speed = 0.0;    // [rad/s] or [m/s]
  double damping = 0.0;  // [N m s/rad] or [N s/m], >= 0
};

// A joint: `child` moves relative to `parent` (a body, or the ground). The joint frame is
// `in_parent` in the parent's frame and `in_child` in the child's; the joint moves the one
// relative to the other.
struct Joint {
  std::string name;
  JointKind kind = JointKind::kRevolute;
  std::string parent{kGroundBody};
  std::string child;
  Frame in_parent, in_child;
  Coordinates axis{0.0, 0.0, 1.0};           // revolute, prismatic: in the joint frame; not zero
  std::vector<JointCoordinate> coordinates;  // CoordinateCount(kind) of them

  // A joint of `kind` whose coordinates are named `name` (one), or `name.x`, `name.y` and
  // `name.rotation` (planar), at value 0.
  static Joint Make(std::string name, JointKind kind, std::string parent, std::string child,
                    Frame in_parent = {}, Frame in_child = {});
};

// The half of a wrap cylinder a path may wrap over (OpenSim's quadrant), in the cylinder's
// frame (z its axis, x and y those of the body's frame turned so): all of it, or the half
// where x (y) is positive or negative.
enum class WrapSide { kAll, kPlusX, kMinusX, kPlusY, kMinusY };
std::string_view ToString(WrapSide side);
WrapSide ParseWrapSide(std::string_view text);  // ParameterError("side")

// A cylinder fixed in a body (or the ground), which the paths that name it wrap over when
// their straight segment would pass through it (docs/model.md 15.3): the shortest path over
// it, two tangent lines and a helical arc.
struct WrapCylinder {
  std::string name;
  std::string body{kGroundBody};
  Coordinates center{};             // [m], in the body's frame
  Coordinates axis{0.0, 0.0, 1.0};  // in the body's frame; not zero
  double radius = 0.0;              // [m], > 0
  WrapSide side = WrapSide::kAll;
};

// Throw ParameterError with paths as a file's keys ("mass", "inertia", "in_parent.orientation").
void Validate(const Body& body);
void Validate(const Joint& joint);
void Validate(const WrapCylinder& wrap);

}  // namespace musclesim
