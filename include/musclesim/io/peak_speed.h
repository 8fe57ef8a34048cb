// The fastest shortening or lengthening of a finished run, against the model's v_max:
// outside [-v_max, v_max] g(v) is the paper's power law extrapolated (docs/model.md section 4),
// which whoever reads the result should be told. Data only; the caller words the note.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "musclesim/solver/simulation.h"

namespace musclesim {

struct PeakSpeed {
  double speed = 0.0;  // largest |shortening velocity| on the trajectory [m/s], >= 0
  double v_max = 1.0;  // the model's maximum shortening velocity [m/s], > 0

  // speed / v_max [-]: above 1 the run left [-v_max, v_max].
  double ratio() const { return speed / v_max; }
  bool beyond_v_max() const { return speed > v_max; }
  // Takes one more point into account, for runs whose points are not kept.
  void Observe(const TrajectoryPoint& point) {
    speed = std::max(speed, std::abs(point.sample.shortening_velocity));
  }
};

// Scans every point of `trajectory` (an empty one gives speed 0). `v_max` [m/s] is the
// model's, model.velocity.v_max.
PeakSpeed FindPeakSpeed(const std::vector<TrajectoryPoint>& trajectory, double v_max);

}  // namespace musclesim
