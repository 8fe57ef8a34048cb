// The measured series of a time-series identification, read from their CSV files with the
// rules the fit needs of them (identify_series_values.h).
#include "identify/identify_series_values.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/identify/identify_series.h"

namespace musclesim {

namespace {

using identify_series_detail::SeriesPlace;

// The series' values from its CSV: t first, then every other column.
void ReadValues(MeasuredSeries& series, const std::string& path, const std::string& label) {
  const CsvTable table = ReadCsv(path);
  table.Require({"t"}, "measured series: t and output columns");
  const int t_column = table.Find("t");
  identify_series_detail::FillValues(
      series, table.header, static_cast<std::size_t>(t_column), table.lines,
      [&](std::size_t r, std::size_t c) { return table.Number(r, static_cast<int>(c)); },
      SeriesPlace{InputPlace{path}, "", " (" + label + ")", path});
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
        throw InputError(label + ".csv = " + *s.csv + " (" + PlaceText(s.csv_at) + ")", e);
      }
    } else if (!design) {
      throw InputError(InputFault{s.at, label, std::nullopt,
                                  "needs csv, the measured values, to fit (only an experiment "
                                  "design does without: it takes the columns from noise)"});
    } else {
      for (const auto& [column, level] : s.noise) series.columns.push_back(column);
    }
    identify_series_detail::ApplyNoise(series, s, label, series.source, design);
    all.push_back(std::move(series));
  }
  return all;
}

}  // namespace musclesim
