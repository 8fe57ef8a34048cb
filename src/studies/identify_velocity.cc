// Velocity identification: linear least squares in s = sgn(v) |v|^(1/n) for each n, from
// the points v >= 0 when there are eccentric ones (v < 0), which then give the eccentric
// branch (identify_eccentric.cc).
#include "musclesim/studies/identify.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "musclesim/errors.h"
#include "studies/identify_eccentric.h"
#include "studies/identify_fit_statistics.h"

namespace musclesim {

using identify_detail::Covariance;
using identify_detail::Rmse;

double VelocityIdentification::Evaluate(double v) const {
  if (v < 0 && eccentric && eccentric->identified) {
    return best.f_iso.value * identify_detail::EccentricFactor(eccentric->best, v);
  }
  const double s = (v > 0) - (v < 0);
  return best.f_iso.value * (1.0 - s * std::pow(std::abs(v) / best.v_max.value, 1.0 / best.n));
}

VelocityIdentification IdentifyVelocity(const std::vector<DataPoint>& all,
                                        std::optional<double> f_iso) {
  VelocityIdentification out;
  // with eccentric points, the concentric power law from v >= 0 alone (the v = 0 point,
  // which fixes f_iso, among them)
  std::vector<DataPoint> data, lengthening;
  for (const DataPoint& p : all) (p.x < 0 ? lengthening : data).push_back(p);
  const std::size_t needed = f_iso ? 2 : 3;
  if (!lengthening.empty() && data.size() < needed) {
    throw InputError("velocity data: points with v >= 0: " + std::to_string(data.size()) +
                     "; the concentric branch (v_max, n" + (f_iso ? "" : ", f_iso") +
                     ") needs at least " + std::to_string(needed) +
                     " (the points v < 0 give the eccentric branch only)");
  }
  const auto n_points = static_cast<Eigen::Index>(data.size());
  for (int n = 1; n <= 10; ++n) {
    VelocityCandidate c;
    c.n = n;
    Eigen::MatrixXd design(n_points, f_iso ? 1 : 2);
    Eigen::VectorXd y(n_points);
    for (Eigen::Index i = 0; i < n_points; ++i) {
      const double v = data[static_cast<std::size_t>(i)].x;
      const double s = ((v > 0) - (v < 0)) * std::pow(std::abs(v), 1.0 / n);
      y(i) = data[static_cast<std::size_t>(i)].y - (f_iso ? *f_iso : 0.0);
      if (f_iso) {
        design(i, 0) = s;
      } else {
        design(i, 0) = 1.0;
        design(i, 1) = s;
      }
    }
    const Eigen::VectorXd coef = design.colPivHouseholderQr().solve(y);
    const double rss = (design * coef - y).squaredNorm();
    const Eigen::MatrixXd cov = Covariance(design, rss);
    const double a = f_iso ? *f_iso : coef(0), b = f_iso ? coef(0) : coef(1);
    const double var_a = f_iso ? 0.0 : cov(0, 0), var_b = f_iso ? cov(0, 0) : cov(1, 1);
    const double cov_ab = f_iso ? 0.0 : cov(0, 1);
    c.rmse = Rmse(rss, data.size());
    c.valid = a > 0 && b < 0;
    if (c.valid) {
      const double v_max = std::pow(-a / b, n);
      // delta method: dv/da = n v / a, dv/db = -n v / b
      const double da = n * v_max / a, db = -n * v_max / b;
      c.v_max = {v_max, std::sqrt(da * da * var_a + db * db * var_b + 2 * da * db * cov_ab)};
      c.f_iso = {a, f_iso ? 0.0 : std::sqrt(var_a)};
    }
    out.candidates.push_back(c);
  }
  const auto best = std::min_element(out.candidates.begin(), out.candidates.end(),
                                     [](const VelocityCandidate& p, const VelocityCandidate& q) {
                                       if (p.valid != q.valid) return p.valid;
                                       return p.rmse < q.rmse;
                                     });
  if (!best->valid) {
    throw InputError("velocity data: tension does not fall with shortening velocity for any n "
                     "in 1..10; nothing to fit");
  }
  out.best = *best;
  if (!lengthening.empty()) {
    out.eccentric = identify_detail::IdentifyEccentric(lengthening, out.best.f_iso);
  }
  return out;
}

}  // namespace musclesim
