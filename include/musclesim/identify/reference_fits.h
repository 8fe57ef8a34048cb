// The fits the literature uses for measured muscle curves, to compare musclesim's model
// with: a natural cubic spline through the points, and least-squares polynomials (the
// third and fourth degrees of the works the paper cites). Eigen does the linear algebra.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace musclesim {

struct DataPoint {
  double x = 0.0;  // length [m] or shortening velocity [m/s]
  double y = 0.0;  // tension [N]
};

// The interpolating cubic spline with zero second derivative at both ends; extrapolated
// linearly beyond them (the natural spline's own continuation). Needs >= 2 points with
// strictly increasing x. The second derivatives come from the tridiagonal system, solved
// with Eigen's sparse LU.
class NaturalCubicSpline {
 public:
  explicit NaturalCubicSpline(const std::vector<DataPoint>& points);
  double operator()(double x) const;

 private:
  std::vector<double> x_;       // knots [the data's x unit]
  std::vector<double> y_;       // values there [the data's y unit]
  std::vector<double> second_;  // second derivatives there [y unit / x unit^2]
};

// The least-squares polynomial of `degree` (Householder QR on a Vandermonde matrix in a
// variable scaled to [-1, 1], for conditioning). Needs more points than the degree.
class PolynomialFit {
 public:
  PolynomialFit(const std::vector<DataPoint>& points, int degree);
  double operator()(double x) const;

 private:
  double center_;                 // middle of the data's x range [x unit]
  double half_width_;             // half that range [x unit]; t = (x - center_) / half_width_
  Eigen::VectorXd coefficients_;  // of t^j [y unit], constant first
};

}  // namespace musclesim
