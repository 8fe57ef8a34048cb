// Passive identification: the model's T_p (eq. 1) by profile likelihood in the slack length,
// then Levenberg-Marquardt on all three parameters, and the slack length's interval from the
// same profile.
#include "musclesim/identify/identify.h"

#include <unsupported/Eigen/LevenbergMarquardt>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "musclesim/core/errors.h"
#include "musclesim/model/passive.h"
#include "musclesim/core/brent_minimum.h"
#include "identify/identify_fit_statistics.h"
#include "identify/identify_passive_profile.h"
#include "identify/identify_slack_interval.h"

namespace musclesim {

using identify_detail::Covariance;
using identify_detail::PassiveProfile;
using identify_detail::ProfilePoint;
using identify_detail::Rmse;

namespace {

// Parameters (ln k, ln alpha, x0): logs keep k, alpha > 0.
struct PassiveResiduals : Eigen::DenseFunctor<double> {
  explicit PassiveResiduals(const std::vector<DataPoint>& d)
      : Eigen::DenseFunctor<double>(3, static_cast<int>(d.size())), data(d) {}

  static PassiveParams Params(const Eigen::VectorXd& p) {
    return {std::exp(p(0)), std::exp(p(1)), p(2)};
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
      j(row, 2) = -t.slope;
    }
    return 0;
  }

  const std::vector<DataPoint>& data;
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

// The best scanned slack length no further than one data span below the data (below that
// the curve is all but a pure exponential, whatever x0: such data leave the slack length
// undetermined, which the interval says), refined between its scanned neighbours.
ProfilePoint ProfileMinimum(const PassiveProfile& profile, const std::vector<ProfilePoint>& scan,
                            double lowest) {
  std::size_t best = scan.size();
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (scan[i].slack_length >= lowest && (best == scan.size() || scan[i].rss < scan[best].rss)) {
      best = i;
    }
  }
  // the scan always reaches a quarter spacing below the first data point
  const double below = best > 0 && std::isfinite(scan[best - 1].slack_length)
                           ? scan[best - 1].slack_length
                           : scan[best].slack_length;
  const double above =
      best + 1 < scan.size() ? scan[best + 1].slack_length : scan[best].slack_length;
  // to 1e-12 of the bracket: the joint fit that follows polishes the rest
  const auto [x0, rss] = BrentMinimum([&](double x) { return profile.At(x).rss; }, below, above,
                                      1e-12 * (above - below));
  return rss < scan[best].rss ? profile.At(x0) : scan[best];
}

}  // namespace

double PassiveIdentification::Evaluate(double x) const {
  return PassiveTension({k_p.value, alpha.value, slack_length.value}, x).value;
}

PassiveIdentification IdentifyPassive(const std::vector<DataPoint>& data, double level) {
  if (!(level > 0.0 && level < 1.0)) {
    throw std::invalid_argument("IdentifyPassive: level = " + std::to_string(level) +
                                ": must lie strictly between 0 and 1");
  }
  const PassiveProfile profile(data);  // throws InputError without 2 positive tensions
  const double span = data.back().x - data.front().x;
  std::vector<ProfilePoint> scan = identify_detail::ScanSlackLengths(profile, data);
  const ProfilePoint best = ProfileMinimum(profile, scan, data.front().x - span);

  // all three jointly from the profile's optimum; kept when it fits better (the profile's
  // optimum often sits on a data point, where RSS(x0) has a kink and the joint fit stops)
  Eigen::VectorXd p(3);
  p << std::log(std::max(best.k_p, std::numeric_limits<double>::min())), std::log(best.alpha),
      best.slack_length;
  PassiveResiduals joint(data);
  Eigen::VectorXd q = p;
  const double joint_rss = Minimise(joint, q);
  if (joint_rss < best.rss) p = q;
  const double rss = std::min(joint_rss, best.rss);

  Eigen::MatrixXd jacobian(joint.values(), 3);
  joint.df(p, jacobian);
  const Eigen::MatrixXd cov = Covariance(jacobian, rss);
  PassiveIdentification out;
  const double k = std::exp(p(0)), alpha = std::exp(p(1));
  out.k_p = {k, k * std::sqrt(cov(0, 0))};
  out.alpha = {alpha, alpha * std::sqrt(cov(1, 1))};
  out.slack_length = {p(2), std::sqrt(cov(2, 2))};
  out.rmse = Rmse(rss, data.size());
  // lengths or tensions near the ends of the doubles can defeat the fit: never write its
  // overflow as a model
  if (!std::isfinite(k) || !(k > 0.0) || !std::isfinite(alpha) || !(alpha > 0.0) ||
      !std::isfinite(p(2)) || !std::isfinite(out.rmse)) {
    throw InputError("passive data: the fit gives k_p = " + FormatNumber(k) + " N, alpha = " +
                     FormatNumber(alpha) + " 1/m, slack_length = " + FormatNumber(p(2)) +
                     " m, RMSE " + FormatNumber(out.rmse) +
                     " N: not a passive curve; lengths [m] and tensions [N] must be of a "
                     "size double precision can fit");
  }

  // the estimate joins the scan, so that the interval holds it
  const ProfilePoint estimate = profile.At(p(2));
  scan.insert(std::upper_bound(scan.begin(), scan.end(), estimate.slack_length,
                               [](double x, const ProfilePoint& s) { return x < s.slack_length; }),
              estimate);
  const identify_detail::SlackInterval interval =
      identify_detail::SlackLengthInterval(profile, scan, data.size(), span, level);
  out.slack_length_interval = interval.interval;
  out.k_p_over_interval = interval.k_p;
  out.alpha_over_interval = interval.alpha;
  return out;
}

}  // namespace musclesim
