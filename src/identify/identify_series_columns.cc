#include "musclesim/identify/identify_series_columns.h"

#include <set>
#include <stdexcept>

#include "identify/identify_series_values.h"
#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

using identify_series_detail::SeriesPlace;

MeasuredSeries FromColumns(const SeriesSpec& spec, const SeriesColumns& columns,
                           const std::string& label, bool design) {
  MeasuredSeries series;
  series.at = spec.at;
  const auto fail = [&](const std::string& key, const std::string& rule) {
    throw InputError(InputFault{spec.at, key, std::nullopt, rule});
  };
  const bool times_only = design && columns.size() == 1 && columns[0].first == "t";
  if (design && (columns.empty() || times_only) && spec.noise.empty()) {
    fail(label,
         "neither output columns nor noise levels: the design takes the columns from noise: "
         "{COLUMN: SD} (and the times from t, or the scenario's output grid)");
  }
  if (design && columns.empty()) {  // the columns from noise, the times from the output grid
    for (const auto& [column, level] : spec.noise) series.columns.push_back(column);
    identify_series_detail::ApplyNoise(series, spec, label, label, design);
    return series;
  }
  std::vector<std::string> header;
  std::set<std::string> seen;
  std::size_t t_column = columns.size();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    header.push_back(columns[c].first);
    if (!seen.insert(columns[c].first).second) {
      fail(label + "." + columns[c].first, "given twice: each column once");
    }
    if (columns[c].first == "t") t_column = c;
  }
  if (t_column == columns.size()) {
    fail(
        label,
        std::string("no column t: give the measured times t [s] beside the output columns") +
            (design ? " (or, for the design, no columns at all: the scenario's output grid)" : ""));
  }
  const std::size_t rows = columns[t_column].second.size();
  for (const auto& [column, values] : columns) {
    if (values.size() != rows) {
      fail(label + "." + column, "has " + std::to_string(values.size()) + " values where t has " +
                                     std::to_string(rows) +
                                     ": every column needs one value per time");
    }
  }
  std::vector<std::size_t> lines(rows);
  for (std::size_t r = 0; r < rows; ++r) lines[r] = r + 1;
  identify_series_detail::FillValues(
      series, header, t_column, lines,
      [&](std::size_t r, std::size_t c) { return columns[c].second[r]; },
      SeriesPlace{spec.at, label, "", ""}, times_only);
  if (times_only) {  // the columns from noise, as a design series without csv
    for (const auto& [column, level] : spec.noise) series.columns.push_back(column);
  }
  identify_series_detail::ApplyNoise(series, spec, label, label, design);
  return series;
}

}  // namespace

std::vector<MeasuredSeries> MeasuredSeriesFromColumns(const IdentifySeriesSpec& spec,
                                                      const std::vector<SeriesColumns>& given,
                                                      bool design) {
  if (given.size() != spec.series.size()) {
    throw std::invalid_argument("MeasuredSeriesFromColumns: " + std::to_string(given.size()) +
                                " series of values for the spec's " +
                                std::to_string(spec.series.size()));
  }
  std::vector<MeasuredSeries> all;
  for (std::size_t i = 0; i < given.size(); ++i) {
    all.push_back(
        FromColumns(spec.series[i], given[i], "series[" + std::to_string(i) + "]", design));
  }
  return all;
}

}  // namespace musclesim
