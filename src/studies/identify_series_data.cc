// The measured series of a time-series identification, read from their CSV files with the
// rules the fit needs of them.
#include <cmath>
#include <limits>

#include "musclesim/errors.h"
#include "musclesim/io/csv_table.h"
#include "musclesim/model/number_format.h"
#include "musclesim/studies/identify_series.h"

namespace musclesim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The series' values from its CSV: t first, then every other column.
void ReadValues(MeasuredSeries& series, const std::string& path, const std::string& label) {
  const CsvTable table = ReadCsv(path);
  table.Require({"t"}, "measured series: t and output columns");
  const int t_column = table.Find("t");
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    if (static_cast<int>(c) != t_column) series.columns.push_back(table.header[c]);
  }
  if (series.columns.empty()) {
    throw InputError(path + ": only a column t (" + label + "): give one or more output columns "
                     "named as the trajectory CSV names them (length, tension_total, ...)");
  }
  if (table.rows.empty()) throw InputError(path + ": no rows (" + label + ")");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string where = path + ":" + std::to_string(table.lines[r]) + ": ";
    const double t = table.Number(r, t_column);
    if (!std::isfinite(t)) throw InputError(where + "t = " + FormatNumber(t) + ": must be finite");
    if (!series.times.empty() && !(t > series.times.back())) {
      throw InputError(where + "t = " + FormatNumber(t) + " is not greater than the row before (" +
                       FormatNumber(series.times.back()) +
                       "): rows must be sorted by t, without duplicates");
    }
    series.times.push_back(t);
    series.lines.push_back(table.lines[r]);
    for (std::size_t c = 0; c < table.header.size(); ++c) {
      if (static_cast<int>(c) == t_column) continue;
      const double value = table.Number(r, static_cast<int>(c));
      if (!std::isfinite(value)) {
        throw InputError(where + table.header[c] + " = " + FormatNumber(value) +
                         ": must be finite");
      }
      series.values.push_back(value);
    }
  }
}

}  // namespace

std::vector<MeasuredSeries> ReadMeasuredSeries(const IdentifySeriesSpec& spec, bool design) {
  std::vector<MeasuredSeries> all;
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const SeriesSpec& s = spec.series[i];
    const std::string label = "series[" + std::to_string(i) + "]";
    MeasuredSeries series;
    series.at = s.at;
    if (s.csv) {
      series.source = *s.csv;
      try {
        ReadValues(series, *s.csv, label);
      } catch (const InputError& e) {
        throw InputError(label + ".csv = " + *s.csv + " (" + s.csv_at + "): " + e.what());
      }
    } else if (!design) {
      throw InputError(label + " (" + s.at + "): needs csv, the measured values, to fit (only "
                       "--design does without: it takes the columns from noise)");
    } else {
      for (const auto& [column, level] : s.noise) series.columns.push_back(column);
    }
    series.noise.assign(series.columns.size(), kNaN);
    for (const auto& [column, level] : s.noise) {
      std::size_t c = 0;
      while (c < series.columns.size() && series.columns[c] != column) ++c;
      if (c == series.columns.size()) {
        throw InputError(label + ".noise." + column + " (" + s.at + "): " + series.source +
                         " has no column " + column + "; noise levels name its output columns");
      }
      series.noise[c] = level;
    }
    if (design) {
      for (std::size_t c = 0; c < series.columns.size(); ++c) {
        if (std::isnan(series.noise[c])) {
          throw InputError(label + " (" + s.at + "): --design needs a noise level for column " +
                           series.columns[c] + " (noise: {" + series.columns[c] +
                           ": SD}): the design's standard errors are in units of the noise");
        }
      }
    }
    all.push_back(std::move(series));
  }
  return all;
}

}  // namespace musclesim
