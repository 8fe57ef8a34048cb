// The passive fit's profile in the slack length: for a fixed slack length x0, the best k_p
// and alpha and their residual sum of squares RSS(x0). The point estimate minimises it; the
// slack length's confidence interval is where it stays below a threshold.
#pragma once

#include <vector>

#include "musclesim/identify/reference_fits.h"

namespace musclesim::identify_detail {

struct ProfilePoint {
  double slack_length = 0.0;  // x0 [m]; -infinity: the limit below the data, a pure exponential
  double rss = 0.0;           // [N^2]; +infinity when fewer than 2 positive tensions lie above x0
  double k_p = 0.0;           // the best k_p there [N]; 0 at x0 = -infinity
  double alpha = 0.0;         // the best alpha there [1/m]
};

// RSS(x0) = min over k_p >= 0, alpha > 0 of sum (T_p(x_i) - y_i)^2 (eq. 1). With x0 and alpha
// fixed, T_p = c (e^(alpha (x - x_n)) - e^(alpha (x0 - x_n))) above x0 is linear in c, so the
// best c is a projection; alpha by a grid in ln(alpha) and Brent's method. Measuring from the
// last data point x_n keeps every term in [0, 1]: no overflow for any alpha, and x0 may go
// down to -infinity, where the curve becomes c e^(alpha (x - x_n)).
class PassiveProfile {
 public:
  // `data`: sorted by x, at least 2 positive tensions (else InputError). Kept by reference:
  // it must outlive the profile.
  explicit PassiveProfile(const std::vector<DataPoint>& data);

  ProfilePoint At(double slack_length) const;

  // The slack lengths the data can fit lie below this one [m]: the second-to-last length
  // with positive tension (above it, fewer than 2 such points are left for k_p and alpha).
  double UpperLimit() const { return upper_limit_; }

 private:
  // sum (c g_i - y_i)^2 at the best c for x0 and ln(alpha) (the projection formula: fast, and
  // exact enough to minimise over alpha); sets c
  double ProjectedRss(double slack_length, double log_alpha, double& c) const;

  const std::vector<DataPoint>& data_;
  double upper_limit_ = 0.0;     // [m]
  double log_alpha_low_ = 0.0;   // ln(alpha [1/m]) searched: alpha times the data's span
  double log_alpha_high_ = 0.0;  // from 1e-3 (a straight line) to 1e3 (only the last point)
};

// The profile along a scan of every slack length the data can distinguish, sorted by slack
// length: -infinity; below the first data point, distances from it growing by sqrt(2) from a
// quarter of the first spacing until alpha times the distance exceeds 40 (then the offset
// e^(alpha (x0 - x)) is below 1e-17 of the curve everywhere: the -infinity limit); at each
// data point (RSS(x0) has a kink at each) and at 3 points between each pair, up to
// UpperLimit().
std::vector<ProfilePoint> ScanSlackLengths(const PassiveProfile& profile,
                                           const std::vector<DataPoint>& data);

}  // namespace musclesim::identify_detail
