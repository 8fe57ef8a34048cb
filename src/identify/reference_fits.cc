#include "musclesim/identify/reference_fits.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <stdexcept>

namespace musclesim {

NaturalCubicSpline::NaturalCubicSpline(const std::vector<DataPoint>& points) {
  if (points.size() < 2) throw std::invalid_argument("a spline needs at least 2 points");
  for (const DataPoint& p : points) {
    x_.push_back(p.x);
    y_.push_back(p.y);
  }
  const std::size_t n = points.size();
  second_.assign(n, 0.0);
  if (n < 3) return;
  // interior equations h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (slope diff)
  const auto m = static_cast<Eigen::Index>(n - 2);
  Eigen::SparseMatrix<double> system(m, m);
  Eigen::VectorXd rhs(m);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < m; ++i) {
    const std::size_t k = static_cast<std::size_t>(i) + 1;
    const double left = x_[k] - x_[k - 1], right = x_[k + 1] - x_[k];
    if (i > 0) entries.emplace_back(i, i - 1, left);
    entries.emplace_back(i, i, 2.0 * (left + right));
    if (i + 1 < m) entries.emplace_back(i, i + 1, right);
    rhs(i) = 6.0 * ((y_[k + 1] - y_[k]) / right - (y_[k] - y_[k - 1]) / left);
  }
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  const Eigen::VectorXd solution = solver.solve(rhs);
  for (Eigen::Index i = 0; i < m; ++i) second_[static_cast<std::size_t>(i) + 1] = solution(i);
}

double NaturalCubicSpline::operator()(double x) const {
  const std::size_t n = x_.size();
  const auto slope_at = [&](std::size_t k, bool at_right_end) {
    // first derivative at an end knot of the interval [k, k+1]
    const double h = x_[k + 1] - x_[k];
    const double secant = (y_[k + 1] - y_[k]) / h;
    return at_right_end ? secant + h * (2.0 * second_[k + 1] + second_[k]) / 6.0
                        : secant - h * (2.0 * second_[k] + second_[k + 1]) / 6.0;
  };
  if (x <= x_.front()) return y_.front() + slope_at(0, false) * (x - x_.front());
  if (x >= x_.back()) return y_.back() + slope_at(n - 2, true) * (x - x_.back());
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double h = x_[k + 1] - x_[k];
  const double a = (x_[k + 1] - x) / h, b = (x - x_[k]) / h;
  return a * y_[k] + b * y_[k + 1] +
         ((a * a * a - a) * second_[k] + (b * b * b - b) * second_[k + 1]) * h * h / 6.0;
}

PolynomialFit::PolynomialFit(const std::vector<DataPoint>& points, int degree) {
  if (static_cast<int>(points.size()) <= degree) {
    throw std::invalid_argument("a polynomial of degree " + std::to_string(degree) +
                                " needs more than " + std::to_string(degree) + " points");
  }
  const auto [lo, hi] =
      std::minmax_element(points.begin(), points.end(),
                          [](const DataPoint& a, const DataPoint& b) { return a.x < b.x; });
  center_ = 0.5 * (lo->x + hi->x);
  half_width_ = std::max(0.5 * (hi->x - lo->x), 1e-300);
  Eigen::MatrixXd vandermonde(static_cast<Eigen::Index>(points.size()), degree + 1);
  Eigen::VectorXd y(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double t = (points[i].x - center_) / half_width_;
    double power = 1.0;
    for (int j = 0; j <= degree; ++j, power *= t)
      vandermonde(static_cast<Eigen::Index>(i), j) = power;
    y(static_cast<Eigen::Index>(i)) = points[i].y;
  }
  coefficients_ = vandermonde.householderQr().solve(y);
}

double PolynomialFit::operator()(double x) const {
  const double t = (x - center_) / half_width_;
  double value = 0.0;
  for (Eigen::Index j = coefficients_.size(); j-- > 0;) value = value * t + coefficients_(j);
  return value;
}

}  // namespace musclesim
