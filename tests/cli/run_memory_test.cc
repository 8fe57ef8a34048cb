// `musclesim run` streams its rows: its peak memory does not grow with the run's length.
#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <string>
#include <vector>

#include "support/scenario_files.h"

extern char** environ;

namespace musclesim {
namespace {

// Runs the program with `arguments` and returns its peak resident set size [KiB].
long PeakKibibytes(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), MUSCLESIM_BINARY);
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  // under AddressSanitizer freed memory waits in a quarantine of up to 256 MB, which would
  // be counted as the program's; without it the sanitized program's memory is its own
  std::vector<std::string> environment = {"ASAN_OPTIONS=quarantine_size_mb=0"};
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::string(*e).rfind("ASAN_OPTIONS=", 0) != 0) environment.emplace_back(*e);
  }
  std::vector<char*> envp;
  for (std::string& e : environment) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t child = 0;
  EXPECT_EQ(posix_spawn(&child, MUSCLESIM_BINARY, nullptr, nullptr, argv.data(), envp.data()), 0);
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(child, &status, 0, &usage), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  return usage.ru_maxrss;
}

TEST(RunMemory, PeakMemoryDoesNotGrowWithTheNumberOfRows) {
  const std::string scenario = testing::ScenarioPath("concentric.yaml");
  // 500 rows, then a million: 0.5 s at 1 ms and at 0.5 us (about 200 MB of CSV text,
  // written into /dev/null)
  const long short_run = PeakKibibytes({"run", scenario, "-o", "/dev/null", "--quiet"});
  const long long_run = PeakKibibytes(
      {"run", scenario, "-o", "/dev/null", "--quiet", "--set", "output.interval=5e-7"});
  // kept in memory the rows alone would be ~200 MB against a few MB for the program itself
  EXPECT_LT(long_run, 2 * short_run) << short_run << " KiB vs " << long_run << " KiB";
}

}  // namespace
}  // namespace musclesim
