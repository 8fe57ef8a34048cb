#include "musclesim/sweep/sweep.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/sweep/sweep_file.h"
#include "musclesim/sweep/sweep_mpi.h"
#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_sorted_summary.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A sweep file next to a copy of a canonical scenario, so that `base` resolves.
std::string WriteSweep(const std::string& name, const std::string& body,
                       const std::string& base = "concentric.yaml") {
  const std::string scenario =
      testing::WriteTempFile(name + "_base.yaml", testing::ReadFile(testing::ScenarioPath(base)));
  return testing::WriteTempFile(
      name + ".yaml", "base: " + std::filesystem::path(scenario).filename().string() + "\n" + body);
}

TEST(Sweep, GridIsTheCartesianProductLastAxisFastest) {
  const SweepPlan plan = LoadSweep(WriteSweep("grid", R"(mode: grid
parameters:
  model.velocity.n: [1, 2, 3]
  load[0].after: {from: 10.0, to: 30.0, count: 3}
metrics: [final_length]
)"));
  ASSERT_EQ(PointCount(plan.spec), 9);
  EXPECT_THAT(PointValues(plan.spec, 0), ElementsAre("1", "10"));
  EXPECT_THAT(PointValues(plan.spec, 1), ElementsAre("1", "20"));
  EXPECT_THAT(PointValues(plan.spec, 5), ElementsAre("2", "30"));
  EXPECT_THAT(PointValues(plan.spec, 8), ElementsAre("3", "30"));
  EXPECT_THAT(PointOverrides(plan.spec, 3), ElementsAre("model.velocity.n=2", "load[0].after=10"));
}

TEST(Sweep, LogScaleIsExactAtTheEndsAndGeometricBetween) {
  const SweepPlan plan = LoadSweep(WriteSweep("log", R"(parameters:
  model.velocity.epsilon: {from: 3.0e-6, to: 7.0e-2, count: 6, scale: log}
metrics: [final_length]
)"));
  ASSERT_EQ(PointCount(plan.spec), 6);
  EXPECT_EQ(std::stod(PointValues(plan.spec, 0)[0]), 3.0e-6);
  EXPECT_EQ(std::stod(PointValues(plan.spec, 5)[0]), 7.0e-2);
  const double ratio = std::pow(7.0e-2 / 3.0e-6, 1.0 / 5.0);
  for (long i = 1; i < 6; ++i) {
    // the values are printed with 17 significant digits: a ratio of two is exact to ~1e-16,
    // and pow/log rounding in the grid adds a few ulps
    EXPECT_NEAR(
        std::stod(PointValues(plan.spec, i)[0]) / std::stod(PointValues(plan.spec, i - 1)[0]),
        ratio, 1e-12 * ratio);
  }
}

TEST(Sweep, ZipPairsAxesAndRejectsUnequalLengths) {
  const SweepPlan plan = LoadSweep(WriteSweep("zip", R"(mode: zip
parameters:
  model.velocity.n: [1, 2, 3]
  load[0].after: {from: 10.0, to: 30.0, count: 3}
metrics: [final_length]
)"));
  ASSERT_EQ(PointCount(plan.spec), 3);
  EXPECT_THAT(PointValues(plan.spec, 2), ElementsAre("3", "30"));
  EXPECT_THAT(
      [] {
        LoadSweep(WriteSweep("zip_bad", R"(mode: zip
parameters:
  model.velocity.n: [1, 2, 3]
  load[0].after: [10, 20]
metrics: [final_length]
)"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("parameters.load[0].after = 2 values (")));
}

TEST(Sweep, RandomDrawsAreReproducibleAndInRange) {
  const std::string body = R"(mode: random
samples: 200
seed: SEED
parameters:
  load[0].after: {from: 10.0, to: 90.0}
  model.velocity.epsilon: {from: 1.0e-6, to: 1.0e-2, scale: log}
  solver.method: [bdf, adams]
metrics: [final_length]
)";
  const auto with_seed = [&](const std::string& seed) {
    std::string text = body;
    text.replace(text.find("SEED"), 4, seed);
    return LoadSweep(WriteSweep("random_" + seed, text));
  };
  const SweepPlan a = with_seed("1"), again = with_seed("1"), other = with_seed("2");
  ASSERT_EQ(PointCount(a.spec), 200);
  std::set<std::string> methods;
  int differing = 0;
  double log_mean = 0.0;
  for (long i = 0; i < 200; ++i) {
    const std::vector<std::string> v = PointValues(a.spec, i);
    EXPECT_EQ(v, PointValues(again.spec, i));
    differing += v != PointValues(other.spec, i);
    const double load = std::stod(v[0]), eps = std::stod(v[1]);
    EXPECT_GE(load, 10.0);
    EXPECT_LT(load, 90.0);
    EXPECT_GE(eps, 1e-6);
    EXPECT_LT(eps, 1e-2);
    log_mean += std::log10(eps) / 200;
    methods.insert(v[2]);
  }
  EXPECT_EQ(differing, 200);
  EXPECT_EQ(methods, (std::set<std::string>{"adams", "bdf"}));
  // log-uniform on [-6, -2] decades: mean -4, standard error 1.15 / sqrt(200) = 0.08; 0.4 is
  // 5 standard errors, which a fixed seed either passes always or never
  EXPECT_NEAR(log_mean, -4.0, 0.4);
}

TEST(Sweep, EveryPointIsValidatedBeforeAnythingRunsNamingTheAxis) {
  // the axis is at line 3, column 3 of the sweep file (after `base:` and `parameters:`)
  EXPECT_THAT(
      [] {
        LoadSweep(
            WriteSweep("bad_path", "parameters:\n  model.speed.n: [1, 2]\nmetrics: [work]\n"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr(
          "bad_path.yaml:3:3: axis model.speed.n = 1 makes point 0 (model.speed.n=1) an invalid "
          "scenario: axis model.speed.n=1: model.speed does not exist")));
  EXPECT_THAT(
      [] {
        LoadSweep(WriteSweep("bad_value",
                             "parameters:\n  model.velocity.n: [3, fast]\nmetrics: [work]\n"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr(
          "bad_value.yaml:3:3: axis model.velocity.n = fast makes point 1 (model.velocity.n=fast) "
          "an invalid scenario: model.velocity.n = fast (axis): must be a number")));
  EXPECT_THAT(
      [] {
        LoadSweep(
            WriteSweep("bad_metric", "parameters:\n  model.velocity.n: [3]\nmetrics: [speed]\n"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("metrics[0] = speed (")));
  EXPECT_THAT(
      [] {
        LoadSweep(WriteSweep("no_target",
                             "parameters:\n  model.velocity.n: [3]\nmetrics: [time_to_length]\n"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("needs metric_options.target_length")));
  EXPECT_THAT(
      [] {
        LoadSweep(WriteSweep(
            "bad_mode", "mode: spiral\nparameters:\n  model.velocity.n: [3]\nmetrics: [work]\n"));
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("mode = spiral (")));
}

TEST(Sweep, AnAxisValueErrorNamesTheAxisValuePointAndTheAxisLine) {
  // the second axis, at line 4 column 3, is the culprit of point 2 = (n=1, epsilon=-1). A
  // numeric axis naming a number of the base sets it through its parameter handle: the rule
  // is the handle's ParameterError, with no "(axis)"
  const std::string sweep = WriteSweep("axis_error", R"(parameters:
  model.velocity.n: [1, 3]
  model.velocity.epsilon: [1.0e-3, 2.0e-3, -1, 3.0e-3]
metrics: [work]
)");
  EXPECT_EQ(testing::InputErrorOf(sweep, [&] { LoadSweep(sweep); }),
            "FILE:4:3: axis model.velocity.epsilon = -1 makes point 2 (model.velocity.n=1, "
            "model.velocity.epsilon=-1) an invalid scenario: model.velocity.epsilon = -1: must "
            "be between 1e-12 v_max and v_max = 1 [m/s] (smaller: too stiff to integrate in "
            "double precision; larger: the regularisation replaces the power law)");
}

TEST(Sweep, AnErrorInTheBaseScenarioNamesTheBaseFileLineAndColumn) {
  // a bad value in the base file, on a line no axis touches
  std::string text = testing::ReadFile(testing::ScenarioPath("concentric.yaml"));
  const std::string good = "epsilon: 1.0e-3", bad = "epsilon: -1.0e-3";
  const std::size_t at = text.find(good);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, good.size(), bad);
  // its position, counted here from the text: 1-based line, and the column of the value
  const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  const std::size_t column = at - text.rfind('\n', at) + std::string("epsilon: ").size();
  const std::string base = testing::WriteTempFile("bad_base.yaml", text);
  const std::string sweep = testing::WriteTempFile(
      "bad_base_sweep.yaml", "base: " + std::filesystem::path(base).filename().string() +
                                 "\nparameters:\n  load[0].after: [10, 20]\nmetrics: [work]\n");
  const std::string message = testing::InputErrorOf(sweep, [&] { LoadSweep(sweep); });
  EXPECT_THAT(message, HasSubstr(base +
                                 " (the base scenario of the sweep FILE) is not a valid "
                                 "scenario: model.velocity.epsilon = -0.001 (" +
                                 base + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                 "): must be between 1e-12 v_max"));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("FILE:1:1")));
}

TEST(Sweep, APointInvalidOnlyInCombinationIsToldSo) {
  // each value is valid alone (with the base's other values), not 0.19 m against 0.15 m
  const std::string sweep = WriteSweep("combination", R"(parameters:
  initial.length: [0.1, 0.19]
  limits.max_length: [0.2, 0.15]
metrics: [work]
)");
  // (both axes set through handles: the rule is the scenario's check of its limits)
  EXPECT_THAT(testing::InputErrorOf(sweep, [&] { LoadSweep(sweep); }),
              HasSubstr("FILE:3:3: point 3 (initial.length=0.19, limits.max_length=0.15) is not "
                        "a valid scenario, though each of its values is valid alone: "
                        "limits.max_length = 0.15: must be above initial.length = 0.19 [m]"));
}

TEST(Sweep, SeedAndSamplesAreForRandomModeOnly) {
  const std::string grid =
      WriteSweep("grid_seed", "seed: 3\nparameters:\n  model.velocity.n: [3]\nmetrics: [work]\n");
  EXPECT_EQ(testing::InputErrorOf(grid, [&] { LoadSweep(grid); }),
            "seed = 3 (FILE:2:7): is for mode random only (this sweep is grid)");
  const std::string zip =
      WriteSweep("zip_samples",
                 "mode: zip\nsamples: 5\nparameters:\n  model.velocity.n: [3]\nmetrics: [work]\n");
  EXPECT_EQ(testing::InputErrorOf(zip, [&] { LoadSweep(zip); }),
            "samples = 5 (FILE:3:10): is for mode random only (this sweep is zip)");
}

TEST(Sweep, RandomModeRequiresASeed) {
  const std::string sweep = WriteSweep(
      "no_seed",
      "mode: random\nsamples: 5\nparameters:\n  model.velocity.n: [3]\nmetrics: [work]\n");
  EXPECT_THAT(testing::InputErrorOf(sweep, [&] { LoadSweep(sweep); }),
              HasSubstr("seed (FILE:1:1): missing required key"));
}

TEST(Sweep, RefusesMoreThanTheMaximumPointsBeforeAllocatingThem) {
  // 1000 x 1000 x 1001 values, and 1e6^4 (which overflows 64 bits): refused from the counts
  const std::string over = WriteSweep("over", R"(parameters:
  load[0].after: {from: 10.0, to: 90.0, count: 1000}
  actuator.mass: {from: 0.05, to: 0.5, count: 1000}
  model.velocity.epsilon: {from: 1.0e-4, to: 1.0e-2, count: 1001}
metrics: [work]
)");
  EXPECT_EQ(testing::InputErrorOf(over, [&] { LoadSweep(over); }),
            "parameters = 1000 x 1000 x 1001 = 1001000000 points (FILE:3:3): a sweep may have at "
            "most 1e9 points: a running sweep keeps a bit per point in memory and about 150 bytes "
            "per point on disk (150 GB at 1e9)");
  const std::string huge = WriteSweep("huge", R"(parameters:
  load[0].after: {from: 10.0, to: 90.0, count: 1000000}
  actuator.mass: {from: 0.05, to: 0.5, count: 1000000}
  model.velocity.epsilon: {from: 1.0e-4, to: 1.0e-2, count: 1000000}
  actuator.damping: {from: 0.0, to: 1.0, count: 1000000}
metrics: [work]
)");
  EXPECT_THAT(testing::InputErrorOf(huge, [&] { LoadSweep(huge); }),
              HasSubstr("= more than 9e18 points (FILE:3:3): a sweep may have at most 1e9 points"));
}

std::string SweepOf(long points_per_axis) {
  return "parameters:\n  load[0].after: {from: 10.0, to: 90.0, count: " +
         std::to_string(points_per_axis) +
         "}\n  model.velocity.n: [1, 3]\nmetrics: [final_length, min_length, max_length, "
         "peak_tension, mean_shortening_velocity, final_shortening_velocity, work, "
         "time_to_length]\nmetric_options: {window: [0.1, 0.2], target_length: 0.095}\n";
}

// Records every progress report; asks to stop once `stop_after` rows are in (never if < 0).
class ProgressLog : public SweepObserver {
 public:
  explicit ProgressLog(long stop_after = -1) : stop_after_(stop_after) {}
  void OnProgress(long done, long total) override { calls.emplace_back(done, total); }
  void OnNotice(const std::string& message) override { notices.push_back(message); }
  bool StopRequested() override {
    if (stop_after_ < 0 || calls.empty() || calls.back().first < stop_after_) return false;
    if (stopped_at < 0) stopped_at = calls.back().first;
    return true;
  }
  std::vector<std::pair<long, long>> calls;  // (done, total) per call [points]
  std::vector<std::string> notices;
  long stopped_at = -1;  // rows in when it first asked to stop [points]

 private:
  long stop_after_;
};

TEST(SweepRunner, OneAndTwoJobsGiveTheSameSummary) {
  const SweepPlan plan = LoadSweep(WriteSweep("jobs", SweepOf(10)));
  SweepRunOptions options;
  options.jobs = 1;
  options.output = testing::WriteTempFile("jobs1.csv", "");
  std::filesystem::remove(options.output);
  const SweepOutcome one = RunSweep(plan, options);
  const std::string first = options.output;
  options.jobs = 2;
  options.output = testing::WriteTempFile("jobs2.csv", "");
  const SweepOutcome two = RunSweep(plan, options);
  EXPECT_EQ(one.points, 20);
  EXPECT_EQ(two.ran, 20);
  EXPECT_EQ(one.failed, 0);
  EXPECT_EQ(testing::SummaryWithoutWallTime(first),
            testing::SummaryWithoutWallTime(options.output));
  EXPECT_FALSE(std::filesystem::exists(options.output + ".partial"));
}

std::vector<std::string> LinesOf(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The first line of the partial file a sweep starts (its signature), from a sweep stopped
// before any point ran.
std::string SignatureLine(const SweepPlan& plan, const std::string& name) {
  SweepRunOptions options;
  options.output = testing::WriteTempFile(name + "_signature.csv", "");
  std::filesystem::remove(options.output + ".partial");
  ProgressLog stop_at_once(0);
  options.observer = &stop_at_once;
  RunSweep(plan, options);
  const std::vector<std::string> lines = LinesOf(options.output + ".partial");
  std::filesystem::remove(options.output + ".partial");
  return lines.empty() ? "" : lines[0];
}

TEST(SweepRunner, ResumeFromAPartialSummaryGivesTheSameResult) {
  const SweepPlan plan = LoadSweep(WriteSweep("resume", SweepOf(8)));
  SweepRunOptions options;
  options.output = testing::WriteTempFile("full.csv", "");
  RunSweep(plan, options);
  const std::string full = testing::SummaryWithoutWallTime(options.output);

  // what an interrupted sweep leaves: signature, header, some rows in any order, a cut-off line
  const std::vector<std::string> lines = LinesOf(options.output);
  const std::string resumed = testing::WriteTempFile("resumed.csv", "");
  std::filesystem::remove(resumed);
  std::ofstream(resumed + ".partial") << SignatureLine(plan, "resume") << "\n"
                                      << lines[0] << "\n"
                                      << lines[7] << "\n"
                                      << lines[2] << "\n"
                                      << lines[12] << "\n"
                                      << lines[5].substr(0, 9);
  options.output = resumed;
  EXPECT_THAT([&] { RunSweep(plan, options); },  // no silent restart over it
              ::testing::ThrowsMessage<InterruptedSweepError>(HasSubstr(
                  "resumed.csv.partial exists: an earlier sweep was interrupted. Resume the "
                  "sweep")));
  options.resume = true;
  ProgressLog log;
  options.observer = &log;
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_EQ(outcome.resumed, 3);
  EXPECT_EQ(outcome.ran, 13);
  EXPECT_TRUE(log.notices.empty());  // a line cut short by a kill is expected, not malformed
  // the first report, before anything runs, counts the three complete rows kept
  ASSERT_FALSE(log.calls.empty());
  EXPECT_EQ(log.calls.front(), std::make_pair(3L, 16L));
  EXPECT_EQ(testing::SummaryWithoutWallTime(resumed), full);
}

TEST(SweepRunner, ResumeDropsMalformedRowsAndRunsTheirPointsAgain) {
  const SweepPlan plan = LoadSweep(WriteSweep("malformed", SweepOf(4)));  // 8 points
  SweepRunOptions options;
  options.output = testing::WriteTempFile("reference.csv", "");
  RunSweep(plan, options);
  const std::vector<std::string> lines = LinesOf(options.output);  // header, rows 0..7
  ASSERT_EQ(lines.size(), 9u);
  const std::string full = testing::SummaryWithoutWallTime(options.output);

  // two good rows (points 0 and 6) among rows no resume may trust
  std::string row3_other_value = lines[4];
  row3_other_value.replace(row3_other_value.find(','), 3, ",11");  // its load, 36.66... N, edited
  std::string row2_bad_status = lines[3];
  row2_bad_status.replace(row2_bad_status.find(",ok,"), 4, ",done,");
  std::string row5_beyond = lines[6];
  row5_beyond.replace(0, 1, "8");  // index 8 of 8 points
  const std::string partial = options.output = testing::WriteTempFile("malformed.csv", "");
  std::filesystem::remove(partial);
  std::ofstream(partial + ".partial") << SignatureLine(plan, "malformed") << "\n"
                                      << lines[0] << "\n"
                                      << lines[1] << "\n"         // point 0, kept
                                      << "1,zzz\n"                // too few fields
                                      << "x" << lines[2] << "\n"  // an index that is not a number
                                      << lines[1] << "\n"         // point 0 again
                                      << row2_bad_status << "\n"
                                      << row3_other_value << "\n"
                                      << row5_beyond << "\n"
                                      << lines[7] << "\n";  // point 6, kept
  options.resume = true;
  ProgressLog log;
  options.observer = &log;
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_EQ(outcome.resumed, 2);
  EXPECT_EQ(outcome.ran, 6);
  ASSERT_EQ(log.notices.size(), 1u);
  EXPECT_THAT(log.notices[0],
              HasSubstr("malformed.csv.partial: dropped 6 malformed rows (line 4: "
                        "2 fields, expected 16; line 5: index 'x1' is not a number"));
  EXPECT_THAT(log.notices[0], HasSubstr("line 6: a second row for point 0"));
  EXPECT_THAT(log.notices[0], HasSubstr("; ...); their points run again"));
  EXPECT_EQ(testing::SummaryWithoutWallTime(partial), full);
  EXPECT_THAT(testing::ReadFile(partial), ::testing::Not(HasSubstr("zzz")));
}

TEST(SweepRunner, ResumeRefusesThePartialOfAnotherSweepSayingWhatChanged) {
  // a sweep of loads 5..95 N interrupted, then its range edited to 50..95 N
  const std::string base = testing::WriteTempFile(
      "edited_base.yaml", testing::ReadFile(testing::ScenarioPath("concentric.yaml")));
  const auto sweep_file = [&](const std::string& range, const std::string& metrics) {
    return testing::WriteTempFile("edited.yaml",
                                  "base: " + std::filesystem::path(base).filename().string() +
                                      "\nparameters:\n  load[0].after: {from: " + range +
                                      ", to: 95.0, count: 19}\nmetrics: [" + metrics + "]\n");
  };
  SweepRunOptions options;
  options.output = testing::WriteTempFile("edited.csv", "");
  std::filesystem::remove(options.output + ".partial");
  ProgressLog stop(3);
  options.observer = &stop;
  options.jobs = 1;
  ASSERT_TRUE(RunSweep(LoadSweep(sweep_file("5.0", "work")), options).interrupted);
  options.observer = nullptr;
  options.resume = true;
  const std::string refused =
      "edited.csv.partial belongs to a different sweep (base scenario, "
      "axes or metrics changed): ";
  EXPECT_THAT([&] { RunSweep(LoadSweep(sweep_file("50.0", "work")), options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr(refused + "the axes changed")));
  EXPECT_THAT([&] { RunSweep(LoadSweep(sweep_file("5.0", "peak_tension")), options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr(refused + "the metrics changed")));
  std::ofstream(base, std::ios::app) << "# edited\n";
  EXPECT_THAT(
      [&] { RunSweep(LoadSweep(sweep_file("5.0", "work")), options); },
      ::testing::ThrowsMessage<InputError>(HasSubstr(refused + "the base scenario changed")));
  // a partial file of an older musclesim, header first, has no signature
  const std::string header = LinesOf(options.output + ".partial")[1];
  std::ofstream(options.output + ".partial") << header << "\n";
  EXPECT_THAT([&] { RunSweep(LoadSweep(sweep_file("5.0", "work")), options); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(refused + "its first line is not a sweep's signature")));
}

TEST(SweepRunner, ASecondSweepOnTheSameOutputIsRefusedWhileTheFirstRuns) {
  const SweepPlan plan = LoadSweep(WriteSweep("busy", SweepOf(300)));
  SweepRunOptions first;
  first.jobs = 1;
  first.output = testing::WriteTempFile("busy.csv", "");
  std::filesystem::remove(first.output + ".partial");
  // the first sweep stops once the second has been tried
  std::atomic<bool> tried{false};
  class StopWhenTold : public SweepObserver {
   public:
    StopWhenTold(std::atomic<long>& rows, std::atomic<bool>& tried) : rows_(rows), tried_(tried) {}
    void OnProgress(long done, long) override { rows_ = done; }
    bool StopRequested() override { return tried_; }

   private:
    std::atomic<long>& rows_;
    std::atomic<bool>& tried_;
  };
  std::atomic<long> rows{0};
  StopWhenTold observer(rows, tried);
  first.observer = &observer;
  SweepOutcome outcome;
  std::thread running([&] { outcome = RunSweep(plan, first); });
  while (rows < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));

  SweepRunOptions second = first;
  second.observer = nullptr;
  for (const bool resume : {false, true}) {
    second.resume = resume;
    EXPECT_THAT([&] { RunSweep(plan, second); },
                ::testing::ThrowsMessage<InputError>(HasSubstr(
                    "busy.csv.partial is in use by a running sweep writing the same output")));
  }
  tried = true;
  running.join();
  ASSERT_TRUE(outcome.interrupted);
  // once the first has stopped, its file is free to resume
  ProgressLog stop_at_once(0);
  second.observer = &stop_at_once;
  EXPECT_EQ(RunSweep(plan, second).resumed, outcome.ran);
}

TEST(SweepRunner, AFailingPointIsMarkedAndTheRestGoesOn) {
  const SweepPlan plan = LoadSweep(WriteSweep(
      "failing",
      "parameters:\n  solver.max_steps: [10000000, 20, 10000000]\nmetrics: [final_length]\n",
      "isometric.yaml"));
  SweepRunOptions options;
  options.output = testing::WriteTempFile("failing.csv", "");
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_EQ(outcome.failed, 1);
  std::ifstream in(options.output);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_THAT(lines[1], HasSubstr("0,10000000,ok,0.0990"));
  EXPECT_THAT(lines[2], HasSubstr("1,20,failed,,"));
  EXPECT_THAT(lines[2], HasSubstr("CV_TOO_MUCH_WORK"));
  EXPECT_THAT(lines[3], HasSubstr("2,10000000,ok,"));
}

TEST(SweepRunner, ObserverSeesProgressFromZeroUpToTheTotal) {
  const SweepPlan plan = LoadSweep(WriteSweep("observed", SweepOf(6)));
  SweepRunOptions options;
  options.jobs = 2;
  options.output = testing::WriteTempFile("observed.csv", "");
  ProgressLog log;
  options.observer = &log;
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_FALSE(outcome.interrupted);
  ASSERT_GE(log.calls.size(), 2u);
  EXPECT_EQ(log.calls.front().first, 0);  // reported before any point ran
  EXPECT_EQ(log.calls.back().first, 12);  // 6 loads x 2 exponents
  for (std::size_t i = 0; i < log.calls.size(); ++i) {
    EXPECT_EQ(log.calls[i].second, 12);
    if (i > 0) {
      EXPECT_GE(log.calls[i].first, log.calls[i - 1].first);
    }
  }
}

TEST(SweepRunner, AStopRequestEndsOnlyTheSweepOfItsObserver) {
  // two sweeps at once in one process: one observer stops after 3 rows, the other never;
  // the first has far more points than it could run before its observer is asked
  const SweepPlan long_plan = LoadSweep(WriteSweep("long_sweep", SweepOf(300)));
  const SweepPlan plan = LoadSweep(WriteSweep("two_sweeps", SweepOf(20)));
  SweepRunOptions stopped, completed;
  stopped.jobs = completed.jobs = 1;
  stopped.output = testing::WriteTempFile("stopped.csv", "");
  completed.output = testing::WriteTempFile("completed.csv", "");
  std::filesystem::remove(stopped.output);
  std::filesystem::remove(stopped.output + ".partial");
  std::filesystem::remove(completed.output + ".partial");
  ProgressLog stopper(3), watcher;
  stopped.observer = &stopper;
  completed.observer = &watcher;

  SweepOutcome first, second;
  std::thread other([&] { second = RunSweep(plan, completed); });
  first = RunSweep(long_plan, stopped);
  other.join();

  EXPECT_TRUE(first.interrupted);
  ASSERT_GE(stopper.stopped_at, 3);
  // rows already in when it asked, plus at most the points handed to its thread and not yet
  // counted: the pool is topped up with 16 points per thread when fewer than 4 wait, and
  // nothing more is handed once the stop is asked for, however the threads are scheduled
  EXPECT_GE(first.ran, stopper.stopped_at);
  EXPECT_LE(first.ran, stopper.stopped_at + 16 + 4);
  EXPECT_LT(first.ran, 300);
  EXPECT_FALSE(std::filesystem::exists(stopped.output));
  const std::string partial = testing::ReadFile(stopped.output + ".partial");
  // the signature line, the header, the rows
  EXPECT_EQ(partial.find("# sweep "), 0u);
  EXPECT_EQ(partial.find("\n" + SummaryHeader(long_plan.spec) + "\n"), partial.find('\n'));
  EXPECT_EQ(std::count(partial.begin(), partial.end(), '\n'), first.ran + 2);

  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(second.ran, 40);
  EXPECT_EQ(watcher.calls.back().first, 40);
  EXPECT_FALSE(std::filesystem::exists(completed.output + ".partial"));
}

// The concentric scenario cut to 0.06 s (activation and load come at 0.05 s): cheap points.
std::string ShortBase(const std::string& name) {
  std::string text = testing::ReadFile(testing::ScenarioPath("concentric.yaml"));
  const std::string end = "end: 0.5}";
  text.replace(text.find(end), end.size(), "end: 0.06}");
  return testing::WriteTempFile(name + "_short_base.yaml", text);
}

std::string SweepOn(const std::string& base, const std::string& name, const std::string& body) {
  return testing::WriteTempFile(
      name + ".yaml", "base: " + std::filesystem::path(base).filename().string() + "\n" + body);
}

TEST(SweepRunner, ASweepOfTheMaximumSizeStartsRunningAtOnce) {
  // 1000 x 1000 x 1000 points: a few thousand are validated up front, the rest as they run
  const std::string sweep = SweepOn(ShortBase("maximum"), "maximum", R"(parameters:
  load[0].after: {from: 10.0, to: 90.0, count: 1000}
  actuator.mass: {from: 0.05, to: 0.5, count: 1000}
  model.velocity.epsilon: {from: 1.0e-4, to: 1.0e-2, count: 1000, scale: log}
metrics: [work]
)");
  const SweepPlan plan = LoadSweep(sweep);
  ASSERT_EQ(PointCount(plan.spec), 1000000000L);
  EXPECT_TRUE(plan.spec.scenarios.empty());
  EXPECT_THAT(PointValues(plan.spec, 999999999L), ElementsAre("90", "0.5", "0.01"));
  SweepRunOptions options;
  options.jobs = 2;
  options.output = testing::WriteTempFile("maximum.csv", "");
  std::filesystem::remove(options.output + ".partial");
  ProgressLog stop_after_five(5);
  options.observer = &stop_after_five;
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_TRUE(outcome.interrupted);
  EXPECT_GE(outcome.ran, 5);
  EXPECT_EQ(stop_after_five.calls.front(), std::make_pair(0L, 1000000000L));
  const std::vector<std::string> lines = LinesOf(options.output + ".partial");
  ASSERT_GE(lines.size(), 7u);  // signature, header, five rows or more
  EXPECT_NE(std::find_if(
                lines.begin(), lines.end(),
                [](const std::string& line) { return line.rfind("0,10,0.05,1e-04,ok,", 0) == 0; }),
            lines.end());
  std::filesystem::remove(options.output + ".partial");
}

TEST(SweepRunner, AnInvalidPointOfALargeSweepIsAnInvalidRow) {
  // 3000 x 2 x 2 = 12,000 points, more than are validated up front. Point 3 (initial
  // length 0.19 m, max_length 0.15 m) is invalid, though both values are valid alone: the
  // sample validated up front (every value of every axis, the others at their first) misses it.
  const std::string body = R"(parameters:
  load[0].after: {from: 10.0, to: 90.0, count: COUNT}
  initial.length: [0.1, 0.19]
  limits.max_length: [0.2, 0.15]
metrics: [work]
)";
  const std::string base = ShortBase("large_invalid");
  const auto with_count = [&](const std::string& count) {
    std::string text = body;
    text.replace(text.find("COUNT"), 5, count);
    return SweepOn(base, "large_invalid_" + count, text);
  };
  // a small sweep of the same values is refused before anything runs
  EXPECT_THROW(LoadSweep(with_count("10")), InputError);
  const SweepPlan plan = LoadSweep(with_count("3000"));
  ASSERT_EQ(PointCount(plan.spec), 12000);
  SweepRunOptions options;
  options.jobs = 1;
  options.output = testing::WriteTempFile("large_invalid.csv", "");
  std::filesystem::remove(options.output + ".partial");
  ProgressLog stop_after_eight(8);
  options.observer = &stop_after_eight;
  const SweepOutcome outcome = RunSweep(plan, options);
  // rows come in order from one thread: points 0 to 7 at least, one in four of them invalid
  // (those with index 3 mod 4: the last two axes at their second values)
  EXPECT_GE(outcome.ran, 8);
  EXPECT_EQ(outcome.failed, 0);
  long expected_invalid = 0;
  bool seen = false;
  const std::vector<std::string> lines = LinesOf(options.output + ".partial");
  for (std::size_t r = 2; r < lines.size(); ++r) {
    const std::string& line = lines[r];
    const long index = std::stol(line.substr(0, line.find(',')));
    const bool invalid = index % 4 == 3;
    expected_invalid += invalid;
    EXPECT_THAT(line, HasSubstr(invalid ? ",invalid," : ",ok,")) << line;
    if (index != 3) continue;
    seen = true;
    EXPECT_THAT(line, ::testing::StartsWith("3,10,0.19,0.15,invalid,,0,0,0,\""));
    EXPECT_THAT(line, HasSubstr("point 3 (load[0].after=10, initial.length=0.19, "
                                "limits.max_length=0.15) is not a valid scenario, though each of "
                                "its values is valid alone: limits.max_length = 0.15: must be "
                                "above initial.length = 0.19 [m]"));
  }
  EXPECT_EQ(outcome.invalid, expected_invalid);
  EXPECT_TRUE(seen);
  std::filesystem::remove(options.output + ".partial");
}

TEST(SweepRunner, EveryShippedSweepRunsEveryPoint) {
  // each sweep in scenarios/, its number of points counted here from its axes
  const std::map<std::string, long> points = {
      {"force_velocity_sweep.yaml", 19},     // 19 loads
      {"millard_benchmark_sweep.yaml", 11},  // activations 0, 0.1, ..., 1
      {"stiffness_sweep.yaml", 20},          // 4 exponents x 5 widths
  };
  std::set<std::string> shipped;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios")) {
    const std::string name = entry.path().filename().string();
    if (name.find("sweep") != std::string::npos) shipped.insert(name);
  }
  std::set<std::string> known;
  for (const auto& [name, count] : points) known.insert(name);
  EXPECT_EQ(shipped, known) << "a sweep was added to scenarios/: give its point count here";
  for (const auto& [name, count] : points) {
    SCOPED_TRACE(name);
    const SweepPlan plan = LoadSweep(testing::ScenarioPath(name));
    SweepRunOptions options;
    options.output = testing::WriteTempFile(name + ".csv", "");
    std::filesystem::remove(options.output + ".partial");
    const SweepOutcome outcome = RunSweep(plan, options);
    EXPECT_EQ(outcome.points, count);
    EXPECT_EQ(outcome.failed, 0);
    EXPECT_EQ(outcome.invalid, 0);
    EXPECT_FALSE(outcome.interrupted);
    const std::vector<std::string> lines = LinesOf(options.output);
    ASSERT_EQ(static_cast<long>(lines.size()), count + 1);
    const std::size_t status = plan.spec.axes.size() + 1;  // the field after index and the axes
    for (long i = 0; i < count; ++i) {
      const std::string& line = lines[static_cast<std::size_t>(i + 1)];
      EXPECT_EQ(line.substr(0, line.find(',')), std::to_string(i));
      std::size_t at = 0;
      for (std::size_t f = 0; f < status; ++f) at = line.find(',', at) + 1;
      EXPECT_EQ(line.substr(at, 3), "ok,") << line;
    }
  }
}

TEST(SweepSortedSummary, RowsBeyondTheMemoryBudgetAreMergedFromSortedRuns) {
  // 5000 rows in a scrambled order, sorted with room for about 100 rows at a time
  const long n = 5000;
  std::vector<long> order(n);
  // 2711 is prime
  for (long i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = (i * 2711) % n;
  std::string text = "# first line\nindex,value\n";
  for (const long i : order) text += std::to_string(i) + ",row " + std::to_string(i) + "\n";
  const std::string partial = testing::WriteTempFile("rows.partial", text);
  const std::string output = testing::WriteTempFile("rows.csv", "");
  WriteSortedSummary(partial, 2, "index,value", output, 100 * 80);
  const std::vector<std::string> lines = LinesOf(output);
  ASSERT_EQ(static_cast<long>(lines.size()), n + 1);
  EXPECT_EQ(lines[0], "index,value");
  for (long i = 0; i < n; ++i) {
    EXPECT_EQ(lines[static_cast<std::size_t>(i + 1)],
              std::to_string(i) + ",row " + std::to_string(i));
  }
  // no sorted run is left behind
  for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir())) {
    EXPECT_EQ(entry.path().string().find(partial + ".sort"), std::string::npos);
  }
}

TEST(SweepMpi, RefusesToRunWithoutAnInitialisedMpi) {
  // this test program never calls MPI_Init (and may be built without MPI at all)
  const SweepPlan plan = LoadSweep(WriteSweep("no_mpi", SweepOf(2)));
  SweepRunOptions options;
  options.output = testing::WriteTempFile("no_mpi.csv", "");
  EXPECT_THROW(RunSweepMpi(plan, options), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(options.output + ".partial"));
}

}  // namespace
}  // namespace musclesim
