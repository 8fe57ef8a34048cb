// The model blocks of the other curve families (docs/model.md 14.1), each described once
// (core/part_fields.h): degroote2016's (OpenSim's DeGrooteFregly2016Muscle properties) and
// mujoco's (MuJoCo's muscle attributes), with their keys, units, ranges, defaults and meaning.
// Their reader, their parameter handles, Validate(ModelParams) for them and the table in
// docs/guide/model.md derive from these. A family's `type` is its `family:` name. The
// paper's own block (passive, velocity, active_length) has a reader of its own.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/tension.h"

namespace musclesim {

using ModelFamily = PartVariant<ModelParams>;

// degroote2016, mujoco.
const std::vector<ModelFamily>& ModelFamilies();

}  // namespace musclesim
