// A controller's gains described once (core/part_fields.h): kp, ki and kd with their units,
// ranges, defaults and meaning (a unit is the measured quantity's: m, m/s or N). The `gains`
// reader, their parameter handles, their part of Validate(Controller) and the table in
// docs/guide/control.md derive from it.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/controller.h"

namespace musclesim {

// One variant, `pid`, the controllers' one law.
const std::vector<PartVariant<PidGains>>& ControllerGains();

}  // namespace musclesim
