#include "musclesim/dynamics/skeleton_parts.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "musclesim/core/enum_names.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

constexpr EnumName<JointKind> kJointKindNames[] = {
    {JointKind::kRevolute, "revolute"},
    {JointKind::kPrismatic, "prismatic"},
    {JointKind::kPlanar, "planar"},
    {JointKind::kWeld, "weld"},
};

std::string_view ToString(JointKind kind) { return ToString(kJointKindNames, kind); }

JointKind ParseJointKind(std::string_view text) { return Parse(kJointKindNames, "type", text); }

constexpr EnumName<WrapSide> kWrapSideNames[] = {
    {WrapSide::kAll, "all"},  {WrapSide::kPlusX, "+x"},  {WrapSide::kMinusX, "-x"},
    {WrapSide::kPlusY, "+y"}, {WrapSide::kMinusY, "-y"},
};

std::string_view ToString(WrapSide side) { return ToString(kWrapSideNames, side); }

WrapSide ParseWrapSide(std::string_view text) { return Parse(kWrapSideNames, "side", text); }

int CoordinateCount(JointKind kind) {
  switch (kind) {
    case JointKind::kRevolute:
    case JointKind::kPrismatic: return 1;
    case JointKind::kPlanar: return 3;
    case JointKind::kWeld: return 0;
  }
  return 0;
}

Joint Joint::Make(std::string name, JointKind kind, std::string parent, std::string child,
                  Frame in_parent, Frame in_child) {
  Joint joint;
  joint.kind = kind;
  joint.parent = std::move(parent);
  joint.child = std::move(child);
  joint.in_parent = in_parent;
  joint.in_child = in_child;
  if (kind == JointKind::kPlanar) {
    for (const char* c : {".x", ".y", ".rotation"}) joint.coordinates.push_back({name + c});
  } else if (kind != JointKind::kWeld) {
    joint.coordinates.push_back({name});
  }
  joint.name = std::move(name);
  Validate(joint);
  return joint;
}

namespace {

std::string Indexed(std::string key, std::size_t i) {
  key.append("[").append(std::to_string(i)).append("]");
  return key;
}

void RequireText(bool condition, const std::string& path, const std::string& value,
                 const std::string& rule) {
  if (!condition) throw ParameterError(path, value, rule);
}

std::string Describe(const double* values, std::size_t n) {
  std::string text = "[";
  for (std::size_t i = 0; i < n; ++i) text.append(i ? ", " : "").append(FormatNumber(values[i]));
  return text + "]";
}

void RequireFinite(const Coordinates& c, const std::string& key, const char* unit) {
  for (std::size_t i = 0; i < 3; ++i) {
    Require(std::isfinite(c[i]), Indexed(key, i), c[i], std::string("must be finite ") + unit);
  }
}

void Validate(const Frame& frame, const std::string& key) {
  RequireFinite(frame.position, key + ".position", "[m]");
  const auto& o = frame.orientation;
  const double norm = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
  // a quaternion read from a file with 15 digits is unit to about 1e-15; 1e-9 admits
  // rounding, not a mistake
  if (!(std::abs(norm - 1.0) <= 1e-9)) {
    throw ParameterError(
        key + ".orientation", Describe(o.data(), 4),
        "must be a unit quaternion [w, x, y, z] (its norm is " + FormatNumber(norm) + ")");
  }
}

}  // namespace

void Validate(const Body& body) {
  RequireText(!body.name.empty(), "name", "\"\"", "must not be empty");
  RequireText(body.name != kGroundBody, "name", body.name,
              "must not be \"ground\": the ground is every skeleton's root, a body of its own");
  Require(std::isfinite(body.mass) && body.mass > 0.0, "mass", body.mass,
          "must be finite and > 0 [kg]");
  RequireFinite(body.center_of_mass, "center_of_mass", "[m]");
  const auto& I = body.inertia;
  for (std::size_t i = 0; i < 6; ++i) {
    Require(std::isfinite(I[i]), Indexed("inertia", i), I[i], "must be finite [kg m^2]");
  }
  // positive definite (Sylvester's criterion) and the triangle inequality of a real body's
  // principal moments, which a positive definite matrix alone does not imply
  const double m1 = I[0], m2 = I[0] * I[1] - I[3] * I[3];
  const double m3 = I[0] * (I[1] * I[2] - I[5] * I[5]) - I[3] * (I[3] * I[2] - I[5] * I[4]) +
                    I[4] * (I[3] * I[5] - I[1] * I[4]);
  if (!(m1 > 0.0 && m2 > 0.0 && m3 > 0.0)) {
    throw ParameterError("inertia", Describe(I.data(), 6),
                         "must be positive definite ([Ixx, Iyy, Izz, Ixy, Ixz, Iyz] about the "
                         "centre of mass [kg m^2])");
  }
  // the principal moments, the eigenvalues of the symmetric matrix
  Eigen::Matrix3d matrix;
  matrix << I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2];
  const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(matrix).eigenvalues();
  const double slack = 1e-12 * (p[0] + p[1] + p[2]);
  if (!(p[0] <= p[1] + p[2] + slack && p[1] <= p[0] + p[2] + slack &&
        p[2] <= p[0] + p[1] + slack)) {
    throw ParameterError("inertia", Describe(I.data(), 6),
                         "each principal moment must be at most the sum of the other two (no "
                         "rigid body has these moments)");
  }
}

void Validate(const Joint& joint) {
  RequireText(!joint.name.empty(), "name", "\"\"", "must not be empty");
  RequireText(!joint.child.empty(), "child", "\"\"", "must name a body");
  RequireText(joint.child != kGroundBody, "child", joint.child,
              "must not be the ground: the ground is the root, no joint moves it");
  RequireText(!joint.parent.empty(), "parent", "\"\"", "must name a body or the ground");
  RequireText(joint.parent != joint.child, "parent", joint.parent, "must not be the joint's child");
  Validate(joint.in_parent, "in_parent");
  Validate(joint.in_child, "in_child");
  if (joint.kind == JointKind::kRevolute || joint.kind == JointKind::kPrismatic) {
    RequireFinite(joint.axis, "axis", "[-]");
    const double norm = std::sqrt(joint.axis[0] * joint.axis[0] + joint.axis[1] * joint.axis[1] +
                                  joint.axis[2] * joint.axis[2]);
    if (!(norm > 0.0)) {
      throw ParameterError("axis", Describe(joint.axis.data(), 3),
                           "must not be zero: the joint turns about it or slides along it");
    }
  }
  const std::size_t n = static_cast<std::size_t>(CoordinateCount(joint.kind));
  Require(joint.coordinates.size() == n, "coordinates",
          static_cast<double>(joint.coordinates.size()),
          "must hold " + std::to_string(n) + " coordinate(s) for a joint of type " +
              std::string(ToString(joint.kind)));
  for (std::size_t k = 0; k < n; ++k) {
    const JointCoordinate& c = joint.coordinates[k];
    const std::string at = Indexed("coordinates", k);
    RequireText(!c.name.empty(), at + ".name", "\"\"", "must not be empty");
    Require(std::isfinite(c.value), at + ".value", c.value, "must be finite [rad or m]");
    Require(std::isfinite(c.speed), at + ".speed", c.speed, "must be finite [rad/s or m/s]");
    Require(std::isfinite(c.damping) && c.damping >= 0.0, at + ".damping", c.damping,
            "must be finite and >= 0");
  }
}

void Validate(const WrapCylinder& wrap) {
  RequireText(!wrap.name.empty(), "name", "\"\"", "must not be empty");
  RequireText(!wrap.body.empty(), "body", "\"\"", "must name a body or the ground");
  RequireFinite(wrap.center, "center", "[m]");
  RequireFinite(wrap.axis, "axis", "[-]");
  const double norm = std::sqrt(wrap.axis[0] * wrap.axis[0] + wrap.axis[1] * wrap.axis[1] +
                                wrap.axis[2] * wrap.axis[2]);
  if (!(norm > 0.0)) {
    throw ParameterError("axis", Describe(wrap.axis.data(), 3),
                         "must not be zero: it is the cylinder's axis");
  }
  Require(std::isfinite(wrap.radius) && wrap.radius > 0.0, "radius", wrap.radius,
          "must be finite and > 0 [m]");
}

}  // namespace musclesim
