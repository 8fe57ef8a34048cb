#include "identify/identify_series_values.h"

#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim::identify_series_detail {

InputPlace SeriesPlace::Row(std::size_t line) const {
  if (row_file.empty()) return InputPlace{"row " + std::to_string(line)};
  return InputPlace{row_file, static_cast<int>(line)};
}

void SeriesPlace::Fail(const InputPlace& place, const std::string& rule) const {
  throw InputError(InputFault{place, key, std::nullopt, rule});
}

void FillValues(MeasuredSeries& series, const std::vector<std::string>& header,
                std::size_t t_column, const std::vector<std::size_t>& lines,
                const std::function<double(std::size_t, std::size_t)>& value,
                const SeriesPlace& place, bool outputs_optional) {
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (c != t_column) series.columns.push_back(header[c]);
  }
  if (series.columns.empty() && !outputs_optional) {
    place.Fail(place.whole, "only a column t" + place.label +
                                ": give one or more output columns named as the trajectory CSV "
                                "names them (length, tension_total, ...)");
  }
  if (lines.empty()) place.Fail(place.whole, "no rows" + place.label);
  for (std::size_t r = 0; r < lines.size(); ++r) {
    const InputPlace row = place.Row(lines[r]);
    const double t = value(r, t_column);
    if (!std::isfinite(t)) place.Fail(row, "t = " + FormatNumber(t) + ": must be finite");
    if (!series.times.empty() && !(t > series.times.back())) {
      place.Fail(row, "t = " + FormatNumber(t) + " is not greater than the row before (" +
                          FormatNumber(series.times.back()) +
                          "): rows must be sorted by t, without duplicates");
    }
    series.times.push_back(t);
    series.lines.push_back(lines[r]);
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (c == t_column) continue;
      const double v = value(r, c);
      if (!std::isfinite(v)) {
        place.Fail(row, header[c] + " = " + FormatNumber(v) + ": must be finite");
      }
      series.values.push_back(v);
    }
  }
}

void ApplyNoise(MeasuredSeries& series, const SeriesSpec& spec, const std::string& label,
                const std::string& holder, bool design) {
  series.noise.assign(series.columns.size(), std::numeric_limits<double>::quiet_NaN());
  for (const auto& [column, level] : spec.noise) {
    std::size_t c = 0;
    while (c < series.columns.size() && series.columns[c] != column) ++c;
    if (c == series.columns.size()) {
      throw InputError(InputFault{
          spec.at, label + ".noise." + column, std::nullopt,
          holder + " has no column " + column + "; noise levels name its output columns"});
    }
    series.noise[c] = level;
  }
  if (!design) return;
  for (std::size_t c = 0; c < series.columns.size(); ++c) {
    if (std::isnan(series.noise[c])) {
      throw InputError(
          InputFault{spec.at, label, std::nullopt,
                     "an experiment design needs a noise level for column " + series.columns[c] +
                         " (noise: {" + series.columns[c] +
                         ": SD}): the design's standard errors are in units of the noise"});
    }
  }
}

}  // namespace musclesim::identify_series_detail
