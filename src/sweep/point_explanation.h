// Private: why a point whose axis values are set through parameter handles is not a valid
// scenario, told by its axes: the first whose value alone breaks the base, or their values
// together when each is valid alone.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/sweep/sweep.h"

namespace musclesim {

// The error for point `index` of `spec`, whose values `numbers` at `handles` (one per
// axis in `axes`, the indices into spec.axes) made `base` fail with `error`.
InputError ExplainInvalidPoint(const SweepSpec& spec, long index, const Scenario& base,
                               const std::vector<std::size_t>& axes,
                               const std::vector<Parameter>& handles,
                               const std::vector<double>& numbers, const ParameterError& error);

// An axis's place for messages: its location in a file, or "parameters.PATH".
std::string AxisPlace(const SweepAxis& axis);

// A fault of an axis (key parameters.PATH, at the axis's place), told as "PLACE: axis PATH"
// then " = VALUE " when `value` is given, else ": ", then the rule.
InputError AxisError(const SweepAxis& axis, const std::optional<std::string>& value,
                     const std::string& rule);

}  // namespace musclesim
