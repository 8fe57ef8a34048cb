// Independent numerical references for the tests: central finite differences and adaptive
// Simpson quadrature. Nothing here calls the code under test.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace musclesim::testing {

// K(k), the complete elliptic integral of the first kind, by the arithmetic-geometric mean.
inline double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return 3.14159265358979323846 / (2.0 * a);
}

// Central difference with a step scaled to the point; error O(h^2).
inline double CentralDifference(const std::function<double(double)>& f, double x,
                                double relative_step = 1e-6) {
  const double h = relative_step * std::max(1.0, std::abs(x));
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

namespace detail {
inline double Simpson(const std::function<double(double)>& f, double a, double b, double fa,
                      double fm, double fb, double whole, double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::abs(delta) <= 15.0 * tolerance) return left + right + delta / 15.0;
  return Simpson(f, a, m, fa, flm, fm, left, 0.5 * tolerance, depth - 1) +
         Simpson(f, m, b, fm, frm, fb, right, 0.5 * tolerance, depth - 1);
}
}  // namespace detail

// Adaptive Simpson (with Richardson extrapolation) of f over [a, b], after splitting at
// `breaks` (kinks and jumps of f) and into `pieces` equal parts between them.
inline double Integrate(const std::function<double(double)>& f, double a, double b,
                        std::vector<double> breaks, double tolerance, int pieces = 64) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (!(hi > lo)) continue;
    for (int p = 0; p < pieces; ++p) {
      const double x0 = lo + (hi - lo) * p / pieces;
      const double x1 = (p + 1 == pieces) ? hi : lo + (hi - lo) * (p + 1) / pieces;
      // evaluate just inside the ends so a jump at a break takes the piece's own side
      const double e = 1e-15 * std::max(std::abs(x0), std::abs(x1));
      const double fa = f(x0 + e), fb = f(x1 - e), fm = f(0.5 * (x0 + x1));
      const double whole = (x1 - x0) / 6.0 * (fa + 4.0 * fm + fb);
      total += detail::Simpson(f, x0, x1, fa, fm, fb, whole, tolerance / pieces, 40);
    }
  }
  return total;
}

}  // namespace musclesim::testing
