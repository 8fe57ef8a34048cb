#include "identify/identify_series_values.h"

#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim::identify_series_detail {

void FillValues(MeasuredSeries& series, const std::vector<std::string>& header,
                std::size_t t_column, const std::vector<std::size_t>& lines,
                const std::function<double(std::size_t, std::size_t)>& value,
                const SeriesPlace& place, bool outputs_optional) {
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (c != t_column) series.columns.push_back(header[c]);
  }
  if (series.columns.empty() && !outputs_optional) {
    throw InputError(place.name + ": only a column t" + place.label +
                     ": give one or more output "
                     "columns named as the trajectory CSV names them (length, tension_total, ...)");
  }
  if (lines.empty()) throw InputError(place.name + ": no rows" + place.label);
  for (std::size_t r = 0; r < lines.size(); ++r) {
    const std::string where = place.row_before + std::to_string(lines[r]) + place.row_after + ": ";
    const double t = value(r, t_column);
    if (!std::isfinite(t)) throw InputError(where + "t = " + FormatNumber(t) + ": must be finite");
    if (!series.times.empty() && !(t > series.times.back())) {
      throw InputError(where + "t = " + FormatNumber(t) + " is not greater than the row before (" +
                       FormatNumber(series.times.back()) +
                       "): rows must be sorted by t, without duplicates");
    }
    series.times.push_back(t);
    series.lines.push_back(lines[r]);
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (c == t_column) continue;
      const double v = value(r, c);
      if (!std::isfinite(v)) {
        throw InputError(where + header[c] + " = " + FormatNumber(v) + ": must be finite");
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
      throw InputError(label + ".noise." + column + " (" + spec.at + "): " + holder +
                       " has no column " + column + "; noise levels name its output columns");
    }
    series.noise[c] = level;
  }
  if (!design) return;
  for (std::size_t c = 0; c < series.columns.size(); ++c) {
    if (std::isnan(series.noise[c])) {
      throw InputError(label + " (" + spec.at +
                       "): an experiment design needs a noise level for column " +
                       series.columns[c] + " (noise: {" + series.columns[c] +
                       ": SD}): the design's standard errors are in units of the noise");
    }
  }
}

}  // namespace musclesim::identify_series_detail
