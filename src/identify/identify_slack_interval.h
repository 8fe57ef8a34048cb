// The slack length's profile-likelihood confidence interval, from a scan of its profile.
#pragma once

#include <cstddef>
#include <vector>

#include "musclesim/identify/identify.h"
#include "identify/identify_passive_profile.h"

namespace musclesim::identify_detail {

struct SlackInterval {
  ProfileInterval interval;  // [m]
  ValueRange k_p;            // the best k_p at the slack lengths inside [N]
  ValueRange alpha;          // the best alpha there [1/m]
};

// The largest RSS [N^2] the interval admits, from the least, rss_min [N^2], of `points`
// data points fitted with 3 parameters, at confidence `level` [-]; +infinity when
// points <= 3 (no residual degree of freedom to measure the noise by).
double SlackRssThreshold(double rss_min, std::size_t points, double level);

// `scan`: the profile at slack lengths sorted ascending (ScanSlackLengths), including the
// best fit found, whose RSS is the least. Each end of the interval is the outermost scanned
// slack length inside, refined by bisection against its outside neighbour to 1e-10 of the
// data's span; a dip inside narrower than the scan's step may be missed. Where RSS(x0)
// stays inside on both sides of an outside stretch, the interval spans both (conservative).
SlackInterval SlackLengthInterval(const PassiveProfile& profile,
                                  const std::vector<ProfilePoint>& scan, std::size_t points,
                                  double span, double level);

}  // namespace musclesim::identify_detail
