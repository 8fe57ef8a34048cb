// Reading sweep files (docs/guide/sweeps.md): the axes, the metrics and the base scenario file,
// into a SweepPlan whose points are the base read once and changed through parameter
// handles (sweep_points.h). An axis whose values are not all numbers (a solver's method, an
// element's name), or whose path names no number of the base, is applied to the base file's
// document instead, as `--set` applies a value, and read again for each point.
#pragma once

#include <string>
#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/sweep/sweep_points.h"

namespace musclesim {

// The sweep file's keys, described once (core/part_fields.h): one variant, `sweep`. Its
// `parameters` (the axes), `metrics` and metric_options.element have their reader's own rules,
// as have those between keys: samples and seed for mode random only, and required there;
// the window's end after its start; time_to_length's target_length.
const std::vector<PartVariant<SweepSpec>>& SweepFileBlock();

// Reads and validates a sweep file and its points (PlanSweep), and resolves the element the
// metrics read (metric_options.element; by default the only actuator). Throws InputError:
// for the sweep file, naming its file, line, column and key (a network without one actuator
// and no metric_options.element, an element that point 0 does not have); for a point whose
// axis value is bad, naming the axis, the value, the point and the axis's line and column;
// for an error in the base scenario, naming the base file's line and column. Of several
// invalid points it names the first. Validates on `threads` threads (0: every core, shared
// with the other MPI ranks of this host). Under MPI (initialised, more than one rank) every
// rank of MPI_COMM_WORLD must call it for the same file.
SweepPlan LoadSweep(const std::string& path, int threads = 0);

// The same for a sweep `document` built in code (io/readers/document.h), `name` naming it in
// messages. Its `base` is a scenario file's path, relative to the working directory, unless
// `base` is given: then that Scenario is the base, the document's `base` only its name in
// messages, and `base_text` (its YAML, say) what resume's signature hashes for it.
SweepPlan ReadSweep(const Document& document, const std::string& name, const Scenario* base,
                    const std::string& base_text, int threads = 0);

}  // namespace musclesim
