// The data file of time-series identification and its measured series: what is read, and
// each rule with the message that names file, line, column, key, value and rule.
#include "musclesim/io/readers/identify_series_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "musclesim/identify/identify_series.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

constexpr const char* kComplete = R"(scenario: release.yaml
series:
  - csv: lengths.csv
    noise: {length: 2.0e-5}
  - noise: {tension_total: 0.1, length: 1.0e-4}
parameters:
  - {path: model.f_iso, start: 80, bounds: [1, 1000]}
  - {path: model.velocity.v_max}
)";

TEST(IdentifySeriesSpec, ReadsACompleteDataFile) {
  const std::string path = WriteTempFile("data.yaml", kComplete);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  EXPECT_TRUE(IsIdentifySeriesFile(path));
  const IdentifySeriesSpec spec = LoadIdentifySeriesSpec(path);
  EXPECT_EQ(spec.scenario, dir + "/release.yaml");
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(*spec.series[0].csv, dir + "/lengths.csv");
  EXPECT_EQ(PlaceText(spec.series[0].csv_at), path + ":3:10");
  EXPECT_FALSE(spec.series[1].csv);
  ASSERT_EQ(spec.series[1].noise.size(), 2u);
  EXPECT_EQ(spec.series[1].noise[0].first, "tension_total");  // the file's order
  EXPECT_EQ(spec.series[1].noise[1].second, 1e-4);
  ASSERT_EQ(spec.parameters.size(), 2u);
  EXPECT_EQ(spec.parameters[0].path, "model.f_iso");
  EXPECT_EQ(*spec.parameters[0].start, 80.0);
  EXPECT_EQ(*spec.parameters[0].lower, 1.0);
  EXPECT_EQ(*spec.parameters[0].upper, 1000.0);
  EXPECT_FALSE(spec.parameters[1].start);
  EXPECT_FALSE(spec.parameters[1].lower);
  EXPECT_EQ(PlaceText(spec.parameters[1].at), path + ":8:5");
}

TEST(IdentifySeriesSpec, TheCurvesKindIsNotTheSeriesKind) {
  EXPECT_FALSE(IsIdentifySeriesFile(WriteTempFile("curves.yaml", "passive: {csv: p.csv}\n")));
  EXPECT_FALSE(IsIdentifySeriesFile(WriteTempFile("list.yaml", "- scenario\n")));
}

// The message for a data file whose text is kComplete with `from` replaced by `to`.
std::string ErrorWith(const std::string& from, const std::string& to) {
  std::string text = kComplete;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string path = WriteTempFile("data.yaml", text);
  return InputErrorOf(path, [&] { LoadIdentifySeriesSpec(path); });
}

TEST(IdentifySeriesSpec, RejectsEachBrokenRuleNamingWhereAndWhy) {
  EXPECT_EQ(ErrorWith("series:", "serie:"),
            "serie (FILE:2:1): unknown key; allowed here: scenario, series, parameters");
  EXPECT_EQ(ErrorWith("scenario: release.yaml", "scenario: \"\""),
            "scenario = \"\" (FILE:1:11): must not be empty");
  EXPECT_THAT(ErrorWith("  - noise: {tension_total: 0.1, length: 1.0e-4}", "  - {}"),
              HasSubstr("series[1] = {} (FILE:5:5): give csv (the measured values, to fit) or "
                        "noise"));
  EXPECT_THAT(ErrorWith("{length: 2.0e-5}", "{length: 0}"),
              HasSubstr("series[0].noise.length = 0 (FILE:4:21): must be > 0"));
  EXPECT_THAT(ErrorWith("{length: 2.0e-5}", "{length: .nan}"),
              HasSubstr("series[0].noise.length = .nan (FILE:4:21): must be > 0"));
  EXPECT_THAT(ErrorWith("{length: 2.0e-5}", "2.0e-5"),
              HasSubstr("series[0].noise = 2.0e-5 (FILE:4:12): must be a map from column names"));
  EXPECT_EQ(ErrorWith("path: model.velocity.v_max", "path: model..v_max"),
            "parameters[1].path = model..v_max (FILE:8:12): must be a dotted key path into "
            "the scenario, e.g. model.f_iso or load[0].value");
  EXPECT_EQ(ErrorWith("path: model.velocity.v_max", "path: model.f_iso"),
            "parameters[1].path = model.f_iso (FILE:8:12): is listed twice: each parameter once");
  EXPECT_EQ(ErrorWith("bounds: [1, 1000]", "bounds: [1000, 1]"),
            "parameters[0].bounds = [1000, 1] (FILE:7:44): must be [lower, upper] with "
            "lower < upper");
  EXPECT_THAT(ErrorWith("bounds: [1, 1000]", "bounds: [1, .inf]"),
              HasSubstr("parameters[0].bounds[1] = .inf (FILE:7:48): must be from -1e+12 to "
                        "1e+12"));
  EXPECT_THAT(ErrorWith("bounds: [1, 1000]", "bounds: [1]"),
              HasSubstr("parameters[0].bounds = [1] (FILE:7:44): must be a list of exactly 2"));
  EXPECT_EQ(ErrorWith("start: 80", "start: 1001"),
            "parameters[0].start = 1001 (FILE:7:32): must lie within bounds [1, 1000]");
  EXPECT_THAT(ErrorWith("  - {path: model.f_iso, start: 80, bounds: [1, 1000]}\n"
                        "  - {path: model.velocity.v_max}\n",
                        ""),
              HasSubstr("parameters = ~ (FILE:7:1): must be a list of one or more parameters"));
  EXPECT_THAT(ErrorWith("start: 80", "stat: 80"),
              HasSubstr("parameters[0].stat (FILE:7:25): unknown key; allowed here: start, "
                        "bounds, path"));
}

// Measured series read from `csv` (as lengths.csv beside a data file) with `noise`.
std::string SeriesError(const std::string& csv, const std::string& noise, bool design) {
  const std::string csv_path = WriteTempFile("lengths.csv", csv);
  const std::string name = std::filesystem::path(csv_path).filename().string();
  const std::string data =
      WriteTempFile("data.yaml", "scenario: release.yaml\nseries:\n  - {csv: " + name + noise +
                                     "}\nparameters:\n  - {path: model.f_iso}\n");
  std::string message =
      InputErrorOf(data, [&] { ReadMeasuredSeries(LoadIdentifySeriesSpec(data), design); });
  for (auto at = message.find(csv_path); at != std::string::npos; at = message.find(csv_path)) {
    message.replace(at, csv_path.size(), "CSV");
  }
  return message;
}

TEST(ReadMeasuredSeries, ReadsTimesColumnsAndNoise) {
  const std::string csv_path =
      WriteTempFile("lengths.csv", "# synthetic\nlength,t,tension_total\n0.1,0,5\n0.099,0.01,6\n");
  const std::string data = WriteTempFile(
      "data.yaml", "scenario: r.yaml\nseries:\n  - {csv: " +
                       std::filesystem::path(csv_path).filename().string() +
                       ", noise: {tension_total: 0.5, length: 1.0e-5}}\nparameters: [{path: a}]\n");
  const std::vector<MeasuredSeries> s = ReadMeasuredSeries(LoadIdentifySeriesSpec(data), false);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].columns, (std::vector<std::string>{"length", "tension_total"}));
  EXPECT_EQ(s[0].times, (std::vector<double>{0.0, 0.01}));
  EXPECT_EQ(s[0].values, (std::vector<double>{0.1, 5, 0.099, 6}));
  EXPECT_EQ(s[0].noise, (std::vector<double>{1e-5, 0.5}));
  EXPECT_EQ(s[0].lines, (std::vector<std::size_t>{3, 4}));
}

TEST(ReadMeasuredSeries, RejectsDataTheFitCannotUse) {
  EXPECT_THAT(SeriesError("time,length\n0,0.1\n", "", false),
              HasSubstr("series[0].csv = CSV (FILE:3:11): CSV: missing columns: t"));
  EXPECT_THAT(SeriesError("t\n0\n", "", false), HasSubstr("CSV: only a column t (series[0])"));
  EXPECT_THAT(SeriesError("t,length\n", "", false), HasSubstr("CSV: no rows (series[0])"));
  EXPECT_THAT(SeriesError("t,length\n0,0.1\n0.02,0.1\n0.01,0.1\n", "", false),
              HasSubstr("CSV:4: t = 0.01 is not greater than the row before (0.02): rows must be "
                        "sorted by t, without duplicates"));
  EXPECT_THAT(SeriesError("t,length\n0,0.1\n0.01,nan\n", "", false),
              HasSubstr("CSV:3: length = nan: must be finite"));
  EXPECT_THAT(SeriesError("t,length\n0,0.1\n", ", noise: {tension_total: 1}", false),
              HasSubstr("series[0].noise.tension_total (FILE:3:5): CSV has no column "
                        "tension_total; noise levels name its output columns"));
  EXPECT_THAT(SeriesError("t,length,tension_total\n0,0.1,1\n", ", noise: {length: 1.0e-5}", true),
              HasSubstr("series[0] (FILE:3:5): an experiment design needs a noise level for column "
                        "tension_total"));
  EXPECT_EQ(SeriesError("t,length\n0,0.1\n", ", noise: {length: 1.0e-5}", false), "accepted");
}

TEST(ReadMeasuredSeries, OnlyTheDesignDoesWithoutCsv) {
  const std::string data = WriteTempFile(
      "data.yaml",
      "scenario: r.yaml\nseries:\n  - noise: {length: 1.0e-5}\nparameters: [{path: a}]\n");
  const IdentifySeriesSpec spec = LoadIdentifySeriesSpec(data);
  EXPECT_EQ(InputErrorOf(data, [&] { ReadMeasuredSeries(spec, false); }),
            "series[0] (FILE:3:5): needs csv, the measured values, to fit (only an experiment "
            "design does without: it takes the columns from noise)");
  const std::vector<MeasuredSeries> planned = ReadMeasuredSeries(spec, true);
  EXPECT_EQ(planned[0].columns, std::vector<std::string>{"length"});
  EXPECT_TRUE(planned[0].times.empty());  // the scenario's output grid
}

}  // namespace
}  // namespace musclesim
