#include "musclesim/io/run_scenario.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "musclesim/io/csv_table.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using testing::ScenarioPath;

// The trajectory CSV that the `musclesim run` program writes for `arguments`.
CsvTable RunProgram(const std::string& arguments, const std::string& name) {
  const std::string out = testing::WriteTempFile(name, "");
  const std::string command = std::string(MUSCLESIM_BINARY) + " run " + arguments + " --quiet -o " + out;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return ReadCsv(out);
}

// Every recorded length and tension of `result` equals the program's CSV to the 17
// digits the CSV keeps (both are the same double printed and parsed back).
void ExpectSameTrajectory(const RunResult& result, const CsvTable& csv) {
  ASSERT_EQ(result.trajectory.size(), csv.rows.size());
  const int length = csv.Find("length"), tension = csv.Find("tension_total");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    ASSERT_EQ(result.trajectory[i].sample.length, csv.Number(i, length)) << "row " << i;
    ASSERT_EQ(result.trajectory[i].sample.tension.total, csv.Number(i, tension)) << "row " << i;
  }
}

TEST(RunScenario, FileRunInCodeEqualsTheProgramsCsv) {
  const RunResult result = RunScenarioFile(ScenarioPath("concentric.yaml"));
  EXPECT_EQ(result.stats.status, RunStatus::kCompleted);
  ExpectSameTrajectory(result, RunProgram(ScenarioPath("concentric.yaml"), "file.csv"));
}

TEST(RunScenario, ValueChangedInCodeEqualsTheSameValueSetOnTheCommandLine) {
  ScenarioSpec spec = LoadScenario(ScenarioPath("concentric.yaml"));
  spec.loads.at(0).force.after = 55.0;  // the step load's value after the switch-on
  const RunResult result = RunScenario(spec);
  ExpectSameTrajectory(result, RunProgram(ScenarioPath("concentric.yaml") +
                                              " --set load[0].after=55", "set.csv"));
}

TEST(RunScenario, ABadOverrideIsAnInputError) {
  EXPECT_THROW(RunScenarioFile(ScenarioPath("concentric.yaml"), {"model.velocity.n=0"}),
               InputError);
}

}  // namespace
}  // namespace musclesim
