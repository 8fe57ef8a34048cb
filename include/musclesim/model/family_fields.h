// The model blocks of the curve families (docs/model.md 14.1), each described once
// (core/part_fields.h): the paper's (its passive and velocity curves, active_length's sigma),
// degroote2016's (OpenSim's DeGrooteFregly2016Muscle properties) and mujoco's (MuJoCo's muscle
// attributes), with their keys, units, ranges, defaults and meaning. Their readers, their
// parameter handles, the closed-form derivatives' names (model/tension_parameter.h),
// Validate(ModelParams) and the table in docs/guide/model.md derive from these. A family's
// `type` is its `family:` name. The paper's L_opt and MuJoCo's lists of two are lists of
// numbers ("range[1]"), the paper's Gaussians a list of sub-parts; a fit in their place is
// the paper's reader's own (`other_keys`).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/tension.h"

namespace musclesim {

using ModelFamily = PartVariant<ModelParams>;

// A Gaussian's numbers: amplitude, width (Gaussian::precision), center; each finite, their
// rules the model's. Tagged with their TensionParameterKind.
const std::vector<NumberField<Gaussian>>& GaussianFields();

// paper, degroote2016, mujoco.
const std::vector<ModelFamily>& ModelFamilies();

}  // namespace musclesim
