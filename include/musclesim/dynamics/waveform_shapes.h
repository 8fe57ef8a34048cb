// The shapes of a waveform, each described once (core/part_fields.h): constant, step, ramp,
// sine, pulses and table with their keys, units, accepted values, defaults and meaning. The
// waveform reader, the waveforms' parameter handles and the table in docs/guide/scenarios.md
// derive from these. A value of the signal is in the unit of what the waveform drives (an
// activation, a force, a position), so its bounds are the reader's context's; the rules
// between fields (a ramp's end after its start, a pulse's width within its period, a table's
// times increasing) stay in Validate(Waveform).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/waveform.h"

namespace musclesim {

using WaveformShape = PartVariant<Waveform>;

// In the order of WaveformKind; a shape's `type` is ToString(kind).
const std::vector<WaveformShape>& WaveformShapes();

}  // namespace musclesim
