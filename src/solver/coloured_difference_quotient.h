// Private: a difference-quotient Jacobian on a sparse structure (Curtis, Powell and Reid
// 1974). Columns that share no row are perturbed together, so a chain costs a handful of
// right-hand sides per Jacobian whatever the order of its nodes, where CVODE's band quotient
// costs one per column of the band (as many as there are states when the nodes are listed
// out of order). It is what `jacobian: difference_quotient` means with the sparse solver.
#pragma once

#include <vector>

#include "musclesim/dynamics/jacobian_pattern.h"

namespace musclesim {

class ColouredDifferenceQuotient {
 public:
  explicit ColouredDifferenceQuotient(const JacobianPattern& pattern);

  // The Jacobian's values in pattern order: `rhs(y, rate)` evaluates the right-hand side,
  // `rate_at_y` is its value at y, `weights` CVODE's error weights (1 / (rtol |y| + atol)),
  // `step` the integrator's current step h [s]. `y` is perturbed in place and restored;
  // `perturbed_rate` is room for n values.
  template <typename Rhs>
  void Evaluate(Rhs rhs, double* y, const double* rate_at_y, const double* weights, double step,
                double* perturbed_rate, double* values) const;

  int groups() const { return static_cast<int>(group_columns_.size()); }
  const std::vector<int>& columns(int group) const { return group_columns_[group]; }

 private:
  // The smallest increment CVODE's own quotients take, relative to 1 / weight: 1000 |h|
  // uround n ||f||_wrms, or 1 where f is 0 (cvLsDenseDQJac).
  double MinimumIncrement(const double* rate_at_y, const double* weights, double step) const;
  static double Increment(double y, double weight, double minimum);

  const JacobianPattern& pattern_;
  std::vector<std::vector<int>> group_columns_;  // the columns perturbed together
};

template <typename Rhs>
void ColouredDifferenceQuotient::Evaluate(Rhs rhs, double* y, const double* rate_at_y,
                                          const double* weights, double step,
                                          double* perturbed_rate, double* values) const {
  std::vector<double> increments(static_cast<std::size_t>(pattern_.size));
  const double minimum = MinimumIncrement(rate_at_y, weights, step);
  for (const std::vector<int>& columns : group_columns_) {
    for (int j : columns) {
      increments[j] = Increment(y[j], weights[j], minimum);
      y[j] += increments[j];
    }
    rhs(y, perturbed_rate);
    for (int j : columns) {
      y[j] -= increments[j];
      for (int k = pattern_.column_starts[j]; k < pattern_.column_starts[j + 1]; ++k) {
        const int row = pattern_.rows[k];
        values[k] = (perturbed_rate[row] - rate_at_y[row]) / increments[j];
      }
    }
  }
}

}  // namespace musclesim
