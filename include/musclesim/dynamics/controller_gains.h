// A controller's names and gains described once (core/part_fields.h): its name, the actuator
// it drives and what it measures; kp, ki and kd with their units, ranges, defaults and meaning
// (a unit is the measured quantity's: m, m/s or N). The readers, the gains' parameter
// handles, their part of Validate(Controller) and the table in docs/guide/control.md derive
// from it.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/controller.h"

namespace musclesim {

// name, and drives, the actuator driven (absent with co_contraction, the reader's rule).
const std::vector<NameField<Controller>>& ControllerNames();

// The `measure` block's element or node, exactly one of them (the reader's rule).
const std::vector<NameField<Measurement>>& MeasureNames();

// One variant, `pid`, the controllers' one law.
const std::vector<PartVariant<PidGains>>& ControllerGains();

}  // namespace musclesim
