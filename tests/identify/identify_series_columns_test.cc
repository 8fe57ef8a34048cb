// Measured series and data-file specs held in memory (the Python module's path): the same
// series as the CSV files give, the same rules, messages naming the series and its row; and
// a spec read from text as the file reader reads it.
#include "musclesim/identify/identify_series_columns.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "musclesim/core/errors.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

// The message of the InputError `f` throws, as it is (the text's name "TEXT" kept).
template <typename F>
std::string MessageOf(F f) {
  return InputErrorOf("no file", f);
}

// A spec read from text with the values in memory; `noise` the series' entry.
IdentifySeriesSpec InMemorySpec(const std::string& entry) {
  return ParseIdentifySeriesSpec(
      "TEXT", "scenario: s.yaml\nseries:\n  - " + entry + "\nparameters: [{path: model.f_iso}]\n",
      "", SeriesValues::kInMemory);
}

// The message of the InputError MeasuredSeriesFromColumns throws for one series.
std::string ErrorOf(const SeriesColumns& columns, const std::string& entry = "{}",
                    bool design = false) {
  const IdentifySeriesSpec spec = InMemorySpec(entry);
  return MessageOf([&] { MeasuredSeriesFromColumns(spec, {columns}, design); });
}

TEST(MeasuredSeriesFromColumns, GivesWhatTheSameCsvGives) {
  // the columns in another order than t first, as a CSV may have them
  const std::string csv = WriteTempFile(
      "lengths.csv", "length,t,tension_total\n0.1,0,5\n0.099,0.01,6\n0.097,0.03,6.5\n");
  const std::string data = WriteTempFile(
      "data.yaml",
      "scenario: r.yaml\nseries:\n  - {csv: " + std::filesystem::path(csv).filename().string() +
          ", noise: {tension_total: 0.5}}\nparameters: [{path: a}]\n");
  const MeasuredSeries file = ReadMeasuredSeries(LoadIdentifySeriesSpec(data), false)[0];
  const MeasuredSeries memory = MeasuredSeriesFromColumns(
      InMemorySpec("{noise: {tension_total: 0.5}}"),
      {{{"length", {0.1, 0.099, 0.097}}, {"t", {0.0, 0.01, 0.03}}, {"tension_total", {5, 6, 6.5}}}},
      false)[0];
  EXPECT_EQ(memory.columns, file.columns);
  EXPECT_EQ(memory.times, file.times);
  EXPECT_EQ(memory.values, file.values);
  ASSERT_EQ(memory.noise.size(), 2u);
  EXPECT_TRUE(std::isnan(memory.noise[0]));  // no level for length
  EXPECT_EQ(memory.noise[1], file.noise[1]);
  EXPECT_EQ(memory.lines, (std::vector<std::size_t>{1, 2, 3}));  // rows, not the file's lines
  EXPECT_EQ(memory.source, "");
  EXPECT_EQ(PlaceText(memory.at), "TEXT:3:5");
}

TEST(MeasuredSeriesFromColumns, RefusesWhatTheCsvRulesRefuse) {
  EXPECT_EQ(ErrorOf({{"length", {0.1}}}),
            "series[0] (TEXT:3:5): no column t: give the measured times t [s] beside the output "
            "columns");
  EXPECT_THAT(ErrorOf({{"t", {0.0}}}), HasSubstr("series[0] (TEXT:3:5): only a column t: give"));
  EXPECT_EQ(ErrorOf({{"t", {}}, {"length", {}}}), "series[0] (TEXT:3:5): no rows");
  EXPECT_EQ(ErrorOf({{"t", {0.0, 0.02, 0.01}}, {"length", {0.1, 0.1, 0.1}}}),
            "series[0] (row 3): t = 0.01 is not greater than the row before (0.02): rows must be "
            "sorted by t, without duplicates");
  EXPECT_EQ(ErrorOf({{"t", {0.0, NAN}}, {"length", {0.1, 0.1}}}),
            "series[0] (row 2): t = nan: must be finite");
  EXPECT_EQ(ErrorOf({{"t", {0.0, 0.01}}, {"length", {0.1, INFINITY}}}),
            "series[0] (row 2): length = inf: must be finite");
  EXPECT_EQ(ErrorOf({{"t", {0.0}}, {"length", {0.1}}}, "{noise: {tension_total: 1}}"),
            "series[0].noise.tension_total (TEXT:3:5): series[0] has no column tension_total; "
            "noise levels name its output columns");
  EXPECT_THAT(ErrorOf({{"t", {0.0}}, {"length", {0.1}}, {"tension_total", {1.0}}},
                      "{noise: {length: 1.0e-5}}", true),
              HasSubstr("series[0] (TEXT:3:5): an experiment design needs a noise level for column "
                        "tension_total"));
  // only in memory: columns of one length, each once
  EXPECT_EQ(ErrorOf({{"t", {0.0, 0.01}}, {"length", {0.1}}}),
            "series[0].length (TEXT:3:5): has 1 values where t has 2: every column needs one "
            "value per time");
  EXPECT_EQ(ErrorOf({{"t", {0.0}}, {"length", {0.1}}, {"length", {0.1}}}),
            "series[0].length (TEXT:3:5): given twice: each column once");
}

TEST(MeasuredSeriesFromColumns, TheDesignTakesColumnsFromNoise) {
  const IdentifySeriesSpec spec = InMemorySpec("{noise: {length: 1.0e-5}}");
  const MeasuredSeries grid = MeasuredSeriesFromColumns(spec, {{}}, true)[0];
  EXPECT_EQ(grid.columns, std::vector<std::string>{"length"});
  EXPECT_TRUE(grid.times.empty());  // the scenario's output grid
  EXPECT_EQ(grid.noise, std::vector<double>{1e-5});
  const MeasuredSeries timed = MeasuredSeriesFromColumns(spec, {{{"t", {0.0, 0.1}}}}, true)[0];
  EXPECT_EQ(timed.columns, std::vector<std::string>{"length"});
  EXPECT_EQ(timed.times, (std::vector<double>{0.0, 0.1}));
  // a fit needs the values
  EXPECT_THAT(MessageOf([&] { MeasuredSeriesFromColumns(spec, {{}}, false); }),
              HasSubstr("no column t"));
  EXPECT_THAT(ErrorOf({}, "{}", true), HasSubstr("neither output columns nor noise levels"));
  EXPECT_THAT(ErrorOf({{"t", {0.0}}}, "{}", true),
              HasSubstr("neither output columns nor noise levels"));
  EXPECT_THROW(MeasuredSeriesFromColumns(spec, {}, true), std::invalid_argument);
}

TEST(ParseIdentifySeriesSpec, ReadsTextAsTheFileReaderReadsAFile) {
  const std::string text =
      "scenario: ../s.yaml\nseries:\n  - {csv: m.csv, noise: {length: 2.0e-5}}\n"
      "parameters:\n  - {path: model.f_iso, start: 80, bounds: [1, 1000]}\n";
  const std::string path = WriteTempFile("data.yaml", text);
  const IdentifySeriesSpec file = LoadIdentifySeriesSpec(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const IdentifySeriesSpec parsed = ParseIdentifySeriesSpec("TEXT", text, dir);
  EXPECT_EQ(parsed.scenario, file.scenario);
  EXPECT_EQ(*parsed.series[0].csv, *file.series[0].csv);
  // the same places, in the text named TEXT
  EXPECT_EQ(parsed.series[0].csv_at.file, "TEXT");
  EXPECT_EQ(parsed.series[0].csv_at.line, file.series[0].csv_at.line);
  EXPECT_EQ(parsed.series[0].csv_at.column, file.series[0].csv_at.column);
  EXPECT_EQ(PlaceText(parsed.parameters[0].at), "TEXT:5:5");
  EXPECT_EQ(PlaceText(file.parameters[0].at), path + ":5:5");
  EXPECT_EQ(*parsed.parameters[0].upper, 1000.0);
  EXPECT_EQ(ParseIdentifySeriesSpec("TEXT", text, "").scenario, "../s.yaml");  // as given
  // the same rules and messages, with the text's name in place of the file's
  std::string broken = text;
  broken.replace(broken.find("[1, 1000]"), 9, "[1000, 1]");
  EXPECT_EQ(MessageOf([&] { ParseIdentifySeriesSpec("TEXT", broken, ""); }),
            "parameters[0].bounds = [1000, 1] (TEXT:5:44): must be [lower, upper] with "
            "lower < upper");
}

TEST(ParseIdentifySeriesSpec, ValuesInMemoryNeedNoCsv) {
  EXPECT_NO_THROW(InMemorySpec("{}"));  // no noise levels: allowed, as for a csv
  EXPECT_THAT(MessageOf([] { InMemorySpec("{csv: m.csv}"); }),
              HasSubstr("series[0].csv (TEXT:3:6): unknown key; allowed here: noise"));
  EXPECT_THAT(MessageOf([] {
                ParseIdentifySeriesSpec("TEXT", "scenario: s\nseries: []\nparameters: [a]\n", "",
                                        SeriesValues::kInMemory);
              }),
              HasSubstr("series = [] (TEXT:2:9): must be a list of one or more series"));
}

}  // namespace
}  // namespace musclesim
