// The note `musclesim run` prints when an actuator moved faster than its model's v_max
// (beyond it g(v) is the paper's power law extrapolated, docs/model.md section 4), against the
// fastest shortening or lengthening in the run's own CSV: lengthening counts like shortening,
// a run within v_max gets no note, and a network's note names its actuator.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/number_format.h"
#include "support/cli_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

struct ProgramRun {
  testing::CliOutcome outcome;
  testing::CsvText csv;
};

// `musclesim run PATH --set ...` (not quiet: the notes are on standard error), its CSV read.
ProgramRun RunWith(const std::string& path, const std::vector<std::string>& sets) {
  const std::string csv = testing::TempPath("run.csv");
  std::string arguments = "run '" + path + "' -o '" + csv + "'";
  for (const std::string& set : sets) arguments += " --set '" + set + "'";
  ProgramRun run{testing::RunMusclesim(arguments), {}};
  EXPECT_EQ(run.outcome.exit_code, 0) << run.outcome.err;
  run.csv = testing::ReadCsv(csv);
  return run;
}

// The largest |value| of column `name` of the CSV.
double Fastest(const testing::CsvText& csv, const std::string& name) {
  const int column = csv.Column(name);
  EXPECT_GE(column, 0) << name;
  double fastest = 0.0;
  for (const auto& row : csv.rows) {
    fastest = std::max(
        fastest, std::abs(std::strtod(row[static_cast<std::size_t>(column)].c_str(), nullptr)));
  }
  return fastest;
}

TEST(PeakSpeed, LengtheningCountsLikeShortening) {
  // 250 N on the fully active actuator (f_iso 100 N): it lengthens where g = 2.5, at
  // (1.5)^3 = 3.4 v_max on the power law, until the passive element takes the load
  const ProgramRun run = RunWith(testing::FixturePath("actuator.yaml"), {"load[0].value=250"});
  const double fastest = Fastest(run.csv, "shortening_velocity");
  ASSERT_GT(fastest, 1.0);
  // the fastest is a lengthening: the velocity's most negative value
  const int v = run.csv.Column("shortening_velocity");
  double lowest = 0.0;
  for (const auto& row : run.csv.rows) {
    lowest = std::min(lowest, std::strtod(row[static_cast<std::size_t>(v)].c_str(), nullptr));
  }
  EXPECT_EQ(-lowest, fastest);
  EXPECT_THAT(run.outcome.err,
              HasSubstr("note: |shortening velocity| reached " + FormatNumber(fastest) +
                        " m/s, beyond v_max = 1 m/s, where g(v) is the paper's power law "
                        "extrapolated"));
}

TEST(PeakSpeed, ARunWithinVmaxHasNoNote) {
  // the concentric contraction shortens at a fraction of v_max
  const ProgramRun run = RunWith(testing::ScenarioPath("concentric.yaml"), {});
  EXPECT_LT(Fastest(run.csv, "shortening_velocity"), 1.0);
  EXPECT_THAT(run.outcome.err, Not(HasSubstr("beyond v_max")));
}

TEST(PeakSpeed, ANetworksNoteNamesEachActuatorBeyondItsOwnVmax) {
  // the extensor starts shortening at 0.2 m/s: beyond a v_max of 0.1 m/s (its epsilon moved
  // below it); the flexor keeps v_max = 1 m/s. Each actuator is judged by its own fastest
  // speed in the CSV against its own model's v_max
  const ProgramRun run =
      RunWith(testing::FixturePath("every_part.yaml"),
              {"models.extensor.velocity.v_max=0.1", "models.extensor.velocity.epsilon=0.01"});
  ASSERT_GT(Fastest(run.csv, "extensor.shortening_velocity"), 0.1);
  for (const auto& [name, v_max] : {std::pair{"extensor", 0.1}, std::pair{"flexor", 1.0}}) {
    const double fastest = Fastest(run.csv, std::string(name) + ".shortening_velocity");
    const std::string note = "note: |shortening velocity| of " + std::string(name) + " reached " +
                             FormatNumber(fastest) + " m/s, beyond v_max = " + FormatNumber(v_max) +
                             " m/s";
    if (fastest > v_max) {
      EXPECT_THAT(run.outcome.err, HasSubstr(note));
    } else {
      EXPECT_THAT(run.outcome.err, Not(HasSubstr(std::string("of ") + name)));
    }
  }
}

}  // namespace
}  // namespace musclesim
