#include "musclesim/core/student_t.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace musclesim {

double StudentTCentralProbability(double t, int dof) {
  const double theta = std::atan(t / std::sqrt(static_cast<double>(dof)));
  const double s = std::sin(theta), c = std::cos(theta), c2 = c * c;
  if (dof % 2 == 0) {
    // sin(theta) (1 + (1/2) cos^2 + (1 3)/(2 4) cos^4 + ... up to cos^(dof-2))
    double term = 1.0, sum = 1.0;
    for (int j = 2; j <= dof - 2; j += 2) {
      term *= (j - 1.0) / j * c2;
      sum += term;
    }
    return s * sum;
  }
  // (2/pi) (theta + sin(theta) (cos + (2/3) cos^3 + ... up to cos^(dof-2)))
  double sum = 0.0;
  if (dof > 1) {
    double term = c;
    sum = c;
    for (int j = 3; j <= dof - 2; j += 2) {
      term *= (j - 1.0) / j * c2;
      sum += term;
    }
  }
  return 2.0 / std::numbers::pi * (theta + s * sum);
}

double StudentTCentralQuantile(double probability, int dof) {
  // the probability rises with t; double the bracket until it holds the quantile
  double low = 0.0, high = 1.0;
  while (StudentTCentralProbability(high, dof) < probability && high < 1e300) {
    low = high;
    high *= 2.0;
  }
  while (high - low > 4.0 * std::numeric_limits<double>::epsilon() * high) {
    const double mid = 0.5 * (low + high);
    (StudentTCentralProbability(mid, dof) < probability ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace musclesim
