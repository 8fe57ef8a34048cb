// The minimum of a function of one variable on an interval, by Brent's method (golden
// sections with parabolic steps; Brent 1973, "Algorithms for minimization without
// derivatives", ch. 5): a local minimum, found in a few evaluations when the function is
// smooth near it, and never outside [low, high].
#pragma once

#include <cmath>
#include <limits>
#include <utility>

namespace musclesim {

// Returns {x, f(x)} for the least f found on [low, high], x to within `tolerance` (> 0, in x's
// unit) plus rounding. `f` is called about 10-40 times.
template <typename F>
std::pair<double, double> BrentMinimum(F f, double low, double high, double tolerance) {
  const double golden = 0.5 * (3.0 - std::sqrt(5.0));
  double a = low, b = high;
  double x = a + golden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;  // the last step and the one before it
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double middle = 0.5 * (a + b);
    const double tol1 = tolerance + 3.0 * std::numeric_limits<double>::epsilon() * std::abs(x);
    const double tol2 = 2.0 * tol1;
    if (std::abs(x - middle) <= tol2 - 0.5 * (b - a)) break;
    bool golden_step = true;
    if (std::abs(e) > tol1) {
      // a parabola through x, w, v
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double previous = e;
      e = d;
      // accepted when inside (a, b) and less than half the step before last
      if (std::abs(p) < std::abs(0.5 * q * previous) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < middle ? tol1 : -tol1;
        golden_step = false;
      }
    }
    if (golden_step) {
      e = (x < middle ? b : a) - x;
      d = golden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + (d > 0 ? tol1 : -tol1);
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return {x, fx};
}

}  // namespace musclesim
