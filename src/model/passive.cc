#include "musclesim/model/passive.h"

#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

void Validate(const PassiveParams& params) {
  Require(std::isfinite(params.k_p) && params.k_p >= 0.0 && params.k_p <= kPositiveForceRange.max,
          "k_p", params.k_p,
          "must be >= 0 and at most 1e9 [N]: " + std::string(kPositiveForceRange.why));
  Require(std::isfinite(params.alpha) && params.alpha > 0.0, "alpha", params.alpha,
          "must be finite and > 0 [1/m]");
  Require(std::isfinite(params.slack_length), "slack_length", params.slack_length,
          "must be finite [m]");
}

}  // namespace musclesim
