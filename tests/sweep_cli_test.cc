// End-to-end tests of `musclesim sweep`: exit codes, interruption and resume, MPI.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
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
  const std::string base = testing::WriteTempFile(name + "_base.yaml",
      testing::ReadFile(testing::ScenarioPath("concentric.yaml")));
  return testing::WriteTempFile(name + ".yaml",
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
  const long kept = Lines(resumed + ".partial") - 1;
  EXPECT_GE(kept, 49);
  EXPECT_LT(kept, 3000);

  // without --resume the partial file is not overwritten
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", resumed}, dir + "sweep_refuse.err"), 2);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_refuse.err"), HasSubstr("Pass --resume"));

  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", resumed, "--resume"},
                     dir + "sweep_resume.err"), 0);
  EXPECT_THAT(testing::ReadFile(dir + "sweep_resume.err"),
              HasSubstr("3000 points (" + std::to_string(3000 - kept) + " run now, " +
                        std::to_string(kept) + " resumed), 0 failed"));
  EXPECT_FALSE(std::filesystem::exists(resumed + ".partial"));
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", reference, "--quiet"},
                     dir + "sweep_reference.err"), 0);
  EXPECT_EQ(testing::SummaryWithoutWallTime(resumed), testing::SummaryWithoutWallTime(reference));
}

TEST(SweepCli, FailedPointsExitThree) {
  const std::string base = testing::WriteTempFile("exit3_base.yaml",
      testing::ReadFile(testing::ScenarioPath("isometric.yaml")));
  const std::string sweep = testing::WriteTempFile("exit3.yaml",
      "base: " + std::filesystem::path(base).filename().string() +
      "\nparameters:\n  solver.max_steps: [20, 10000000]\nmetrics: [final_length]\n");
  const std::string err = ::testing::TempDir() + "sweep_exit3.err";
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", ::testing::TempDir() + "exit3.csv"}, err), 3);
  EXPECT_THAT(testing::ReadFile(err), HasSubstr("2 points (2 run now, 0 resumed), 1 failed"));
}

TEST(SweepCli, InvalidSweepExitsTwo) {
  const std::string sweep = testing::WriteTempFile("exit2.yaml", "base: nowhere.yaml\nparameters: {a: [1]}\nmetrics: [work]\n");
  const std::string err = ::testing::TempDir() + "sweep_exit2.err";
  EXPECT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", "-"}, err), 2);
  EXPECT_THAT(testing::ReadFile(err), HasSubstr("nowhere.yaml: cannot open the file"));
}

#ifdef MUSCLESIM_MPIEXEC
TEST(SweepCli, TwoMpiRanksGiveTheSingleProcessSummary) {
  const std::string sweep = Sweep("mpi", 60);
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(RunToEnd({MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + "sweep_single.csv", "--jobs", "1",
                      "--quiet"}, dir + "sweep_single.err"), 0);
  ASSERT_EQ(RunToEnd({MUSCLESIM_MPIEXEC, "-n", "2", "--oversubscribe", "--allow-run-as-root",
                      MUSCLESIM_BINARY, "sweep", sweep, "-o", dir + "sweep_mpi.csv", "--quiet"},
                     dir + "sweep_mpi.err"), 0)
      << testing::ReadFile(dir + "sweep_mpi.err");
  EXPECT_EQ(Lines(dir + "sweep_mpi.csv"), 121);
  EXPECT_EQ(testing::SummaryWithoutWallTime(dir + "sweep_mpi.csv"), testing::SummaryWithoutWallTime(dir + "sweep_single.csv"));
}
#endif

}  // namespace
}  // namespace musclesim
