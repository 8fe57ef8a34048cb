// Passive identification: the model's T_p (eq. 1) by profile likelihood in the slack length,
// then Levenberg-Marquardt on all three parameters.
#include "musclesim/studies/identify.h"

#include <unsupported/Eigen/LevenbergMarquardt>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/errors.h"
#include "musclesim/model/passive.h"
#include "studies/identify_fit_statistics.h"

namespace musclesim {

using identify_detail::Covariance;
using identify_detail::Rmse;

namespace {

// Parameters (ln k, ln alpha) with x0 fixed, or (ln k, ln alpha, x0): logs keep k, alpha > 0.
struct PassiveResiduals : Eigen::DenseFunctor<double> {
  PassiveResiduals(const std::vector<DataPoint>& d, std::optional<double> slack)
      : Eigen::DenseFunctor<double>(slack ? 2 : 3, static_cast<int>(d.size())), data(d),
        fixed_slack(slack) {}

  PassiveParams Params(const Eigen::VectorXd& p) const {
    return {std::exp(p(0)), std::exp(p(1)), fixed_slack ? *fixed_slack : p(2)};
  }

  int operator()(const Eigen::VectorXd& p, Eigen::VectorXd& r) const {
    const PassiveParams params = Params(p);
    for (std::size_t i = 0; i < data.size(); ++i) {
      r(static_cast<Eigen::Index>(i)) = PassiveTension(params, data[i].x).value - data[i].y;
    }
    return 0;
  }

  // with T and dT/dx from PassiveTension, u = x - x0: dT/d(ln k) = T,
  // dT/d(ln alpha) = u dT/dx, dT/dx0 = -dT/dx
  int df(const Eigen::VectorXd& p, Eigen::MatrixXd& j) const {
    const PassiveParams params = Params(p);
    for (std::size_t i = 0; i < data.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      const CurvePoint t = PassiveTension(params, data[i].x);
      j(row, 0) = t.value;
      j(row, 1) = (data[i].x - params.slack_length) * t.slope;
      if (!fixed_slack) j(row, 2) = -t.slope;
    }
    return 0;
  }

  const std::vector<DataPoint>& data;
  std::optional<double> fixed_slack;
};

double Minimise(PassiveResiduals& residuals, Eigen::VectorXd& p) {
  Eigen::LevenbergMarquardt<PassiveResiduals> lm(residuals);
  lm.setXtol(1e-15);
  lm.setFtol(1e-15);
  lm.setMaxfev(2000);
  lm.minimize(p);
  Eigen::VectorXd r(residuals.values());
  residuals(p, r);
  return std::isfinite(r.squaredNorm()) ? r.squaredNorm() : std::numeric_limits<double>::infinity();
}

// (ln k, ln alpha) to start from for a slack length x0: a log-linear fit of the larger
// tensions, where T ~ k exp(alpha (x - x0)).
Eigen::VectorXd PassiveStart(const std::vector<DataPoint>& data, double x0, double span) {
  double top = 0.0;
  for (const DataPoint& d : data) top = std::max(top, d.y);
  double su = 0, sl = 0, suu = 0, sul = 0, n = 0;
  for (const DataPoint& d : data) {
    if (d.x <= x0 || d.y <= 0.05 * top) continue;
    const double u = d.x - x0, l = std::log(d.y);
    su += u; sl += l; suu += u * u; sul += u * l; n += 1;
  }
  double alpha = 3.0 / span, log_k = std::log(std::max(top, 1e-300)) - 3.0;
  if (n >= 2 && n * suu - su * su > 0) {
    const double slope = (n * sul - su * sl) / (n * suu - su * su);
    if (slope > 0) {
      alpha = slope;
      log_k = (sl - slope * su) / n;
    }
  }
  Eigen::VectorXd p(2);
  p << log_k, std::log(alpha);
  return p;
}

}  // namespace

double PassiveIdentification::Evaluate(double x) const {
  return PassiveTension({k_p.value, alpha.value, slack_length.value}, x).value;
}

PassiveIdentification IdentifyPassive(const std::vector<DataPoint>& data) {
  const double lo = data.front().x, hi = data.back().x, span = hi - lo;
  // the profile: the best (k, alpha) for each candidate slack length
  const auto profile = [&](double x0, Eigen::VectorXd* best) {
    std::size_t above = 0;
    for (const DataPoint& d : data) above += d.x > x0 && d.y > 0;
    if (above < 2) return std::numeric_limits<double>::infinity();
    PassiveResiduals residuals(data, x0);
    Eigen::VectorXd p = PassiveStart(data, x0, span);
    const double rss = Minimise(residuals, p);
    if (best != nullptr) *best = p;
    return rss;
  };
  const int candidates = 200;
  const double first = lo - 0.25 * span, step = (hi - first) / candidates;
  double best_x0 = first, best_rss = std::numeric_limits<double>::infinity();
  for (int i = 0; i < candidates; ++i) {
    const double x0 = first + step * i;
    const double rss = profile(x0, nullptr);
    if (rss < best_rss) {
      best_rss = rss;
      best_x0 = x0;
    }
  }
  if (!std::isfinite(best_rss)) {
    throw InputError("passive data: fewer than 2 points with positive tension; nothing to fit");
  }
  // golden-section refinement of the profile around the best candidate
  double a = best_x0 - step, b = best_x0 + step;
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double c = b - ratio * (b - a), d = a + ratio * (b - a);
    if (profile(c, nullptr) < profile(d, nullptr)) {
      b = d;
    } else {
      a = c;
    }
  }
  double x0 = 0.5 * (a + b);
  Eigen::VectorXd p2;
  if (!(profile(x0, &p2) <= best_rss)) {
    x0 = best_x0;
    profile(x0, &p2);
  }
  // all three jointly from the profile's optimum
  Eigen::VectorXd p(3);
  p << p2(0), p2(1), x0;
  PassiveResiduals joint(data, std::nullopt);
  Eigen::VectorXd q = p;
  const double joint_rss = Minimise(joint, q);
  PassiveResiduals fixed(data, x0);
  Eigen::VectorXd r2 = p2;
  const double profile_rss = Minimise(fixed, r2);
  if (joint_rss <= profile_rss) p = q; else p << r2(0), r2(1), x0;
  const double rss = std::min(joint_rss, profile_rss);

  Eigen::MatrixXd jacobian(joint.values(), 3);
  joint.df(p, jacobian);
  const Eigen::MatrixXd cov = Covariance(jacobian, rss);
  PassiveIdentification out;
  const double k = std::exp(p(0)), alpha = std::exp(p(1));
  out.k_p = {k, k * std::sqrt(cov(0, 0))};
  out.alpha = {alpha, alpha * std::sqrt(cov(1, 1))};
  out.slack_length = {p(2), std::sqrt(cov(2, 2))};
  out.rmse = Rmse(rss, data.size());
  return out;
}

}  // namespace musclesim
