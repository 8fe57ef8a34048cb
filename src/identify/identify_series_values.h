// Private: the rules a measured series' values obey wherever they come from (a CSV file or
// columns held in memory), shared by ReadMeasuredSeries and MeasuredSeriesFromColumns so that
// both accept and refuse alike; each names the series and its rows its own way.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/identify/identify_series.h"

namespace musclesim::identify_series_detail {

// How errors place a series and its rows.
struct SeriesPlace {
  InputPlace whole;      // the whole series: the CSV's path, or its entry's place
  std::string key;       // "series[0]" for values in memory, "" for a CSV (its rows are placed)
  std::string label;     // after a message on the whole series: " (series[0])", or ""
  std::string row_file;  // rows at ROW_FILE:LINE, or at "row LINE" when empty

  InputPlace Row(std::size_t line) const;
  [[noreturn]] void Fail(const InputPlace& place, const std::string& rule) const;
};

// Fills series.columns, times, values and lines from a table of `lines.size()` rows whose
// columns `header` names, t at `t_column`; `value(r, c)` is row r's value in column c, and
// lines[r] the number messages give row r. Throws InputError: no output column beside t
// (unless `outputs_optional`), no rows, a value not finite, t not strictly increasing.
void FillValues(MeasuredSeries& series, const std::vector<std::string>& header,
                std::size_t t_column, const std::vector<std::size_t>& lines,
                const std::function<double(std::size_t, std::size_t)>& value,
                const SeriesPlace& place, bool outputs_optional = false);

// Sets series.noise (one per series.columns, NaN where `spec` gives none) from the data
// file's entry `spec` of the series `label` ("series[0]"), whose values `holder` names
// (the CSV's path, or the label). Throws InputError: a noise key naming no column, and with
// `design`, a column without a noise level.
void ApplyNoise(MeasuredSeries& series, const SeriesSpec& spec, const std::string& label,
                const std::string& holder, bool design);

}  // namespace musclesim::identify_series_detail
