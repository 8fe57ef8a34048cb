// End-to-end tests of `musclesim sweep`: exit codes, interruption and resume, MPI.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <utility>
#include <thread>

#include "support/scenario_files.h"

extern char** environ;

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// Starts the command line with `args`, standard error to `err`; returns the process id.
pid_t Start(const std::vector<std::string>& args, const std::string& err) {
  std::vector<std::string> all = {"/bin/sh", "-c", ""};
  std::string command = "exec";
  for (const std::string& a : args) command += " '" + a + "'";
  all[2] = command + " 2>'" + err + "' >/dev/null";
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv.data(), environ), 0);
  return pid;
}

int Finish(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int RunToEnd(const std::vector<std::string>& args, const std::string& err) {
  return Finish(Start(args, err));
}

std::string Sweep(const std::string& name, long loads) {
  const std::string base = testing::WriteTempFile(
      name + "_base.yaml", testing::ReadFile(testing::ScenarioPath("concentric.yaml")));
  return testing::WriteTempFile(
      name + ".yaml",
      "base: " + std::filesystem::path(base).filename().string() +
          "\nparameters:\n  load[0].after: {from: 10.0, to: 90.0, count: " + std::to_string(loads) +
          "}\n  model.velocity.n: [1, 3]\nmetrics: [final_length, peak_tension, work]\n");
}

long Lines(const std::string& path) {
  const std::string text = testing::ReadFile(path);
  return std::count(text.begin(), text.end(), '\n');
}

TEST(SweepCli, InterruptedSweepResumesToTheUninterruptedResult) {
  const std::string sweep = Sweep("interrupt", 1500);  // 3000 points, seconds of work
  const std::string dir = ::testing::TempDir();
  const std::string reference = dir + "sweep_reference.csv", resumed = dir + "sweep_resumed.csv";
  std::filesystem::remove(resumed);
  std::filesystem::remove(resumed + ".partial");

  const pid_t pid = Start({MUSCLESIM_BINARY, "sweep", sweep, "-o", resumed, "--jobs", "2"},
                          dir + "sweep_interrupt.err");
  // interrupt once some rows are safely in the partial file
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (Lines(resumed + ".partial") < 50 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, SIGINT);
  EXPECT_EQ(Finish(pid), 130);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_interrupt.err"),
              HasSubstr(".partial; run again with --resume to finish"));
  EXPECT_FALSE(std::filesystem::exists(resumed));
  const long kept = Lines(resumed + ".partial") - 2;  // the signature and the header
  EXPECT_GE(kept, 49);
  EXPECT_LT(kept, 3000);

  // without --resume the partial file is not overwritten
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", resumed}, dir + "sweep_refuse.err"),
            2);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_refuse.err"), HasSubstr("Pass --resume"));

  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", resumed, "--resume"},
                     dir + "sweep_resume.err"),
            0);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_resume.err"),
              HasSubstr("3000 points (" + std::to_string(3000 - kept) + " run now, " +
                        std::to_string(kept) + " resumed), 0 failed"));
  EXPECT_FALSE(std::filesystem::exists(resumed + ".partial"));
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", reference, "--quiet"},
                     dir + "sweep_reference.err"),
            0);
  EXPECT_EQ(testing::SummaryWithoutWallTime(resumed), testing::SummaryWithoutWallTime(reference));
}

TEST(SweepCli, FailedPointsExitThree) {
  const std::string base = testing::WriteTempFile(
      "exit3_base.yaml", testing::ReadFile(testing::ScenarioPath("isometric.yaml")));
  const std::string sweep = testing::WriteTempFile(
      "exit3.yaml",
      "base: " + std::filesystem::path(base).filename().string() +
          "\nparameters:\n  solver.max_steps: [20, 10000000]\nmetrics: [final_length]\n");
  const std::string err = ::testing::TempDir() + "sweep_exit3.err";
  EXPECT_EQ(
      RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", ::testing::TempDir() + "exit3.csv"}, err),
      3);
  EXPECT_THAT(testing::ReadFile(err), HasSubstr("2 points (2 run now, 0 resumed), 1 failed"));
}

TEST(SweepCli, InvalidSweepExitsTwo) {
  const std::string sweep = testing::WriteTempFile(
      "exit2.yaml", "base: nowhere.yaml\nparameters: {a: [1]}\nmetrics: [work]\n");
  const std::string err = ::testing::TempDir() + "sweep_exit2.err";
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", "-"}, err), 2);
  EXPECT_THAT(testing::ReadFile(err), HasSubstr("nowhere.yaml: cannot open the file"));
}

// Starts a 3000-point sweep on `output` and returns its process once `rows` rows are in.
pid_t StartAndWaitForRows(const std::string& sweep, const std::string& output, long rows,
                          const std::string& err) {
  std::filesystem::remove(output);
  std::filesystem::remove(output + ".partial");
  const pid_t pid = Start({MUSCLESIM_BINARY, "sweep", sweep, "-o", output, "--jobs", "1"}, err);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (Lines(output + ".partial") < rows + 2 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return pid;
}

TEST(SweepCli, ResumeRefusesAnEditedSweepAndDropsMalformedRows) {
  const std::string sweep = Sweep("edited", 1500);
  const std::string dir = ::testing::TempDir(), output = dir + "sweep_edited.csv";
  const pid_t pid = StartAndWaitForRows(sweep, output, 20, dir + "sweep_edited_first.err");
  kill(pid, SIGINT);
  ASSERT_EQ(Finish(pid), 130);

  // the same file with the load range 10..90 N changed to 50..90 N
  const std::string text = testing::ReadFile(sweep);
  std::string edited = text;
  edited.replace(edited.find("from: 10.0"), 10, "from: 50.0");
  std::ofstream(sweep) << edited;
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", output, "--resume"},
                     dir + "sweep_edited.err"),
            2);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_edited.err"),
              HasSubstr("sweep_edited.csv.partial belongs to a different sweep (base scenario, "
                        "axes or metrics changed): the axes changed since it was written"));

  // back to the original sweep, with a malformed row in its partial file
  std::ofstream(sweep) << text;
  std::ofstream(output + ".partial", std::ios::app) << "1,zzz\n";
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", output, "--resume", "--quiet"},
                     dir + "sweep_malformed.err"),
            0);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_malformed.err"),
              HasSubstr("sweep_edited.csv.partial: dropped 1 malformed row (line "));
  EXPECT_THAT(testing::ReadFile(dir + "sweep_malformed.err"),
              HasSubstr(": 2 fields, expected 11); their points run again"));
  EXPECT_EQ(Lines(output), 3001);
  EXPECT_THAT(testing::ReadFile(output), ::testing::Not(HasSubstr("zzz")));
}

TEST(SweepCli, ASecondSweepOnAnOutputInUseSaysSoAndAKilledOneLeavesNoLock) {
  const std::string sweep = Sweep("busy", 1500);
  const std::string dir = ::testing::TempDir(), output = dir + "sweep_busy.csv";
  const pid_t pid = StartAndWaitForRows(sweep, output, 5, dir + "sweep_busy_first.err");
  // frozen, so that it is still running (and holding its lock) whatever the machine's load
  kill(pid, SIGSTOP);
  for (const char* resume : {"--quiet", "--resume"}) {
    EXPECT_EQ(
        RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", output, resume}, dir + "sweep_busy.err"),
        2);
    EXPECT_THAT(testing::ReadFile(dir + "sweep_busy.err"),
                HasSubstr("sweep_busy.csv.partial is in use by a running sweep writing the same "
                          "output"));
  }
  // killed outright, the first sweep leaves its partial file, and the kernel drops its lock
  kill(pid, SIGKILL);
  EXPECT_EQ(Finish(pid), 128 + SIGKILL);
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", output}, dir + "sweep_busy.err"), 2);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_busy.err"),
              HasSubstr("sweep_busy.csv.partial exists: an earlier sweep was interrupted. Pass "
                        "--resume"));
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", output, "--resume", "--quiet"},
                     dir + "sweep_busy.err"),
            0);
  EXPECT_EQ(Lines(output), 3001);
}

// A sweep file beside a copy of the concentric scenario, with `replace` done in that copy.
std::string SweepWithBase(const std::string& name, const std::string& body,
                          const std::string& find = "", const std::string& replace = "") {
  std::string text = testing::ReadFile(testing::ScenarioPath("concentric.yaml"));
  if (!find.empty()) text.replace(text.find(find), find.size(), replace);
  const std::string base = testing::WriteTempFile(name + "_base.yaml", text);
  return testing::WriteTempFile(
      name + ".yaml", "base: " + std::filesystem::path(base).filename().string() + "\n" + body);
}

// Runs `musclesim sweep` on `sweep` to `output` and returns (exit code, standard error).
std::pair<int, std::string> SweepExit(const std::string& sweep, const std::string& name) {
  const std::string dir = ::testing::TempDir();
  const int code =
      RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + name + ".csv", "--quiet"},
               dir + name + ".err");
  return {code, testing::ReadFile(dir + name + ".err")};
}

TEST(SweepCli, SeedAndSamplesOutsideRandomModeAndRandomWithoutSeedExitTwo) {
  const auto seed =
      SweepExit(SweepWithBase("cli_seed",
                              "seed: 3\nparameters:\n  load[0].after: [10, 20]\nmetrics: [work]\n"),
                "cli_seed");
  EXPECT_EQ(seed.first, 2);
  EXPECT_THAT(seed.second,
              HasSubstr("cli_seed.yaml:2:7): is for mode random only (this sweep is grid)"));
  const auto samples = SweepExit(
      SweepWithBase("cli_samples",
                    "samples: 3\nparameters:\n  load[0].after: [10, 20]\nmetrics: [work]\n"),
      "cli_samples");
  EXPECT_EQ(samples.first, 2);
  EXPECT_THAT(samples.second, HasSubstr("samples = 3 ("));
  EXPECT_THAT(samples.second, HasSubstr("is for mode random only"));
  const auto unseeded =
      SweepExit(SweepWithBase("cli_unseeded",
                              "mode: random\nsamples: 3\nparameters:\n  load[0].after: {from: 10, "
                              "to: 20}\nmetrics: [work]\n"),
                "cli_unseeded");
  EXPECT_EQ(unseeded.first, 2);
  EXPECT_THAT(unseeded.second, HasSubstr("seed ("));
  EXPECT_THAT(unseeded.second, HasSubstr("cli_unseeded.yaml:1:1): missing required key"));
}

TEST(SweepCli, ErrorsNameTheBaseFileOrTheAxisThatCausedThem) {
  // epsilon on line 19 of concentric.yaml: `  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}`
  const auto base = SweepExit(
      SweepWithBase("cli_base_error", "parameters:\n  load[0].after: [10, 20]\nmetrics: [work]\n",
                    "epsilon: 1.0e-3", "epsilon: -1.0e-3"),
      "cli_base_error");
  EXPECT_EQ(base.first, 2);
  EXPECT_THAT(base.second, HasSubstr("cli_base_error_base.yaml (the base scenario of the sweep "));
  EXPECT_THAT(base.second, HasSubstr("model.velocity.epsilon = -0.001 ("));
  EXPECT_THAT(base.second,
              HasSubstr("cli_base_error_base.yaml:19:41): must be between 1e-12 v_max"));
  const auto axis = SweepExit(
      SweepWithBase(
          "cli_axis_error",
          "parameters:\n  load[0].after: [10, 20]\n  model.velocity.n: [3, 0]\nmetrics: [work]\n"),
      "cli_axis_error");
  EXPECT_EQ(axis.first, 2);
  // a numeric axis sets its number through the parameter handle: the rule is the handle's,
  // with no "(axis)"
  EXPECT_THAT(axis.second, HasSubstr("cli_axis_error.yaml:4:3: axis model.velocity.n = 0 makes "
                                     "point 1 (load[0].after=10, model.velocity.n=0) an invalid "
                                     "scenario: model.velocity.n = 0: must be an integer"));
}

TEST(SweepCli, TooManyPointsExitTwoAndInvalidPointsOfALargeSweepExitTwoAfterIt) {
  const auto over = SweepExit(
      SweepWithBase("cli_over",
                    "parameters:\n  load[0].after: {from: 10, to: 90, count: 1000000000}\n"
                    "  model.velocity.n: [1, 3]\nmetrics: [work]\n"),
      "cli_over");
  EXPECT_EQ(over.first, 2);
  EXPECT_THAT(over.second, HasSubstr("parameters = 1000000000 x 2 = 2000000000 points ("));
  EXPECT_THAT(over.second, HasSubstr("a sweep may have at most 1e9 points"));

  // 3000 x 2 x 2 points of a 0.06 s run: too many to validate up front; the points with
  // initial length 0.19 m and max_length 0.15 m (one in four) are invalid when they run
  const std::string sweep = SweepWithBase(
      "cli_large",
      "parameters:\n  load[0].after: {from: 10, to: 90, count: 3000}\n"
      "  initial.length: [0.1, 0.19]\n  limits.max_length: [0.2, 0.15]\nmetrics: [work]\n",
      "end: 0.5}", "end: 0.06}");
  const std::string dir = ::testing::TempDir();
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + "cli_large.csv"},
                     dir + "cli_large.err"),
            2);
  EXPECT_THAT(testing::ReadFile(dir + "cli_large.err"),
              HasSubstr("12000 points (12000 run now, 0 resumed), 0 failed, 3000 invalid"));
  EXPECT_THAT(testing::ReadFile(dir + "cli_large.err"),
              HasSubstr("3000 of 12000 points are not valid scenarios (status invalid in "));
  EXPECT_EQ(Lines(dir + "cli_large.csv"), 12001);
}

#ifdef MUSCLESIM_MPIEXEC
TEST(SweepCli, TwoMpiRanksGiveTheSingleProcessSummary) {
  const std::string sweep = Sweep("mpi", 60);
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + "sweep_single.csv", "--jobs",
                      "1", "--quiet"},
                     dir + "sweep_single.err"),
            0);
  ASSERT_EQ(RunToEnd({MUSCLESIM_MPIEXEC, "-n", "2", "--oversubscribe", "--allow-run-as-root",
                      MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + "sweep_mpi.csv", "--quiet"},
                     dir + "sweep_mpi.err"),
            0)
      << testing::ReadFile(dir + "sweep_mpi.err");
  EXPECT_EQ(Lines(dir + "sweep_mpi.csv"), 121);
  EXPECT_EQ(testing::SummaryWithoutWallTime(dir + "sweep_mpi.csv"),
            testing::SummaryWithoutWallTime(dir + "sweep_single.csv"));
}
#endif

}  // namespace
}  // namespace musclesim
