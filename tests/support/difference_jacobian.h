// df/dy of a network's right-hand side by central differences: the independent check of
// every analytic Jacobian entry.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "musclesim/dynamics/network.h"

namespace musclesim::testing {

// Entry (i, j) of a dense n x n matrix stored row by row.
inline std::size_t Dense(int n, int i, int j) { return static_cast<std::size_t>(i * n + j); }

// df/dy at (t, y) by central differences of RightHandSide with `step`, column by column.
inline std::vector<double> DifferenceJacobian(const NetworkSystem& system, double t,
                                              const std::vector<double>& y, double step) {
  const int n = system.state_size();
  std::vector<double> jacobian(Dense(n, n, 0));
  std::vector<double> plus(y), minus(y), f_plus(y.size()), f_minus(y.size());
  for (int j = 0; j < n; ++j) {
    plus[j] = y[j] + step;
    minus[j] = y[j] - step;
    system.RightHandSide(t, plus.data(), f_plus.data());
    system.RightHandSide(t, minus.data(), f_minus.data());
    for (int i = 0; i < n; ++i) {
      // divided by the steps as rounded, not 2 step
      jacobian[Dense(n, i, j)] = (f_plus[i] - f_minus[i]) / (plus[j] - minus[j]);
    }
    plus[j] = minus[j] = y[j];
  }
  return jacobian;
}

// Which entries of the dense n x n Jacobian `system`'s pattern holds.
inline std::vector<bool> PatternMask(const NetworkSystem& system) {
  const JacobianPattern& pattern = system.jacobian_pattern();
  const int n = system.state_size();
  std::vector<bool> in_pattern(Dense(n, n, 0), false);
  for (int k = 0; k < pattern.entries(); ++k) {
    in_pattern[Dense(n, pattern.rows[k], pattern.ColumnOf(k))] = true;
  }
  return in_pattern;
}

// Whether (t, y) is more than `margin` (in the kink's unit) from every kink: a difference
// straddling a kink measures neither side's slope.
inline bool AwayFromKinks(const NetworkSystem& system, double t, const std::vector<double>& y,
                          double margin) {
  for (const NetworkSystem::Kink& kink : system.kinks()) {
    if (std::abs(system.KinkValue(kink, t, y.data())) < margin) return false;
  }
  return true;
}

// The analytic Jacobian at (t, y) against central differences with `step`: every entry of the
// pattern, and exactly zero differences outside it.
inline void ExpectJacobianMatchesDifferences(const NetworkSystem& system, double t,
                                             const std::vector<double>& y, double step) {
  const JacobianPattern& pattern = system.jacobian_pattern();
  const int n = system.state_size();
  std::vector<double> values(static_cast<std::size_t>(pattern.entries()));
  system.Jacobian(t, y.data(), values.data());
  const std::vector<double> fd = DifferenceJacobian(system, t, y, step);
  for (int k = 0; k < pattern.entries(); ++k) {
    const int i = pattern.rows[k], j = pattern.ColumnOf(k);
    const double reference = fd[Dense(n, i, j)];
    // rounding costs 1e-16 |f| / h with |f| up to ~1e3 (m/s^2, and 1/s for an activation
    // rate): 1e-6 absolute at h = 1e-7, doubled. Truncation, h^2 times the third derivative
    // over 6: the curves bend over 1e-2 m and over eps = 1e-3 m/s ((1e-7 / 1e-3)^2), an
    // activation rate over 0.5 in u: below 1e-8 relative, so 1e-7 is margin
    EXPECT_NEAR(values[k], reference, 2e-6 + 1e-7 * std::abs(reference))
        << "entry (" << i << ", " << j << ") at t = " << t;
  }
  const std::vector<bool> in_pattern = PatternMask(system);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (in_pattern[Dense(n, i, j)]) continue;
      // f_i does not depend on y_j: both evaluations do the same operations on the same
      // numbers, so the difference is exactly zero
      EXPECT_EQ(fd[Dense(n, i, j)], 0.0) << "entry (" << i << ", " << j << ") outside the pattern";
    }
  }
}

}  // namespace musclesim::testing
