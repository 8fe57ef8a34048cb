// Sweeps made in code (sweep/sweep_points.h): a Scenario built in code swept through its
// parameter handles (ParameterPoints), and points made by a function (FunctionPoints), each
// with its summary kept in memory, against the same sweep read from files and written as CSV:
// the same axis values and the same metrics to the last bit, and not a file written by the
// sweeps in memory. Then the refusals of points made in code.
#include "musclesim/sweep/sweep_points.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/sweep/sweep_file.h"
#include "musclesim/sweep/sweep_runner.h"
#include "support/canonical_scenarios.h"
#include "support/cli_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The sweep of every test here: the concentric contraction (scenarios/concentric.yaml) under
// three loads and at two maximum velocities, every metric.
const std::vector<Metric> kMetrics = {Metric::kFinalLength,
                                      Metric::kMinLength,
                                      Metric::kMaxLength,
                                      Metric::kPeakTension,
                                      Metric::kMeanShorteningVelocity,
                                      Metric::kFinalShorteningVelocity,
                                      Metric::kWork,
                                      Metric::kTimeToLength};

constexpr const char* kSweepBody = R"(parameters:
  load[0].after: {from: 20.0, to: 60.0, count: 3}
  model.velocity.v_max: [0.8, 1.2]
metrics: [final_length, min_length, max_length, peak_tension, mean_shortening_velocity,
          final_shortening_velocity, work, time_to_length]
metric_options: {window: [0.1, 0.2], target_length: 0.095}
)";

// The same sweep in code: its axes, metrics and options as the file above gives them.
SweepSpec SpecInCode(const std::string& base_name) {
  SweepSpec spec;
  spec.source = "sweep in code";
  spec.base = base_name;
  spec.form = ScenarioForm::kActuator;
  SweepAxis load;
  load.path = "load[0].after";
  load.from = 20.0;
  load.to = 60.0;
  load.count = 3;
  SweepAxis v_max;
  v_max.path = "model.velocity.v_max";
  v_max.values = {"0.8", "1.2"};
  v_max.numbers = {0.8, 1.2};
  spec.axes = {load, v_max};
  spec.metrics = kMetrics;
  spec.metric_options.window_start = 0.1;
  spec.metric_options.window_end = 0.2;
  spec.metric_options.target_length = 0.095;
  return spec;
}

// Every file below `dir` with its size: what a run may have left there.
std::map<std::string, std::uintmax_t> Listing(const std::string& dir) {
  std::map<std::string, std::uintmax_t> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    files[entry.path().string()] = entry.is_regular_file() ? entry.file_size() : 0;
  }
  return files;
}

// Runs `plan` with its summary in memory, from a working directory and a TMPDIR of its own
// (ctest runs other tests beside this one, writing files of their own in the shared temporary
// directory): the rows, after checking that not a file appeared in either.
std::vector<SweepRow> RunInMemory(const SweepPlan& plan, const std::string& name) {
  const std::string dir = testing::TempPath(name + "_in_memory");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path previous = std::filesystem::current_path();
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string saved_tmpdir = tmpdir != nullptr ? tmpdir : "";
  std::filesystem::current_path(dir);
  setenv("TMPDIR", dir.c_str(), 1);
  SweepRunOptions options;  // output empty: the summary in memory
  options.jobs = 2;
  const SweepOutcome outcome = RunSweep(plan, options);
  std::filesystem::current_path(previous);
  if (tmpdir != nullptr) {
    setenv("TMPDIR", saved_tmpdir.c_str(), 1);
  } else {
    unsetenv("TMPDIR");
  }
  for (const auto& [file, size] : Listing(dir)) {
    ADD_FAILURE() << "the sweep in memory wrote " << file << " (" << size << " bytes)";
  }
  EXPECT_EQ(outcome.points, 6);
  EXPECT_EQ(outcome.ran, 6);
  EXPECT_EQ(outcome.failed, 0);
  EXPECT_EQ(outcome.invalid, 0);
  return outcome.rows;
}

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// A summary line without its wall_seconds field (the third last), which no run repeats.
std::string WithoutWallTime(const std::string& line) {
  const auto last = line.rfind(',');
  const auto wall = line.rfind(',', last - 1);
  return line.substr(0, wall) + line.substr(last);
}

// The summary CSV of a sweep read from files: its fields, and its lines as written.
struct Summary {
  testing::CsvText csv;
  std::vector<std::string> lines;
};

// The sweep read from files (a copy of scenarios/concentric.yaml as its base) and run into a
// summary CSV, read back.
Summary SweepFromFiles(const std::string& name) {
  const std::string dir = testing::TempPath(name + "_files");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(testing::ScenarioPath("concentric.yaml"), dir + "/base.yaml");
  const std::string sweep = dir + "/sweep.yaml";
  std::ofstream(sweep) << "base: base.yaml\n" << kSweepBody;
  SweepRunOptions options;
  options.output = dir + "/summary.csv";
  options.jobs = 2;
  const SweepOutcome outcome = RunSweep(LoadSweep(sweep, 1), options);
  EXPECT_EQ(outcome.ran, 6);
  Summary summary{testing::ReadCsv(options.output), {}};
  std::istringstream text(testing::ReadText(options.output));
  for (std::string line; std::getline(text, line);) summary.lines.push_back(line);
  return summary;
}

// Every row of `rows` holds the file sweep's axis values and, in every metric, the very
// double its summary CSV writes (17 significant digits read back exactly; an empty field a
// metric with no value).
void ExpectSameSummary(const std::vector<SweepRow>& rows, const Summary& summary) {
  const testing::CsvText& csv = summary.csv;
  ASSERT_EQ(rows.size(), csv.rows.size());
  ASSERT_EQ(summary.lines.size(), rows.size() + 1);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const SweepRow& row = rows[i];
    const std::vector<std::string>& fields = csv.rows[i];
    EXPECT_EQ(row.index, static_cast<long>(i));
    EXPECT_EQ(std::to_string(row.index), fields[0]);
    ASSERT_EQ(row.values.size(), 2u);
    EXPECT_EQ(row.values[0], fields[static_cast<std::size_t>(csv.Column("load[0].after"))]);
    EXPECT_EQ(row.values[1], fields[static_cast<std::size_t>(csv.Column("model.velocity.v_max"))]);
    EXPECT_EQ(row.status, RowStatus::kOk);
    EXPECT_EQ(fields[static_cast<std::size_t>(csv.Column("status"))], "ok");
    ASSERT_EQ(row.metrics.size(), kMetrics.size());
    for (std::size_t m = 0; m < kMetrics.size(); ++m) {
      const std::string name(ToString(kMetrics[m]));
      const int column = csv.Column(name);
      ASSERT_GE(column, 0) << name;
      const std::string& text = fields[static_cast<std::size_t>(column)];
      if (text.empty()) {
        EXPECT_TRUE(std::isnan(row.metrics[m])) << name;
      } else {
        EXPECT_TRUE(SameBits(row.metrics[m], std::strtod(text.c_str(), nullptr)))
            << name << ": " << row.metrics[m] << " in memory, " << text << " in the file";
      }
    }
    EXPECT_EQ(std::to_string(row.steps), fields[static_cast<std::size_t>(csv.Column("steps"))]);
    // and the line the file holds for it, but for the wall time
    EXPECT_EQ(WithoutWallTime(FormatSummaryRow(row)), WithoutWallTime(summary.lines[i + 1]));
  }
}

TEST(SweepPoints, ParameterPointsOfAScenarioInCodeAreTheFileSweep) {
  const Scenario base = testing::ConcentricScenario();
  const SweepSpec spec = SpecInCode("concentric in code");
  const SweepPlan plan = PlanSweep(spec, ParameterPoints(base, spec), 1);
  EXPECT_TRUE(plan.spec.kept);  // six points: validated and kept up front
  ASSERT_EQ(plan.spec.scenarios.size(), 6u);
  // point 4 (the grid's last axis fastest): the third load, the first v_max
  EXPECT_EQ(plan.spec.scenarios[4].loads[0].load.force.after, 60.0);
  EXPECT_EQ(plan.spec.scenarios[4].models.at("model").spec.params.velocity.v_max, 0.8);
  const Summary from_files = SweepFromFiles("parameters");
  EXPECT_EQ(SummaryHeader(plan.spec), from_files.lines[0]);
  ExpectSameSummary(RunInMemory(plan, "parameters"), from_files);
}

TEST(SweepPoints, FunctionPointsMadeFromTheSpecAreTheFileSweep) {
  // each point built anew from the single actuator's spec, not from a base and handles
  const ScenarioMaker make = [](long, const std::vector<double>& values) {
    ActuatorScenarioSpec spec = testing::ConcentricSpec();
    spec.loads[0].force.after = values[0];
    spec.model.params.velocity.v_max = values[1];
    return MakeActuatorScenario(spec);
  };
  const SweepSpec spec = SpecInCode("concentric made by a function");
  const SweepPlan plan = PlanSweep(spec, FunctionPoints(make), 1);
  ExpectSameSummary(RunInMemory(plan, "function"), SweepFromFiles("function"));
}

TEST(SweepPoints, AnAxisNamingNoNumberOfTheBaseIsRefused) {
  SweepSpec spec = SpecInCode("concentric in code");
  spec.axes[1].path = "model.velocity.top_speed";
  EXPECT_THAT([&] { ParameterPoints(testing::ConcentricScenario(), spec); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("model.velocity.top_speed")));
}

TEST(SweepPoints, AnInvalidPointIsNamedBeforeAnythingRuns) {
  // through handles: a load of 20 N is fine, a maximum velocity below epsilon is not
  SweepSpec spec = SpecInCode("concentric in code");
  spec.axes[1].values = {"0.8", "1e-4"};
  spec.axes[1].numbers = {0.8, 1e-4};
  EXPECT_THAT([&] { PlanSweep(spec, ParameterPoints(testing::ConcentricScenario(), spec), 1); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("axis model.velocity.v_max = 1e-4 makes point 1 (load[0].after=20, "
                            "model.velocity.v_max=1e-4) an invalid scenario: ")));
  // a function's ParameterError: the point, its values and the error
  const ScenarioMaker make = [](long index, const std::vector<double>&) {
    if (index == 2) throw ParameterError("actuator.mass", "-1", "must be > 0");
    return testing::ConcentricScenario();
  };
  EXPECT_THAT([&] { PlanSweep(SpecInCode("made"), FunctionPoints(make), 1); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("point 2 (load[0].after=40, model.velocity.v_max=0.8) is not a "
                            "valid scenario: actuator.mass = -1: must be > 0")));
}

TEST(SweepPoints, ASummaryInMemoryKeepsNoTrajectories) {
  SweepSpec spec = SpecInCode("concentric in code");
  spec.trajectories = TrajectoryPolicy::kAll;
  EXPECT_THAT([&] { CheckSummaryPath(spec, ""); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("give the summary a file")));
  spec.trajectories = TrajectoryPolicy::kNone;
  EXPECT_NO_THROW(CheckSummaryPath(spec, ""));
}

// Each run's trajectory goes to SUMMARY_trajectories/INDEX.csv: an input lying there (the base
// scenario, or the sweep file itself) would be overwritten by a point's rows.
TEST(SweepPoints, NoInputMayLieWhereTheTrajectoriesGo) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "sweep_trajectory_inputs";
  fs::remove_all(dir);
  fs::create_directories(dir / "t_trajectories");
  std::ofstream(dir / "t_trajectories" / "0.csv") << "name: base\n";
  SweepSpec spec = SpecInCode("concentric in code");
  spec.trajectories = TrajectoryPolicy::kAll;
  spec.base = (dir / "t_trajectories" / "0.csv").string();
  EXPECT_THAT([&] { CheckSummaryPath(spec, (dir / "t.csv").string()); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("where the base scenario " + spec.base + " lies")));
  spec.base.clear();
  spec.source = (dir / "t_trajectories" / "1.csv").string();
  EXPECT_THAT([&] { CheckSummaryPath(spec, (dir / "t.csv").string()); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("where the sweep file")));
  // elsewhere, or with no trajectories written, nothing is refused
  EXPECT_NO_THROW(CheckSummaryPath(spec, (dir / "other.csv").string()));
  spec.trajectories = TrajectoryPolicy::kNone;
  EXPECT_NO_THROW(CheckSummaryPath(spec, (dir / "t.csv").string()));
}

}  // namespace
}  // namespace musclesim
