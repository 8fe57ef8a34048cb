#include "musclesim/model/degroote2016.h"

#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

// finite and in (low, high], or [low, high] when `closed`
void RequireIn(double value, double low, double high, bool closed, const char* path,
               const std::string& rule) {
  const bool above = closed ? value >= low : value > low;
  Require(std::isfinite(value) && above && value <= high, path, value, rule);
}

}  // namespace

void Validate(const DeGrooteParams& p) {
  RequireIn(p.optimal_fiber_length, 0.0, kLengthRange.max, false, "optimal_fiber_length",
            "must be > 0 and at most 1e3 [m]: " + std::string(kLengthRange.why));
  RequireIn(p.max_contraction_velocity, 0.0, 1e6, false, "max_contraction_velocity",
            "must be > 0 and at most 1e6 [optimal fiber lengths per second]");
  RequireIn(p.active_force_width_scale, 1.0, 1e3, true, "active_force_width_scale",
            "must be >= 1 (OpenSim's rule: the curve only widens) and at most 1e3 [-]");
  RequireIn(p.passive_fiber_strain_at_one_norm_force, 0.0, 1e3, false,
            "passive_fiber_strain_at_one_norm_force", "must be > 0 and at most 1e3 [-]");
  RequireIn(p.fiber_damping, 0.0, 1e3, true, "fiber_damping",
            "must be >= 0 and at most 1e3 [-] (OpenSim's default 0, its suggestion 0.01)");
}

}  // namespace musclesim
