// Private: the shortest path from a point over a cylinder to another (docs/model.md 15.3),
// the geometry of a wrap surface: the straight lines from each point to its tangent point on
// the cylinder and the helical arc between them, which unroll into one straight line.
#pragma once

#include "dynamics/element_path.h"
#include "musclesim/dynamics/skeleton_parts.h"

namespace musclesim {

// The cylinder at one instant, in the world's frame: its centre, its unit axis `z`, and `x`,
// a unit vector across it that turns with its body (the side's x; y = z x x).
struct PlacedCylinder {
  Point center, x, z;
  double radius = 0.0;
  WrapSide side = WrapSide::kAll;
};

struct CylinderWrap {
  bool wraps = false;   // false: the straight segment from p to s stays off the cylinder
  bool inside = false;  // p or s is inside the cylinder: the path has no tangent there
  Point t1, t2;         // the tangent points, after p and before s [m]
  double arc = 0.0;     // the length on the surface from t1 to t2 [m]
};

// Whether and how the path from p to s wraps over `cylinder`. On `all` sides it wraps when
// the straight segment would pass through the cylinder, around the side it passes; on one
// side (+x, ...), it always goes over that half (the shorter way whose middle lies there),
// unless its straight segment passes that side without touching: a pulley's cable, whose
// length jumps where that segment's closest point to the axis crosses from one half to the
// other off the cylinder (the cable falling off the pulley). A point inside the cylinder (its
// distance from the axis at most the radius) has no tangent: `inside`, and no wrap.
CylinderWrap WrapOverCylinder(const Point& p, const Point& s, const PlacedCylinder& cylinder);

// The distance of p from the cylinder's axis [m].
double DistanceFromAxis(const Point& p, const PlacedCylinder& cylinder);

}  // namespace musclesim
