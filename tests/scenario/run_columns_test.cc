// A run in memory (scenario/run.h, scenario/run_columns.h) against the CSV the built program
// writes for the same scenario file: the same column names in the same order, every number
// the same double (the CSV's 17 significant digits read back exactly) and every phase the same
// word, for single actuators and networks; and the rows a run records, counted before it runs.
#include "musclesim/scenario/run_columns.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/run.h"
#include "support/cli_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

// `musclesim run PATH` with `sets` as --set, its CSV read back as text.
testing::CsvText ProgramCsv(const std::string& path, const std::vector<std::string>& sets = {}) {
  const std::string csv = testing::TempPath("run.csv");
  std::string arguments = "run '" + path + "' --quiet -o '" + csv + "'";
  for (const std::string& set : sets) arguments += " --set '" + set + "'";
  const testing::CliOutcome r = testing::RunMusclesim(arguments);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return testing::ReadCsv(csv);
}

// Every column of `run` equals the program's CSV of the same scenario.
void ExpectRunIsTheProgramsCsv(const RecordedRun& run, const testing::CsvText& csv) {
  ASSERT_EQ(run.columns.names(), csv.columns);
  ASSERT_EQ(run.values.size(), csv.columns.size());
  ASSERT_FALSE(csv.rows.empty());
  for (std::size_t c = 0; c < csv.columns.size(); ++c) {
    SCOPED_TRACE(csv.columns[c]);
    ASSERT_EQ(run.values[c].size(), csv.rows.size());
    for (std::size_t r = 0; r < csv.rows.size(); ++r) {
      const std::string& text = csv.rows[r][c];
      if (run.columns.is_phase(c)) {
        ASSERT_EQ(ToString(run.phase(c, r)), text) << "row " << r;
      } else {
        // 17 significant digits: the text reads back as the very double
        ASSERT_EQ(run.values[c][r], std::strtod(text.c_str(), nullptr)) << "row " << r;
      }
    }
  }
}

TEST(RunColumns, SingleActuatorRunEqualsTheProgramsCsv) {
  const std::string path = testing::ScenarioPath("concentric.yaml");
  const RecordedRun run = RunScenario(LoadScenario(path));
  EXPECT_EQ(run.columns.names(),
            (std::vector<std::string>{"t", "length", "shortening_velocity", "activation",
                                      "tension_passive", "tension_active", "tension_total", "load",
                                      "phase"}));
  ExpectRunIsTheProgramsCsv(run, ProgramCsv(path));
}

TEST(RunColumns, SingleActuatorWithActivationDynamicsEqualsTheProgramsCsv) {
  const std::string path = testing::ScenarioPath("twitches.yaml");
  const RecordedRun run = RunScenario(LoadScenario(path));
  EXPECT_EQ(run.columns.names()[4], "excitation");  // right after the activation
  ExpectRunIsTheProgramsCsv(run, ProgramCsv(path));
}

TEST(RunColumns, EveryStepRunEqualsTheProgramsCsv) {
  // a row per internal step: a grid the run finds as it goes, the same in both
  const std::string path = testing::FixturePath("actuator.yaml");
  const std::vector<std::string> sets = {"output.interval=steps", "time.end=0.2"};
  const Scenario scenario = LoadScenario(path, sets);
  EXPECT_EQ(ExpectedRows(scenario), 0u);  // unknown before it runs
  ExpectRunIsTheProgramsCsv(RunScenario(scenario), ProgramCsv(path, sets));
}

TEST(RunColumns, NetworkRunEqualsTheProgramsCsv) {
  // every kind of node, element and load; the phases against each actuator's own epsilon
  const std::string path = testing::FixturePath("every_part.yaml");
  ExpectRunIsTheProgramsCsv(RunScenario(LoadScenario(path)), ProgramCsv(path));
  // one phase tolerance for every actuator
  ExpectRunIsTheProgramsCsv(RunScenario(LoadScenario(path, {"output.phase_tolerance=0.1"})),
                            ProgramCsv(path, {"output.phase_tolerance=0.1"}));
}

TEST(RunColumns, ControlledNetworkRunEqualsTheProgramsCsv) {
  // the controller's columns come last: reference, measured, error, output
  const std::string path = testing::ScenarioPath("position_tracking.yaml");
  const RecordedRun run = RunScenario(LoadScenario(path, {"time.end=0.5"}));
  const std::vector<std::string>& names = run.columns.names();
  EXPECT_EQ(std::vector<std::string>(names.end() - 4, names.end()),
            (std::vector<std::string>{"position.reference", "position.measured", "position.error",
                                      "position.output"}));
  ExpectRunIsTheProgramsCsv(run, ProgramCsv(path, {"time.end=0.5"}));
}

TEST(RunColumns, ExpectedRowsAreTheRowsTheRunRecords) {
  for (const char* name : {"concentric.yaml", "mass_spring_damper.yaml", "sine_load.yaml"}) {
    SCOPED_TRACE(name);
    const Scenario scenario = LoadScenario(testing::ScenarioPath(name));
    const RecordedRun run = RunScenario(scenario);
    ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
    EXPECT_EQ(ExpectedRows(scenario), run.values[0].size());
  }
}

// every_part.yaml: 0.25 to 0.26 s every 1 ms, a span of 0.010000000000000009 s whose
// rounding error a run merges into the end; 11 rows, not ceil(span / interval) + 1 = 12
TEST(RunColumns, ExpectedRowsOfAGridFarFromZero) {
  const Scenario scenario = LoadScenario(testing::FixturePath("every_part.yaml"));
  EXPECT_EQ(ExpectedRows(scenario), RunScenario(scenario).values[0].size());
}

TEST(RunColumns, ARecorderOnTheCallersSimulationRecordsTheSameRun) {
  // RunScenario(scenario) is RunScenario(scenario, simulation, recorder) on a new Simulation;
  // a Simulation re-used for a second scenario leaves nothing of the first in it
  const Scenario concentric = LoadScenario(testing::ScenarioPath("concentric.yaml"));
  const Scenario network = LoadScenario(testing::FixturePath("every_part.yaml"));
  Simulation simulation;
  for (const Scenario* s : {&network, &concentric}) {
    const NetworkSystem system = s->Build();
    ColumnRecorder recorder(*s, system);
    recorder.Reserve(ExpectedRows(*s));
    RecordedRun run{recorder.layout(), {}, RunScenario(*s, simulation, recorder)};
    EXPECT_EQ(recorder.rows(), recorder.column(0).size());
    for (std::size_t c = 0; c < recorder.layout().size(); ++c) {
      run.values.push_back(recorder.column(c));
    }
    EXPECT_TRUE(testing::SameRecordedRun(run, RunScenario(*s)));
  }
}

TEST(RunColumns, ASingleActuatorSeenAsItsNetwork) {
  // the network's view of the single actuator: its nodes, its three elements, the tip's load
  const Scenario scenario = LoadScenario(testing::ScenarioPath("concentric.yaml"));
  const RunColumns view(scenario, scenario.Build(), ScenarioForm::kNetwork);
  EXPECT_THAT(view.names(),
              ::testing::ElementsAre("t", "ground.position", "ground.velocity", "tip.position",
                                     "tip.velocity", "actuator.length", "actuator.tension",
                                     "actuator.shortening_velocity", "actuator.activation",
                                     "actuator.tension_passive", "actuator.tension_active",
                                     "actuator.phase", "damper.length", "damper.tension",
                                     "spring.length", "spring.tension", "tip.load"));
}

}  // namespace
}  // namespace musclesim
