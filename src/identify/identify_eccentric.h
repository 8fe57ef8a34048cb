// Private: the eccentric branch of the velocity identification (docs/model.md section 9),
// fitted to the points with v < 0 (docs/guide/identification.md).
#pragma once

#include <vector>

#include "musclesim/identify/identify.h"

namespace musclesim::identify_detail {

// The eccentric branch fitted to `lengthening` (every point v < 0) with f_iso held at
// `f_iso` [N]; f_iso's standard error (0 when it was given, not fitted) is carried into the
// branch's. Never throws for data it cannot use: it says why in the result.
EccentricIdentification IdentifyEccentric(const std::vector<DataPoint>& lengthening,
                                          const Estimate& f_iso);

// The unregularised g(v) of `branch` at v < 0 [m/s]: 1 + psi, or 1 + (L - 1) tanh(psi /
// (L - 1)) with a finite limit, psi = (-v / v_max_e)^(1/n_e).
double EccentricFactor(const EccentricCandidate& branch, double v);

}  // namespace musclesim::identify_detail
