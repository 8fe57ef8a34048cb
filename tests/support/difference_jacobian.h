// df/dy of a network's right-hand side by central differences: the independent check of
// every analytic Jacobian entry.
#pragma once

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

}  // namespace musclesim::testing
