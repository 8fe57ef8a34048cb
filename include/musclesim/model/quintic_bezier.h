// Curves made of quintic Bezier corners joined with continuous slopes, the form of Millard
// 2012's muscle curves (Millard et al. 2013, appendix; OpenSim's SmoothSegmentedFunction).
// A corner runs from (x0, y0) with slope dydx0 to (x1, y1) with slope dydx1; its six control
// points lie on the two tangent lines, the middle four pulled toward where the lines meet by
// the curviness c: x(u) and y(u) are quintics in u in [0, 1]. Before the first corner and
// after the last the curve goes on as the straight lines of its end slopes.
#pragma once

#include <array>
#include <vector>

#include "musclesim/model/curve_point.h"

namespace musclesim {

struct BezierCorner {
  std::array<double, 6> x{}, y{};  // the control points
};

// The corner between two points and their slopes. `curviness` is the control points' pull,
// in [0, 1] (OpenSim's scaled curviness, 0.1 + 0.8 c). Throws std::invalid_argument when the
// tangents do not make a corner (their crossing farther from either point than the points
// are from each other: an S, not a C; or not between them in x, where x(u) would not rise).
BezierCorner MakeBezierCorner(double x0, double y0, double dydx0, double x1, double y1,
                              double dydx1, double curviness);

class SegmentedBezierCurve {
 public:
  // `corners` in increasing x, each starting where the one before ends; `slope_before` and
  // `slope_after` continue the curve outside them (the first and last corners' end slopes).
  // Throws std::invalid_argument for no corner.
  SegmentedBezierCurve(std::vector<BezierCorner> corners, double slope_before, double slope_after);

  // The value and slope at x: inside a corner, u solved from x(u) = x to rounding.
  CurvePoint Evaluate(double x) const;

  double first_x() const { return corners_.front().x[0]; }
  double last_x() const { return corners_.back().x[5]; }

 private:
  std::vector<BezierCorner> corners_;
  double slope_before_, slope_after_;
};

}  // namespace musclesim
