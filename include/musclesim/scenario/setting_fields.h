// The run's settings described once (core/part_fields.h): the `time:` span and the numbers of
// the `output:` block. Their readers, their `time.*`, `output.interval` and
// `output.phase_tolerance` parameter handles and their reference tables derive from these;
// the rules between keys (the span against the time scale, the output interval against the
// span) stay the readers'.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

// The `time` block: the span a run integrates [s].
struct TimeSpan {
  double start = 0.0;  // [s]
  double end = 1.0;    // [s], > start by at least kMinSpanRelative of the time scale
};

// One variant, `time`: start and end, both required.
const std::vector<PartVariant<TimeSpan>>& TimeBlock();

// One variant, `output`: interval (a time or `steps`; its rule against the span the reader's)
// and phase_tolerance, both optional, and the text `file`.
const std::vector<PartVariant<OutputRequest>>& OutputBlock();

}  // namespace musclesim
