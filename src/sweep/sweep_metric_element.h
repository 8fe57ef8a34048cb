// Private: which element a sweep's metrics read. metric_options.element names it; left out,
// it is the only actuator of the base (in the single-actuator form, always its actuator).
#pragma once

#include <string>

#include "io/readers/yaml_fields.h"
#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_points.h"

namespace musclesim {

// The element of `elements` (those of the sweep's point 0) that the metrics of the sweep
// file `root` (read from `src`) read. Throws InputError at metric_options.element when it
// names no element of them, listing them; at metric_options (or metrics, without it) when
// it is left out and a network has no actuator or several, naming them.
std::string ResolveMetricElement(const yaml::Source& src, const Document& root,
                                 const SweepSpec& spec, const MetricElements& elements);

}  // namespace musclesim
