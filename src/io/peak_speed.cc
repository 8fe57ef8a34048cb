#include "musclesim/io/peak_speed.h"

#include <algorithm>
#include <cmath>

namespace musclesim {

PeakSpeed FindPeakSpeed(const std::vector<TrajectoryPoint>& trajectory, double v_max) {
  PeakSpeed peak;
  peak.v_max = v_max;
  for (const TrajectoryPoint& p : trajectory) {
    peak.speed = std::max(peak.speed, std::abs(p.sample.shortening_velocity));
  }
  return peak;
}

}  // namespace musclesim
