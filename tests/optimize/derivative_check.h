// The shooting program's gradient and constraint Jacobian against central differences of its
// own objective and constraints, variable by variable: exact derivatives match to the
// differences' truncation and the integration's tolerance.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "musclesim/optimize/multiple_shooting.h"

namespace musclesim {

// `steps[c]`: variable c's difference step; `tolerance` relative to max(1, |difference|).
inline void ExpectExactDerivatives(MultipleShooting& shooting, const std::vector<double>& x,
                                   const std::vector<double>& steps, double tolerance) {
  const int n = shooting.variable_count(), m = shooting.constraint_count();
  std::vector<double> gradient(static_cast<std::size_t>(n));
  ASSERT_TRUE(shooting.ObjectiveGradient(x.data(), gradient.data()));
  std::vector<double> values(static_cast<std::size_t>(shooting.jacobian_nonzeros()));
  ASSERT_TRUE(shooting.ConstraintJacobian(x.data(), values.data()));
  std::vector<int> rows(values.size()), columns(values.size());
  shooting.JacobianStructure(rows.data(), columns.data());
  std::vector<double> jacobian(static_cast<std::size_t>(n) * static_cast<std::size_t>(m), 0.0);
  for (std::size_t k = 0; k < values.size(); ++k) {
    jacobian[static_cast<std::size_t>(rows[k]) * static_cast<std::size_t>(n) +
             static_cast<std::size_t>(columns[k])] += values[k];
  }
  for (int c = 0; c < n; ++c) {
    const double h = steps[static_cast<std::size_t>(c)];
    std::vector<double> plus = x, minus = x;
    plus[static_cast<std::size_t>(c)] += h;
    minus[static_cast<std::size_t>(c)] -= h;
    double above = 0.0, below = 0.0;
    ASSERT_TRUE(shooting.Objective(plus.data(), above));
    ASSERT_TRUE(shooting.Objective(minus.data(), below));
    const double objective = (above - below) / (2.0 * h);
    EXPECT_NEAR(gradient[static_cast<std::size_t>(c)], objective,
                tolerance * std::max(1.0, std::abs(objective)))
        << "objective, variable " << c;
    std::vector<double> g_plus(static_cast<std::size_t>(m)), g_minus(static_cast<std::size_t>(m));
    ASSERT_TRUE(shooting.Constraints(plus.data(), g_plus.data()));
    ASSERT_TRUE(shooting.Constraints(minus.data(), g_minus.data()));
    for (int r = 0; r < m; ++r) {
      const double difference =
          (g_plus[static_cast<std::size_t>(r)] - g_minus[static_cast<std::size_t>(r)]) / (2.0 * h);
      const double exact = jacobian[static_cast<std::size_t>(r) * static_cast<std::size_t>(n) +
                                    static_cast<std::size_t>(c)];
      EXPECT_NEAR(exact, difference, tolerance * std::max(1.0, std::abs(difference)))
          << "row " << r << ", variable " << c;
    }
  }
}

}  // namespace musclesim
