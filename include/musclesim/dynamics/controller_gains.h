// A controller's names, signals and gains described once (core/part_fields.h,
// dynamics/signal_fields.h): its name, the actuator it drives and what it measures; its
// reference, feedforward and co-contraction level; kp, ki and kd with their units, ranges,
// defaults and meaning (a unit is the measured quantity's: m, m/s or N). The readers, the
// parameter handles, their parts of Validate(Controller) and the table in
// docs/guide/control.md derive from it.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/signal_fields.h"

namespace musclesim {

// name, and drives, the actuator driven (absent with co_contraction, the reader's rule).
const std::vector<NameField<Controller>>& ControllerNames();

// The `measure` block's element or node, exactly one of them (the reader's rule).
const std::vector<NameField<Measurement>>& MeasureNames();

// reference, feedforward and co_contraction.level, in the order a file's are read.
const std::vector<SignalField<Controller>>& ControllerSignals();

// One variant, `pid`, the controllers' one law.
const std::vector<PartVariant<PidGains>>& ControllerGains();

// The controllers' types, a variant each with its gains below `gains` ("gains.kp"): `pid`.
const std::vector<PartVariant<Controller>>& ControllerTypes();

}  // namespace musclesim
