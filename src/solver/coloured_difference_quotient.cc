#include "coloured_difference_quotient.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace musclesim {

ColouredDifferenceQuotient::ColouredDifferenceQuotient(const JacobianPattern& pattern)
    : pattern_(pattern) {
  // greedy colouring in column order: a column takes the first group none of whose columns
  // has an entry in one of its rows (a chain, in any order, needs a few groups)
  const auto n = static_cast<std::size_t>(pattern.size);
  std::vector<std::vector<int>> row_columns(n);  // the columns with an entry in each row
  for (int j = 0; j < pattern.size; ++j) {
    for (int k = pattern.column_starts[j]; k < pattern.column_starts[j + 1]; ++k) {
      row_columns[static_cast<std::size_t>(pattern.rows[k])].push_back(j);
    }
  }
  std::vector<int> group_of(n, -1);
  std::vector<int> excluded_for(n + 1, -1);  // group g is excluded for column j: j
  for (int j = 0; j < pattern.size; ++j) {
    for (int k = pattern.column_starts[j]; k < pattern.column_starts[j + 1]; ++k) {
      for (int other : row_columns[static_cast<std::size_t>(pattern.rows[k])]) {
        const int group = group_of[static_cast<std::size_t>(other)];
        if (group >= 0) excluded_for[static_cast<std::size_t>(group)] = j;
      }
    }
    std::size_t group = 0;
    while (excluded_for[group] == j) ++group;
    if (group == group_columns_.size()) group_columns_.emplace_back();
    group_columns_[group].push_back(j);
    group_of[static_cast<std::size_t>(j)] = static_cast<int>(group);
  }
}

double ColouredDifferenceQuotient::MinimumIncrement(const double* rate_at_y, const double* weights,
                                                    double step) const {
  double sum = 0.0;
  for (int j = 0; j < pattern_.size; ++j) {
    const double scaled = rate_at_y[j] * weights[j];
    sum += scaled * scaled;
  }
  const double norm = pattern_.size > 0 ? std::sqrt(sum / pattern_.size) : 0.0;
  constexpr double kMultiple = 1000.0;  // CVODE's MIN_INC_MULT
  return norm != 0.0 ? kMultiple * std::abs(step) * std::numeric_limits<double>::epsilon() *
                           pattern_.size * norm
                     : 1.0;
}

double ColouredDifferenceQuotient::Increment(double y, double weight, double minimum) {
  // CVODE's own choice for its dense and band quotients: sqrt(unit roundoff) relative to the
  // value, and at least `minimum` relative to the size the error test considers negligible
  // (1 / weight), so that a state near 0 (a velocity at rest) is not stepped by a few ulps
  static const double root_roundoff = std::sqrt(std::numeric_limits<double>::epsilon());
  const double increment = std::max(root_roundoff * std::abs(y), minimum / weight);
  // y + increment - y exactly, so the quotient divides by the step actually taken
  return (y + increment) - y;
}

}  // namespace musclesim
