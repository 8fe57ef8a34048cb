#include "musclesim/model/mujoco_muscle.h"

#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

void Validate(const MujocoMuscleParams& p) {
  // each number's range is its field's (model/family_fields.h), checked before
  Require(p.range[1] > p.range[0], "range[1]", p.range[1],
          "must be above range[0] = " + FormatNumber(p.range[0]));
  Require(p.lengthrange[1] > p.lengthrange[0], "lengthrange[1]", p.lengthrange[1],
          "must be above lengthrange[0] = " + FormatNumber(p.lengthrange[0]) +
              " [m] (MuJoCo computes it; `musclesim import` copies it)");
  Require(std::isfinite(p.lmin) && p.lmin >= 0.0 && p.lmin < 1.0, "lmin", p.lmin,
          "must be in [0, 1) [-]: the active curve peaks at 1");
}

}  // namespace musclesim
