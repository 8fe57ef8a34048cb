// Private: why a point whose axis values are set through parameter handles is not a valid
// scenario, told by its axes: the first whose value alone breaks the base, or their values
// together when each is valid alone.
#pragma once

#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/sweep/sweep.h"

namespace musclesim {

// The message for point `index` of `spec`, whose values `numbers` at `handles` (one per
// axis in `axes`, the indices into spec.axes) made `base` fail with `error`.
std::string ExplainInvalidPoint(const SweepSpec& spec, long index, const Scenario& base,
                                const std::vector<std::size_t>& axes,
                                const std::vector<Parameter>& handles,
                                const std::vector<double>& numbers, const ParameterError& error);

// An axis's place for messages: its location in a file, or "parameters.PATH".
std::string AxisPlace(const SweepAxis& axis);

}  // namespace musclesim
