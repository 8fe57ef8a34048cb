#include "musclesim/model/mujoco_muscle.h"

#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

void Validate(const MujocoMuscleParams& p) {
  for (int i = 0; i < 2; ++i) {
    const std::string at = "range[" + std::to_string(i) + "]";
    Require(std::isfinite(p.range[i]) && p.range[i] > 0.0 && p.range[i] <= 1e3, at, p.range[i],
            "must be > 0 and at most 1e3 [-] (a length over the optimal one)");
  }
  Require(p.range[1] > p.range[0], "range[1]", p.range[1],
          "must be above range[0] = " + FormatNumber(p.range[0]));
  for (int i = 0; i < 2; ++i) {
    const std::string at = "lengthrange[" + std::to_string(i) + "]";
    Require(kPositionRange.Contains(p.lengthrange[i]), at, p.lengthrange[i], kPositionRange.Rule());
  }
  Require(p.lengthrange[1] > p.lengthrange[0], "lengthrange[1]", p.lengthrange[1],
          "must be above lengthrange[0] = " + FormatNumber(p.lengthrange[0]) +
              " [m] (MuJoCo computes it; `musclesim import` copies it)");
  Require(std::isfinite(p.lmin) && p.lmin >= 0.0 && p.lmin < 1.0, "lmin", p.lmin,
          "must be in [0, 1) [-]: the active curve peaks at 1");
}

}  // namespace musclesim
