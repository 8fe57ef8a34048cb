// Passive tension of the parallel elastic element (paper eq. 1, docs/model.md section 2):
// zero up to the slack length, an exponential above it.
#pragma once

#include <cmath>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/curve_point.h"

namespace musclesim {

struct PassiveParams {
  double k_p = 0.0;           // tension scale [N], >= 0
  double alpha = 1.0;         // exponential rate [1/m], > 0
  double slack_length = 0.0;  // length where passive tension starts [m], finite
};

// The curve's keys (core/part_fields.h): k_p, alpha, slack_length, with their ranges; the
// model block's `passive:` map (model/family_fields.h).
const PartVariant<PassiveParams>& PassiveBlock();

// Throws ParameterError (paths "k_p", "alpha", "slack_length") for a value outside its range.
void Validate(const PassiveParams& params);

// T_p(x) and dT_p/dx (eq. 1). The slope jumps from 0 to k_p * alpha at the slack length;
// at x == slack_length exactly the left (zero) branch is returned. Inline: it sits in the
// integrator's right-hand side.
inline CurvePoint PassiveTension(const PassiveParams& params, double x) {
  if (x <= params.slack_length) return {0.0, 0.0};
  const double growth = std::exp(params.alpha * (x - params.slack_length));
  return {params.k_p * (growth - 1.0), params.k_p * params.alpha * growth};
}

}  // namespace musclesim
