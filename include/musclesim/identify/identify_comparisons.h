// The comparisons of `musclesim identify --report` (docs/guide/identification.md): each curve's
// model fit against the reference fitters (a natural cubic spline, polynomials of degree 3
// and 4), with the notes the report prints under it. Shared by the command and the Python
// module, so that both report the same for the same data.
#pragma once

#include <optional>
#include <vector>

#include "musclesim/identify/identify.h"
#include "musclesim/identify/identify_report.h"

namespace musclesim {

// "passive tension-length": the exponential (eq. 1) refitted by IdentifyPassive, the slack
// length's uncertainty notes of `fit` (the fit of all of `data`) under the table.
CurveComparison ComparePassiveFit(const std::vector<DataPoint>& data,
                                  const PassiveIdentification& fit);

// "active tension-length": `count` Gaussians (eqs. 3-4) refitted by IdentifyActive with
// `nonnegative`.
CurveComparison CompareActiveFit(const std::vector<DataPoint>& data, int count, bool nonnegative);

// "tension-velocity": the power law (eq. 12) refitted by IdentifyVelocity with `f_iso` [N]
// held when given; what `fit` (the fit of all of `data`) found of an eccentric branch, when
// the data hold points v < 0, under the table.
CurveComparison CompareVelocityFit(const std::vector<DataPoint>& data, std::optional<double> f_iso,
                                   const VelocityIdentification& fit);

}  // namespace musclesim
