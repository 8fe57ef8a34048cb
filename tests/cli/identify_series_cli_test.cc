// `musclesim identify` on a time-series data file, end to end: the estimated scenario runs
// and holds the estimates, the design and the residuals, the exit codes and messages of bad
// input, and the measured curves' kind left as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "musclesim/io/readers/scenario_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

struct Outcome {
  int exit_code;
  std::string out;  // standard output
  std::string err;  // standard error
};

Outcome RunCli(const std::string& arguments) {
  const std::string err_path = testing::WriteTempFile("stderr.txt", "");
  const std::string command = std::string(MUSCLESIM_BINARY) + " " + arguments + " 2>" + err_path;
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out, testing::ReadFile(err_path)};
}

std::string Data(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/data/" + name;
}

TEST(IdentifySeriesCli, TheEstimatedScenarioHoldsTheEstimatesAndRuns) {
  const std::string scenario = testing::WriteTempFile("estimated.yaml", "");
  const std::string report = testing::WriteTempFile("report.md", "");
  const std::string residuals = testing::WriteTempFile("residuals.csv", "");
  const Outcome r = RunCli("identify " + Data("quick_release.yaml") + " -o " + scenario +
                           " --report " + report + " --residuals " + residuals);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const std::string text = testing::ReadFile(scenario);
  EXPECT_THAT(text, StartsWith("# estimated by musclesim identify from "));
  EXPECT_THAT(text, HasSubstr("model.passive.slack_length is not: its column is zero"));
  // the header's estimate is the file's value, and the file loads as a scenario; the data
  // were made with f_iso = 100 N and 20 um noise: the estimate is near 100 (within 0.2 N,
  // some 6 of its standard errors)
  const auto at = text.find("#   model.f_iso = ") + 18;
  const double f_iso = std::stod(text.substr(at, text.find(' ', at) - at));
  const Scenario estimated = LoadScenario(scenario);
  const ModelParams& model = estimated.models.at("model").spec.params;
  EXPECT_EQ(model.f_iso, f_iso);
  EXPECT_NEAR(f_iso, 100.0, 0.2);
  EXPECT_EQ(model.passive.slack_length, 0.11);  // the start: not identifiable
  EXPECT_EQ(RunCli("run " + scenario + " -o - --quiet").exit_code, 0);
  EXPECT_THAT(testing::ReadFile(report), HasSubstr("| model.f_iso | 100 | 80 | "));
  // 251 measured lengths, one residual row each
  const std::string csv = testing::ReadFile(residuals);
  EXPECT_THAT(csv, StartsWith("series,output,t,measured,model,residual,standardised\n"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 252);
}

TEST(IdentifySeriesCli, TheDesignRanksWithoutData) {
  const std::string data = testing::WriteTempFile(
      "plan.yaml", "scenario: " + testing::ScenarioPath("quick_release.yaml") +
                       "\nseries:\n  - noise: {length: 2.0e-5}\nparameters:\n"
                       "  - {path: model.passive.slack_length}\n  - {path: model.f_iso}\n");
  const Outcome r = RunCli("identify " + data + " --design");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("| 1 | model.f_iso | 100 |"));
  EXPECT_THAT(r.out, HasSubstr("| 2 | model.passive.slack_length | 0.105 | not determined |"));
  EXPECT_THAT(r.out, HasSubstr("251 measured values"));  // the scenario's grid, 0 to 0.25 s
}

TEST(IdentifySeriesCli, BadInputExitsTwoNamingWhereAndWhy) {
  const std::string data = testing::WriteTempFile(
      "data.yaml", "scenario: " + testing::ScenarioPath("quick_release.yaml") +
                       "\nseries:\n  - {csv: " + Data("quick_release_length.csv") +
                       ", noise: {length: -1}}\nparameters:\n  - {path: model.f_iso}\n");
  Outcome r = RunCli("identify " + data);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(data + ":3:"));  // the series entry's line
  EXPECT_THAT(r.err, HasSubstr("series[0].noise.length = -1"));
  EXPECT_THAT(r.err, HasSubstr("must be > 0"));

  const std::string unknown = testing::WriteTempFile(
      "unknown.yaml", "scenario: " + testing::ScenarioPath("quick_release.yaml") +
                          "\nseries:\n  - {csv: " + Data("quick_release_length.csv") +
                          "}\nparameters:\n  - {path: model.f_isometric}\n");
  r = RunCli("identify " + unknown);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("model.f_isometric"));

  r = RunCli("identify " + Data("quick_release.yaml") + " --design --residuals x.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--report and --residuals go with a fit, not --design"));

  // a file that does not parse, with an option of the time series' kind: its reader says so
  const std::string broken = testing::WriteTempFile("broken.yaml", "scenario: [\n");
  r = RunCli("identify " + broken + " --design");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr(broken + ":"));
  EXPECT_THAT(r.err, HasSubstr("YAML syntax error"));
}

// --design -o names an input (the scenario, a measured series, the data file): refused before
// anything is written, as the fit's outputs are. Run on copies, so a regression cannot touch
// the repository's files.
TEST(IdentifySeriesCli, TheDesignReportNeverOverwritesAnInput) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "design_over_inputs";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(std::string(MUSCLESIM_SOURCE_DIR) + "/data", dir / "data", fs::copy_options::recursive);
  fs::copy(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios", dir / "scenarios",
           fs::copy_options::recursive);
  const std::string data = (dir / "data" / "quick_release.yaml").string();
  for (const fs::path& input : {dir / "scenarios" / "quick_release.yaml",
                                dir / "data" / "quick_release_length.csv", fs::path(data)}) {
    const auto before = fs::file_size(input);
    const Outcome r = RunCli("identify " + data + " --design -o " + input.string());
    EXPECT_EQ(r.exit_code, 2) << input;
    EXPECT_THAT(r.err, HasSubstr("-o")) << r.err;
    EXPECT_EQ(fs::file_size(input), before) << input;
  }
}

TEST(IdentifySeriesCli, SetChangesTheScenarioBeforeTheFit) {
  // with the load halved the recorded lengths no longer fit f_iso = 100 N: the estimate
  // halves too (only force ratios matter without passive tension), as the header shows
  const std::string scenario = testing::WriteTempFile("estimated.yaml", "");
  const Outcome r = RunCli("identify " + Data("quick_release.yaml") + " -o " + scenario +
                           " --set load[0].after=30 --set load[1].after=-15"
                           " --set actuator.mass=0.05");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Scenario estimated = LoadScenario(scenario);
  EXPECT_NEAR(estimated.models.at("model").spec.params.f_iso, 50.0, 0.1);  // half of 100 +- 0.2
  // the --set values are in the estimated scenario
  EXPECT_EQ(estimated.nodes[kActuatorTipNode].mass, 0.05);
}

TEST(IdentifySeriesCli, TheMeasuredCurvesKindIsUnchangedAndHelpShowsBoth) {
  const Outcome curves = RunCli("identify " + Data("hill.yaml"));
  EXPECT_EQ(curves.exit_code, 0) << curves.err;
  EXPECT_THAT(curves.out, HasSubstr("velocity:"));
  const Outcome help = RunCli("identify --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.out, HasSubstr("passive:  {csv: passive.csv}"));
  EXPECT_THAT(help.out, HasSubstr("A data file with a top-level `scenario:` key"));
}

TEST(IdentifySeriesCli, PlotDrawsTheResiduals) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  const std::string residuals = testing::WriteTempFile("residuals.csv", "");
  ASSERT_EQ(RunCli("identify " + Data("tetanus_transducer.yaml") + " -o /dev/null --residuals " +
                   residuals)
                .exit_code,
            0);
  const std::string figure = testing::WriteTempFile("fit.png", "");
  std::filesystem::remove(figure);
  const Outcome r = RunCli("plot " + residuals + " -o " + figure);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(figure), 1000u);  // a PNG, not an empty file
}

}  // namespace
}  // namespace musclesim
