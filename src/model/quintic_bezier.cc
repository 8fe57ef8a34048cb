#include "musclesim/model/quintic_bezier.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace musclesim {

namespace {

// The quintic in Bernstein form with control values p, and its derivative in u.
double Bernstein(const std::array<double, 6>& p, double u) {
  const double t = 1.0 - u;
  const double u2 = u * u, t2 = t * t;
  return t2 * t2 * t * p[0] + 5.0 * u * t2 * t2 * p[1] + 10.0 * u2 * t2 * t * p[2] +
         10.0 * u2 * u * t2 * p[3] + 5.0 * u2 * u2 * t * p[4] + u2 * u2 * u * p[5];
}

double BernsteinSlope(const std::array<double, 6>& p, double u) {
  const double t = 1.0 - u;
  const double u2 = u * u, t2 = t * t;
  return 5.0 * (t2 * t2 * (p[1] - p[0]) + 4.0 * u * t2 * t * (p[2] - p[1]) +
                6.0 * u2 * t2 * (p[3] - p[2]) + 4.0 * u2 * u * t * (p[4] - p[3]) +
                u2 * u2 * (p[5] - p[4]));
}

// u in [0, 1] with x(u) = x, x(u) increasing: Newton's steps kept inside a bracket that
// bisection shrinks when a step would leave it.
double SolveU(const BezierCorner& c, double x) {
  double low = 0.0, high = 1.0;
  double u = (x - c.x[0]) / (c.x[5] - c.x[0]);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double residual = Bernstein(c.x, u) - x;
    if (residual == 0.0) return u;
    (residual < 0.0 ? low : high) = u;
    const double slope = BernsteinSlope(c.x, u);
    double next = slope > 0.0 ? u - residual / slope : 0.5 * (low + high);
    if (!(next > low && next < high)) next = 0.5 * (low + high);
    if (std::abs(next - u) <= 4.0 * std::numeric_limits<double>::epsilon()) return next;
    u = next;
  }
  return u;
}

}  // namespace

BezierCorner MakeBezierCorner(double x0, double y0, double dydx0, double x1, double y1,
                              double dydx1, double curviness) {
  // where the tangent lines cross (halfway when they are parallel, as OpenSim does)
  const double x_cross = std::abs(dydx0 - dydx1) > std::sqrt(std::numeric_limits<double>::epsilon())
                             ? (y1 - y0 - x1 * dydx1 + x0 * dydx0) / (dydx0 - dydx1)
                             : 0.5 * (x0 + x1);
  const double y_cross = (x_cross - x1) * dydx1 + y1;
  const double to_first = std::pow(x_cross - x0, 2) + std::pow(y_cross - y0, 2);
  const double to_last = std::pow(x_cross - x1, 2) + std::pow(y_cross - y1, 2);
  const double apart = std::pow(x1 - x0, 2) + std::pow(y1 - y0, 2);
  if (!(apart > to_first && apart > to_last)) {
    throw std::invalid_argument("the slopes at the two points make an S, not a corner");
  }
  const double x0_mid = x0 + curviness * (x_cross - x0), y0_mid = y0 + curviness * (y_cross - y0);
  const double x1_mid = x1 + curviness * (x_cross - x1), y1_mid = y1 + curviness * (y_cross - y1);
  // x(u) must rise for the curve to be a function of x: the crossing between the two points
  if (!(x0 < x0_mid && x0_mid <= x1_mid && x1_mid < x1)) {
    throw std::invalid_argument("the slopes' lines cross outside the two points, no corner");
  }
  return {{x0, x0_mid, x0_mid, x1_mid, x1_mid, x1}, {y0, y0_mid, y0_mid, y1_mid, y1_mid, y1}};
}

SegmentedBezierCurve::SegmentedBezierCurve(std::vector<BezierCorner> corners, double slope_before,
                                           double slope_after)
    : corners_(std::move(corners)), slope_before_(slope_before), slope_after_(slope_after) {
  if (corners_.empty()) throw std::invalid_argument("a segmented curve needs a corner");
}

CurvePoint SegmentedBezierCurve::Evaluate(double x) const {
  if (x <= first_x()) {
    return {corners_.front().y[0] + slope_before_ * (x - first_x()), slope_before_};
  }
  if (x >= last_x()) return {corners_.back().y[5] + slope_after_ * (x - last_x()), slope_after_};
  std::size_t i = 0;
  while (x > corners_[i].x[5]) ++i;
  const BezierCorner& c = corners_[i];
  const double u = SolveU(c, x);
  return {Bernstein(c.y, u), BernsteinSlope(c.y, u) / BernsteinSlope(c.x, u)};
}

}  // namespace musclesim
