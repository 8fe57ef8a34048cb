#include "identify/identify_passive_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/brent_minimum.h"

namespace musclesim::identify_detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// g_i = e^(alpha (x_i - x_n)) (1 - e^(-alpha (x_i - x0))) for x_i > x0, in [0, 1]; 0 below
double Shape(double x, double slack_length, double alpha, double last) {
  return std::exp(alpha * (x - last)) * -std::expm1(-alpha * (x - slack_length));
}

}  // namespace

PassiveProfile::PassiveProfile(const std::vector<DataPoint>& data) : data_(data) {
  std::vector<double> positive;
  for (const DataPoint& d : data) {
    if (d.y > 0) positive.push_back(d.x);
  }
  if (positive.size() < 2) {
    throw InputError("passive data: fewer than 2 points with positive tension; nothing to fit");
  }
  upper_limit_ = positive[positive.size() - 2];
  const double span = data.back().x - data.front().x;
  log_alpha_low_ = std::log(1e-3 / span);
  log_alpha_high_ = std::log(1e3 / span);
}

double PassiveProfile::ProjectedRss(double slack_length, double log_alpha, double& c) const {
  const double alpha = std::exp(log_alpha), last = data_.back().x;
  double gg = 0.0, gy = 0.0, yy = 0.0;
  for (const DataPoint& d : data_) {
    yy += d.y * d.y;
    if (d.x <= slack_length) continue;
    const double g = Shape(d.x, slack_length, alpha, last);
    gg += g * g;
    gy += g * d.y;
  }
  // k_p >= 0: a negative projection means the best is no tension at all
  c = gg > 0.0 && gy > 0.0 ? gy / gg : 0.0;
  return std::max(0.0, yy - c * gy);
}

ProfilePoint PassiveProfile::At(double slack_length) const {
  ProfilePoint out;
  out.slack_length = slack_length;
  if (!(slack_length < upper_limit_)) {
    out.rss = kInfinity;
    return out;
  }
  // a grid of 15 in ln(alpha) (steps of e) finds the basin; Brent's method its bottom, to
  // 1e-9 in ln(alpha), far finer than the RSS can tell (quadratic there)
  constexpr int kGrid = 15;
  double c = 0.0, best_u = log_alpha_low_, best_rss = kInfinity;
  const double step = (log_alpha_high_ - log_alpha_low_) / (kGrid - 1);
  for (int i = 0; i < kGrid; ++i) {
    const double u = log_alpha_low_ + step * i, rss = ProjectedRss(slack_length, u, c);
    if (rss < best_rss) {
      best_rss = rss;
      best_u = u;
    }
  }
  const auto [u, rss] = BrentMinimum([&](double v) { return ProjectedRss(slack_length, v, c); },
                                     std::max(log_alpha_low_, best_u - step),
                                     std::min(log_alpha_high_, best_u + step), 1e-9);
  const double log_alpha = rss <= best_rss ? u : best_u;
  ProjectedRss(slack_length, log_alpha, c);

  // the residuals summed directly: the projection formula loses digits to cancellation when
  // the fit is nearly exact
  const double alpha = std::exp(log_alpha), last = data_.back().x;
  double direct = 0.0;
  for (const DataPoint& d : data_) {
    const double t = d.x > slack_length ? c * Shape(d.x, slack_length, alpha, last) : 0.0;
    direct += (t - d.y) * (t - d.y);
  }
  out.rss = direct;
  out.alpha = alpha;
  out.k_p = c * std::exp(-alpha * (last - slack_length));
  return out;
}

std::vector<ProfilePoint> ScanSlackLengths(const PassiveProfile& profile,
                                           const std::vector<DataPoint>& data) {
  std::vector<ProfilePoint> scan;
  const double first = data.front().x, top = profile.UpperLimit();
  // below the data, nearest first, until the curve no longer changes with x0
  const double start = 0.25 * (data[1].x - first);
  for (int j = 0; j < 400; ++j) {
    const double distance = start * std::pow(2.0, 0.5 * j);
    const ProfilePoint p = profile.At(first - distance);
    scan.push_back(p);
    if (std::isfinite(p.rss) && p.alpha * distance > 40.0) break;
  }
  scan.push_back(profile.At(-kInfinity));
  std::reverse(scan.begin(), scan.end());
  // each data point and 3 between each pair: RSS(x0) is smooth between data points
  constexpr int kBetween = 3;
  for (std::size_t i = 0; i + 1 < data.size() && data[i].x < top; ++i) {
    for (int m = 0; m <= kBetween; ++m) {
      const double x0 = data[i].x + (data[i + 1].x - data[i].x) * m / (kBetween + 1);
      if (x0 < top) scan.push_back(profile.At(x0));
    }
  }
  return scan;
}

}  // namespace musclesim::identify_detail
