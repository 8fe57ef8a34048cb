#include "musclesim/io/peak_speed.h"

namespace musclesim {

PeakSpeed FindPeakSpeed(const std::vector<TrajectoryPoint>& trajectory, double v_max) {
  PeakSpeed peak;
  peak.v_max = v_max;
  for (const TrajectoryPoint& p : trajectory) peak.Observe(p);
  return peak;
}

}  // namespace musclesim
