// The families of activation dynamics (docs/model.md 8.1), each described once
// (core/part_fields.h): thelen2003, degroote2016 and mujoco with their time constants and
// smoothings, units, ranges, defaults and meaning. The `activation_dynamics` reader, its
// parameter handles, Validate(ActivationDynamics) and the table in docs/guide/scenarios.md
// derive from these; a family's `type` is its `family:` name.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/activation_dynamics.h"

namespace musclesim {

using ActivationFamilyVariant = PartVariant<ActivationDynamics>;

// thelen2003 (the default), degroote2016, mujoco.
const std::vector<ActivationFamilyVariant>& ActivationFamilies();

}  // namespace musclesim
