// The model blocks of the curve families (docs/model.md 14.1), each described once
// (core/part_fields.h): the paper's (its passive and velocity curves, active_length's sigma),
// degroote2016's (OpenSim's DeGrooteFregly2016Muscle properties) and mujoco's (MuJoCo's muscle
// attributes), with their keys, units, ranges, defaults and meaning. Their readers, their
// parameter handles, the closed-form derivatives' names (model/tension_parameter.h),
// Validate(ModelParams) and the table in docs/guide/model.md derive from these. A family's
// `type` is its `family:` name. The paper's Gaussians and L_opt, and MuJoCo's lists of two,
// are their readers' own (`other_keys`).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/tension.h"

namespace musclesim {

using ModelFamily = PartVariant<ModelParams>;

// paper, degroote2016, mujoco.
const std::vector<ModelFamily>& ModelFamilies();

}  // namespace musclesim
