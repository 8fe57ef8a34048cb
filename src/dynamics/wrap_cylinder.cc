#include "dynamics/wrap_cylinder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace musclesim {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// An angle in [0, 2 pi).
double Positive(double angle) {
  angle = std::fmod(angle, kTwoPi);
  return angle < 0.0 ? angle + kTwoPi : angle;
}

// The side's axis (0: x, 1: y) and sign; sign 0 on all sides.
void SideOf(WrapSide side, int& axis, double& sign) {
  axis = 0;
  sign = 0.0;
  switch (side) {
    case WrapSide::kAll: break;
    case WrapSide::kPlusX: sign = 1.0; break;
    case WrapSide::kMinusX: sign = -1.0; break;
    case WrapSide::kPlusY: axis = 1, sign = 1.0; break;
    case WrapSide::kMinusY: axis = 1, sign = -1.0; break;
  }
}

}  // namespace

double DistanceFromAxis(const Point& p, const PlacedCylinder& cylinder) {
  const Point r = p - cylinder.center;
  return (r - r.dot(cylinder.z) * cylinder.z).norm();
}

CylinderWrap WrapOverCylinder(const Point& p, const Point& s, const PlacedCylinder& c) {
  CylinderWrap wrap;
  const Point y = c.z.cross(c.x);
  const Point rp = p - c.center, rs = s - c.center;
  // in the cylinder's frame: the plane across the axis, and the height along it
  const Eigen::Vector2d p2(rp.dot(c.x), rp.dot(y)), s2(rs.dot(c.x), rs.dot(y));
  const double zp = rp.dot(c.z), zs = rs.dot(c.z);
  const double R = c.radius, dp = p2.norm(), ds = s2.norm();
  if (!(dp > R && ds > R)) {
    wrap.inside = true;
    return wrap;
  }
  // the straight segment's closest approach to the axis, in the plane
  const Eigen::Vector2d d = s2 - p2;
  const double dd = d.squaredNorm();
  const double t = dd > 0.0 ? std::clamp(-p2.dot(d) / dd, 0.0, 1.0) : 0.0;
  const Eigen::Vector2d closest = p2 + t * d;
  const bool through = closest.norm() < R;
  int axis = 0;
  double sign = 0.0;
  SideOf(c.side, axis, sign);
  const double ap = std::acos(R / dp), as = std::acos(R / ds);
  const double thp = std::atan2(p2.y(), p2.x()), ths = std::atan2(s2.y(), s2.x());
  // counterclockwise about z: leaving p at thp + ap, reaching s at ths - as; clockwise the
  // other way round
  const double ccw = Positive((ths - as) - (thp + ap));
  const double cw = Positive((thp - ap) - (ths + as));
  bool counterclockwise = true;
  if (sign == 0.0) {
    if (!through) return wrap;
    const double cross = p2.x() * s2.y() - p2.y() * s2.x();
    counterclockwise = cross >= 0.0;
  } else {
    // over the active half: the shorter arc whose middle lies in it
    const auto active = [&](double a) {
      return (axis == 0 ? std::cos(a) : std::sin(a)) * sign > 0.0;
    };
    const bool ccw_active = active(thp + ap + 0.5 * ccw), cw_active = active(thp - ap - 0.5 * cw);
    counterclockwise = ccw_active != cw_active ? ccw_active : ccw <= cw;
    // a segment that passes the active side without touching stays straight
    if (!through && closest[axis] * sign > 0.0) return wrap;
  }
  const double a1 = counterclockwise ? thp + ap : thp - ap;
  const double a2 = counterclockwise ? ths - as : ths + as;
  const double angle = counterclockwise ? ccw : cw;
  if (!(angle > 1e-12)) return wrap;  // touching: the straight segment is the path
  // a segment crossing the cylinder wraps less than half of it: an angle past pi is a
  // rounding of a slightly negative one, at the touch
  if (sign == 0.0 && angle > std::numbers::pi) return wrap;
  // unrolled, the path is one straight line: the height rises in proportion to its length
  const double la = std::sqrt(dp * dp - R * R), lb = std::sqrt(ds * ds - R * R);
  const double arc = R * angle, planar = la + arc + lb;
  const double z1 = zp + (zs - zp) * la / planar, z2 = zp + (zs - zp) * (la + arc) / planar;
  const auto at = [&](double a, double z) {
    return Point(c.center + R * std::cos(a) * c.x + R * std::sin(a) * y + z * c.z);
  };
  wrap.wraps = true;
  wrap.t1 = at(a1, z1);
  wrap.t2 = at(a2, z2);
  wrap.arc = std::hypot(arc, z2 - z1);
  return wrap;
}

}  // namespace musclesim
