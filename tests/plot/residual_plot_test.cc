// The residual figure of time-series identification: what its gnuplot script holds, the
// layouts it refuses, and that gnuplot draws it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/identify/identify_series.h"
#include "musclesim/plot/plot.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

CsvTable Residuals(const std::string& text) {
  return ReadCsv(testing::WriteTempFile("residuals.csv", text));
}

// Two series: lengths at two times, and a tension at one.
const char* const kResiduals =
    "series,output,t,measured,model,residual,standardised\n"
    "0,length,0,0.1,0.1001,-0.0001,-5\n"
    "0,length,0.5,0.09,0.0899,0.0001,5\n"
    "1,tension_total,0.25,40,39,1,2\n";

TEST(ResidualPlot, APanelPerSeriesAndOutputOverTheStandardisedResiduals) {
  const CsvTable table = Residuals(kResiduals);
  EXPECT_TRUE(IsResidualTable(table));
  PlotOptions options;
  options.output = "fit.png";
  const std::string script = ResidualPlotScript(table, options);
  // each panel's rows: t, measured, model, standardised
  EXPECT_THAT(script, HasSubstr("$d0 << EOD\n0 0.1 0.1001 -5\n0.5 0.09 0.0899 5\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("$d1 << EOD\n0.25 40 39 2\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 3,1"));  // two series, the residuals
  EXPECT_THAT(script, HasSubstr("set ylabel 'series 0: length'"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'series 1: tension_total'"));
  EXPECT_THAT(script, HasSubstr("$d1 using 1:4 with points pt 7 ps 0.5 title '1: tension_total'"));
}

TEST(ResidualPlot, OtherTablesAreNotResidualsAndBrokenOnesAreRefused) {
  EXPECT_FALSE(IsResidualTable(Residuals("t,length,tension_total\n0,0.1,1\n")));
  PlotOptions options;
  options.output = "fit.png";
  const std::string path =
      testing::WriteTempFile("residuals.csv", "series,t,measured,model,standardised\n0,0,1,1,0\n");
  EXPECT_EQ(testing::InputErrorOf(path, [&] { ResidualPlotScript(ReadCsv(path), options); }),
            "FILE: missing columns: output (a residual CSV of a time-series identification: "
            "series, output, t, measured, model, residual, standardised)");
  const std::string nan = testing::WriteTempFile(
      "residuals.csv",
      "series,output,t,measured,model,residual,standardised\n0,length,0,nan,1,0,0\n");
  EXPECT_THAT(testing::InputErrorOf(nan, [&] { ResidualPlotScript(ReadCsv(nan), options); }),
              HasSubstr("FILE:2: column measured = 'nan': must be a finite number"));
}

TEST(ResidualPlot, TheResidualCsvOfAFitIsWhatItDraws) {
  SeriesIdentification fit;
  fit.residuals = {{0, "length", 0.0, 0.1, 0.1001, -5.0}, {0, "length", 0.5, 0.09, 0.0899, 5.0}};
  const std::string path = testing::WriteTempFile("residuals.csv", FormatResidualCsv(fit));
  const CsvTable table = ReadCsv(path);
  ASSERT_TRUE(IsResidualTable(table));
  PlotOptions options;
  options.output = "fit.png";
  EXPECT_THAT(ResidualPlotScript(table, options),
              HasSubstr("0 0.1 0.1001 -5\n0.5 0.09 0.0899 5\nEOD\n"));
}

TEST(ResidualPlot, GnuplotDrawsIt) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  PlotOptions options;
  options.output = testing::WriteTempFile("fit.png", "");
  std::filesystem::remove(options.output);
  Render(ResidualPlotScript(Residuals(kResiduals), options), options);
  EXPECT_GT(std::filesystem::file_size(options.output), 1000u);  // a PNG, not an empty file
}

}  // namespace
}  // namespace musclesim
