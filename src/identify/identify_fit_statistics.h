// What every identification reports of a least-squares fit: standard errors from the
// residual Jacobian, and the RMSE.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <cstddef>
#include <limits>

namespace musclesim::identify_detail {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// sigma^2 (J^T J)^-1 from residual Jacobian J and residual sum of squares; NaN when the
// data leave no degree of freedom. A pseudo-inverse keeps a degenerate fit finite.
inline Eigen::MatrixXd Covariance(const Eigen::MatrixXd& jacobian, double rss) {
  const Eigen::Index n = jacobian.rows(), p = jacobian.cols();
  if (n <= p) return Eigen::MatrixXd::Constant(p, p, kNaN);
  const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  return rss / static_cast<double>(n - p) *
         normal.completeOrthogonalDecomposition().pseudoInverse();
}

inline double Rmse(double rss, std::size_t n) { return std::sqrt(rss / static_cast<double>(n)); }

}  // namespace musclesim::identify_detail
