// Where a function of time changes sign within one integrator step, found on the step's
// interpolant: the Illinois variant of the secant method, as CVODE's own root finder uses,
// with a bisection every third iteration so that a badly scaled function still converges.
#pragma once

#include <cmath>

namespace musclesim {

// `g` changes sign over (t_lo, t_hi]: g_lo = g(t_lo) is non-zero and g_hi = g(t_hi) is zero
// or of the other sign. Returns the right end of a bracket no wider than `tolerance`, on the
// far side of the crossing (so a restart there sees the new sign, or zero).
template <class Function>
double LocateCrossing(Function&& g, double t_lo, double g_lo, double t_hi, double g_hi,
                      double tolerance) {
  int kept = 0;  // which end stayed in the last iteration: -1 low, +1 high
  for (int iteration = 1; g_hi != 0.0 && t_hi - t_lo > tolerance; ++iteration) {
    double t =
        iteration % 3 == 0 ? 0.5 * (t_lo + t_hi) : t_hi - g_hi * (t_hi - t_lo) / (g_hi - g_lo);
    // at least half a tolerance inside, so every iteration shrinks the bracket
    const double margin = 0.5 * tolerance;
    t = std::fmin(std::fmax(t, t_lo + margin), t_hi - margin);
    const double value = g(t);
    if (value == 0.0) return t;
    if ((value < 0.0) == (g_lo < 0.0)) {
      t_lo = t;
      g_lo = value;
      if (kept == 1) g_hi *= 0.5;  // Illinois: the high end stayed twice
      kept = 1;
    } else {
      t_hi = t;
      g_hi = value;
      if (kept == -1) g_lo *= 0.5;
      kept = -1;
    }
  }
  return t_hi;
}

}  // namespace musclesim
