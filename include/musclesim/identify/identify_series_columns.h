// Measured series held in memory rather than in CSV files (the Python module's arrays), for
// time-series identification: the same rules as ReadMeasuredSeries, with messages that name
// the series and its 1-based row instead of a file and its line.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/identify/identify_series.h"

namespace musclesim {

// One series' values: named columns of equal length, in the caller's order, as the
// trajectory CSV names them (length, tension_total, NODE.position, ...), with `t` [s] among
// them [the columns' units].
using SeriesColumns = std::vector<std::pair<std::string, std::vector<double>>>;

// The measured series of `spec` (read with SeriesValues::kInMemory), given[i] holding the
// values of spec.series[i] and spec.series[i].noise their noise levels. The rules are
// ReadMeasuredSeries's: a column t, one or more output columns, at least one row, every value
// finite, t strictly increasing, noise keys naming output columns, and with `design` a noise
// level for every column; besides, column names are distinct and every column as long as t.
// With `design`, a series without output columns takes them from its noise keys (as one
// without csv does), and its times from its t, or without t (no columns at all) from the
// scenario's output grid. Throws InputError naming the series ("series[0] (row 4): t = ...",
// "series[0].noise.force (WHERE): ..."), the column, the value and the rule; a
// std::invalid_argument when `given` and spec.series differ in length.
std::vector<MeasuredSeries> MeasuredSeriesFromColumns(const IdentifySeriesSpec& spec,
                                                      const std::vector<SeriesColumns>& given,
                                                      bool design);

}  // namespace musclesim
