// Velocity identification: linear least squares in s = sgn(v) |v|^(1/n) for each n. With
// eccentric points (v < 0) also the two-branch curve: the concentric branch from v >= 0, the
// eccentric one from v < 0 (identify_eccentric.cc), kept when the information criterion
// prefers it to the symmetric curve fitted to every point.
#include "musclesim/identify/identify.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "identify/identify_eccentric.h"
#include "identify/identify_fit_statistics.h"

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

namespace {

// The power law T = f_iso (1 - sgn(v) (|v| / v_max)^(1/n)) for each n in 1..10, linear
// least squares in s = sgn(v) |v|^(1/n); the valid candidate of least RMSE first.
struct PowerLawFit {
  VelocityCandidate best;
  std::vector<VelocityCandidate> candidates;
  double rss = 0.0;  // of `best` [N^2]
};

PowerLawFit FitPowerLaw(const std::vector<DataPoint>& data, std::optional<double> f_iso) {
  PowerLawFit out;
  std::vector<double> rss_of;
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
    rss_of.push_back(rss);
  }
  const auto best = std::min_element(out.candidates.begin(), out.candidates.end(),
                                     [](const VelocityCandidate& p, const VelocityCandidate& q) {
                                       if (p.valid != q.valid) return p.valid;
                                       return p.rmse < q.rmse;
                                     });
  out.best = *best;
  out.rss = rss_of[static_cast<std::size_t>(best - out.candidates.begin())];
  return out;
}

// The Bayesian information criterion of a least-squares fit with Gaussian noise of unknown
// variance: lower is better; each parameter must buy a factor exp(ln(n) / n) in the RSS.
double Bic(double rss, std::size_t points, int parameters) {
  const double n = static_cast<double>(points);
  return n * std::log(std::max(rss, 1e-300) / n) + parameters * std::log(n);
}

}  // namespace

VelocityIdentification IdentifyVelocity(const std::vector<DataPoint>& all,
                                        std::optional<double> f_iso) {
  // the paper's symmetric curve from every point
  const PowerLawFit symmetric = FitPowerLaw(all, f_iso);
  if (!symmetric.best.valid) {
    throw InputError(
        "velocity data: tension does not fall with shortening velocity for any n "
        "in 1..10; nothing to fit");
  }
  VelocityIdentification out;
  out.best = symmetric.best;
  out.candidates = symmetric.candidates;
  std::vector<DataPoint> data, lengthening;
  for (const DataPoint& p : all) (p.x < 0 ? lengthening : data).push_back(p);
  if (lengthening.empty()) return out;

  // with eccentric points: the concentric branch from v >= 0 alone (the v = 0 point, which
  // fixes f_iso, among them), the eccentric one from v < 0 with that f_iso
  const std::size_t needed = f_iso ? 2 : 3;
  if (data.size() < needed) {
    throw InputError("velocity data: points with v >= 0: " + std::to_string(data.size()) +
                     "; the concentric branch (v_max, n" + (f_iso ? "" : ", f_iso") +
                     ") needs at least " + std::to_string(needed) +
                     " (the points v < 0 give the eccentric branch only)");
  }
  EccentricIdentification eccentric;
  eccentric.points = lengthening.size();
  const PowerLawFit concentric = FitPowerLaw(data, f_iso);
  if (!concentric.best.valid) {
    eccentric.why_not =
        "the points with v >= 0 alone show no tension falling with shortening "
        "velocity";
    eccentric.why_no_limit = eccentric.why_not;
    out.eccentric = eccentric;
    return out;
  }
  eccentric = identify_detail::IdentifyEccentric(lengthening, concentric.best.f_iso);
  if (eccentric.identified) {
    // the two-branch curve has v_max_e and n_e (and L) more than the symmetric one, which it
    // contains: it is kept only when the data pay for them
    const int own = f_iso ? 0 : 1;  // f_iso, when fitted
    const double rss =
        concentric.rss + std::pow(eccentric.best.rmse, 2) * static_cast<double>(eccentric.points);
    const int two_branch = own + 4 + (eccentric.limit_identified ? 1 : 0);
    const int one_branch = own + 2;
    if (Bic(rss, all.size(), two_branch) < Bic(symmetric.rss, all.size(), one_branch)) {
      out.best = concentric.best;
      out.candidates = concentric.candidates;
    } else {
      eccentric.identified = eccentric.limit_identified = false;
      eccentric.why_not =
          "the symmetric curve fitted to every point describes the data as well "
          "(Bayesian information criterion), so the data do not tell a separate "
          "eccentric branch apart";
      eccentric.why_no_limit = eccentric.why_not;
    }
  }
  out.eccentric = eccentric;
  return out;
}

}  // namespace musclesim
