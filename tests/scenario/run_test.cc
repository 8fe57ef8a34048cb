// A scenario run in code (scenario/run.h) against the `musclesim run` program's CSV, and the
// canonical scenarios doing what the README says they do.
#include "musclesim/scenario/run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using testing::ColumnOf;
using testing::ScenarioPath;

// The trajectory CSV that the `musclesim run` program writes for `arguments`.
CsvTable RunProgram(const std::string& arguments, const std::string& name) {
  const std::string out = testing::WriteTempFile(name, "");
  const std::string command =
      std::string(MUSCLESIM_BINARY) + " run " + arguments + " --quiet -o " + out;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return ReadCsv(out);
}

// Every recorded length and tension of `result` equals the program's CSV to the 17
// digits the CSV keeps (both are the same double printed and parsed back).
void ExpectSameTrajectory(const RecordedRun& result, const CsvTable& csv) {
  const std::vector<double>& lengths = ColumnOf(result, "length");
  const std::vector<double>& tensions = ColumnOf(result, "tension_total");
  ASSERT_EQ(lengths.size(), csv.rows.size());
  ASSERT_EQ(tensions.size(), csv.rows.size());
  const int length = csv.Find("length"), tension = csv.Find("tension_total");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    ASSERT_EQ(lengths[i], csv.Number(i, length)) << "row " << i;
    ASSERT_EQ(tensions[i], csv.Number(i, tension)) << "row " << i;
  }
}

TEST(RunScenario, FileRunInCodeEqualsTheProgramsCsv) {
  const RecordedRun result = RunScenario(LoadScenario(ScenarioPath("concentric.yaml")));
  EXPECT_EQ(result.stats.status, RunStatus::kCompleted);
  ExpectSameTrajectory(result, RunProgram(ScenarioPath("concentric.yaml"), "file.csv"));
}

TEST(RunScenario, ValueChangedInCodeEqualsTheSameValueSetOnTheCommandLine) {
  Scenario scenario = LoadScenario(ScenarioPath("concentric.yaml"));
  // the step load's value after the switch-on, written into the network's load on the tip
  scenario.loads.at(0).load.force.after = 55.0;
  const RecordedRun result = RunScenario(scenario);
  ExpectSameTrajectory(
      result, RunProgram(ScenarioPath("concentric.yaml") + " --set load[0].after=55", "set.csv"));
}

TEST(RunScenario, ABadOverrideIsAnInputError) {
  EXPECT_THROW(LoadScenario(ScenarioPath("concentric.yaml"), {"model.velocity.n=0"}), InputError);
}

// docs/guide/scenarios.md: what each run shows, checked on the shipped files.
TEST(RunScenario, CanonicalScenariosDoWhatTheReadmeSays) {
  // concentric: "a 40 N load [...] applied with full activation at 0.05 s: the actuator
  // shortens where T(x, v, 1) = 40 N, slowing as it leaves L_opt"
  const RunResult concentric = testing::RunActuator(LoadScenario(ScenarioPath("concentric.yaml")));
  ASSERT_EQ(concentric.stats.status, RunStatus::kCompleted);
  double previous_v = INFINITY;
  for (const TrajectoryPoint& p : concentric.trajectory) {
    if (p.t < 0.1) continue;  // past the acceleration that follows the step at 0.05 s
    EXPECT_GT(p.sample.shortening_velocity, 0.0) << p.t;
    // T balances the load but for inertia, m |dv/dt| <= 0.1 kg x 2 m/s^2 = 0.2 N here
    EXPECT_NEAR(p.sample.tension.total, 40.0, 0.5) << p.t;
    if (p.sample.length < 0.095) {  // below L_opt: ever slower
      EXPECT_LT(p.sample.shortening_velocity, previous_v) << p.t;
      previous_v = p.sample.shortening_velocity;
    }
  }
  EXPECT_LT(previous_v, INFINITY);  // it did leave L_opt

  // eccentric: "a 150 N load: it lengthens (v < 0) with the active tension above f_iso,
  // until the passive element holds the load"
  const RunResult eccentric = testing::RunActuator(LoadScenario(ScenarioPath("eccentric.yaml")));
  ASSERT_EQ(eccentric.stats.status, RunStatus::kCompleted);
  // (when the passive element catches it, it rebounds for ~10 ms before settling)
  double peak_active = 0.0;
  for (const TrajectoryPoint& p : eccentric.trajectory) {
    if (p.t <= 0.05) continue;
    if (p.sample.tension.passive > 0.5 * 150.0) break;  // the passive element takes over
    EXPECT_LT(p.sample.shortening_velocity, 0.0) << p.t;
    peak_active = std::max(peak_active, p.sample.tension.active);
  }
  EXPECT_GT(peak_active, 100.0);
  const ActuatorSample& end = eccentric.trajectory.back().sample;
  // held: the passive element carries most of the load, and the rest is still (below the
  // 1e-3 m/s phase tolerance: "isometric" in the CSV)
  EXPECT_GT(end.tension.passive, 0.5 * 150.0);
  EXPECT_LT(std::abs(end.shortening_velocity), 1e-3);

  // sine_load: "a 60 +- 50 N, 2 Hz load on the active actuator: concentric and eccentric
  // phases alternate" (three periods: at least two of each)
  const Scenario sine = LoadScenario(ScenarioPath("sine_load.yaml"));
  const RunResult run = testing::RunActuator(sine);
  // the CSV's isometric band, 1e-3 m/s
  const double tolerance = sine.PhaseTolerance(kActuatorElement);
  int concentric_spells = 0, eccentric_spells = 0;
  double last = 0.0;  // sign of the last spell that left the isometric band
  for (const TrajectoryPoint& p : run.trajectory) {
    const double v = p.sample.shortening_velocity;
    if (v > tolerance && last <= 0.0) {
      ++concentric_spells;
      last = 1.0;
    } else if (v < -tolerance && last >= 0.0) {
      ++eccentric_spells;
      last = -1.0;
    }
  }
  EXPECT_GE(concentric_spells, 2);
  EXPECT_GE(eccentric_spells, 2);
}

}  // namespace
}  // namespace musclesim
