// Private: the points of a sweep file. The base file is read once into a Scenario and each
// numeric axis (SweepAxis::is_numeric) whose path names a number of it becomes a parameter
// handle; the other axes (words, or paths the base has no number at) are applied to the base
// file's document as `--set` applies a value, and the point read again. A base that is not a
// valid scenario alone (its axes may make every point valid) is read again for every point
// with all the axes applied to its document.
#pragma once

#include <memory>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/sweep/sweep_points.h"

namespace musclesim {

// The points of `spec` made from the base file `base` (spec.base). Messages name the sweep
// file's axes and the base file's keys with their lines and columns.
std::unique_ptr<PointFactory> FilePoints(std::unique_ptr<ScenarioTemplate> base,
                                         const SweepSpec& spec);

}  // namespace musclesim
