// The single actuator's `actuator:` block described once (core/part_fields.h): its moving
// mass and the parallel damper and spring, with their units, ranges, defaults and meaning.
// Its reader, Validate(ActuatorParams) and the table in docs/guide/scenarios.md derive from
// it; its keys as parameter handles are its network's (scenario/actuator_scenario.h).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/actuator.h"

namespace musclesim {

// One variant, `actuator`.
const std::vector<PartVariant<ActuatorParams>>& ActuatorBlock();

}  // namespace musclesim
