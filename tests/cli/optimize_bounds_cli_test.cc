// musclesim optimize on problems without a solution or too big to take: each ends in bounded
// time with a clear status or refusal. An infeasible final value (a move the muscles cannot
// make, a tension out of reach) ends with exit 3, status infeasibility_stalled and the
// constraint violated most named; optimizer.max_seconds bounds the solve; a reference that
// is no regular file or holds too many points, and a grid the process cannot hold, are
// refused when read (exit 2).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

struct Outcome {
  int exit_code;
  std::string err;
  std::string summary;
};

// `musclesim optimize problem.yaml` in `dir`, with `limit` (a shell command such as
// "ulimit -v 400000") before it.
Outcome Optimize(const std::string& dir, const std::string& problem,
                 const std::string& limit = "") {
  std::ofstream(dir + "/problem.yaml") << problem;
  std::filesystem::remove(dir + "/problem_optimum.json");
  const std::string command =
      "cd '" + dir + "' && (" +
      (limit.empty() ? "" : "export OPENBLAS_NUM_THREADS=1; " + limit + "; ") + "'" +
      MUSCLESIM_BINARY + "' optimize problem.yaml --quiet) 2> err.txt";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::ReadFile(dir + "/err.txt"),
          std::filesystem::exists(dir + "/problem_optimum.json")
              ? testing::ReadFile(dir + "/problem_optimum.json")
              : ""};
}

std::string PairDirectory() {
  const std::string dir = testing::FreshDirectory("optimize_bounds_");
  std::filesystem::copy_file(testing::ScenarioPath("antagonist_move.yaml"),
                             dir + "/antagonist_move.yaml");
  return dir;
}

// The antagonist pair's move (scenarios/antagonist_move_problem.yaml) with `finals` as its
// final values and `optimizer` as its optimizer block.
std::string Move(const std::string& finals,
                 const std::string& optimizer = "{tolerance: 1.0e-8, max_iterations: 300}",
                 int intervals = 20) {
  return "base: antagonist_move.yaml\nintervals: " + std::to_string(intervals) +
         "\ncontrols:\n"
         "  - {actuator: flexor, bounds: [0.0, 1.0], effort: {weight: 1.0, power: 2}}\n"
         "  - {actuator: extensor, bounds: [0.0, 1.0], effort: {weight: 1.0, power: 2}}\n"
         "final_values:\n" +
         finals + "optimizer: " + optimizer + "\n";
}

TEST(OptimizeBounds, AMoveTheMusclesCannotMakeEndsInfeasibleNamingItsFinalValue) {
  // the load at 0.3 m, past the wall at 0.14 m: before, 300 iterations (100 s) hovering at a
  // violation of 0.16; the stall rule ends it after 60, the last 30 no better
  const std::string dir = PairDirectory();
  // (3 intervals: each iteration cheap, the stall the same)
  const Outcome out = Optimize(dir, Move("  - {column: load.position, value: 0.3}\n"
                                         "  - {column: load.velocity, value: 0.0}\n",
                                         "{tolerance: 1.0e-8, max_iterations: 300}", 3));
  EXPECT_EQ(out.exit_code, 3) << out.err;
  EXPECT_THAT(out.summary, HasSubstr("\"status\": \"infeasibility_stalled\""));
  EXPECT_THAT(out.summary, HasSubstr("\"infeasible\": true"));
  EXPECT_THAT(out.summary, HasSubstr("\"largest_violation\": \"final_values[0] load.position: "));
  EXPECT_THAT(out.summary, HasSubstr("where 0.3 is asked"));
  // stopped by the rule, long before the iteration limit
  const std::size_t at = out.summary.find("\"iterations\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_LT(std::stoi(out.summary.substr(at + 14)), 150);
}

TEST(OptimizeBounds, ATensionOutOfReachEndsInfeasibleNamingIt) {
  const std::string dir = PairDirectory();
  const Outcome out = Optimize(dir, Move("  - {column: load.position, value: 0.075}\n"
                                         "  - {column: flexor.tension, value: 10000.0}\n",
                                         "{tolerance: 1.0e-8, max_iterations: 300}", 3));
  EXPECT_EQ(out.exit_code, 3) << out.err;
  EXPECT_THAT(out.summary, HasSubstr("\"status\": \"infeasibility_stalled\""));
  // the flexor's 100 N at full activation is what it can reach
  EXPECT_THAT(out.summary, HasSubstr("\"largest_violation\": \"final_values[1] flexor.tension: "));
  EXPECT_THAT(out.summary, HasSubstr("where 1e+04 is asked"));
}

TEST(OptimizeBounds, AFeasibleMoveIsNotCalledStalled) {
  // the shipped move, and one to the far side of the midpoint: both solved
  const std::string dir = PairDirectory();
  for (const char* position : {"0.075", "0.065"}) {
    const Outcome out =
        Optimize(dir, Move("  - {column: load.position, value: " + std::string(position) +
                           "}\n  - {column: load.velocity, value: 0.0}\n"));
    EXPECT_EQ(out.exit_code, 0) << position << ": " << out.err;
    EXPECT_THAT(out.summary, HasSubstr("\"infeasible\": false"));
  }
}

TEST(OptimizeBounds, MaxSecondsEndsTheSolveWithItsStatusAndTheFilesOfThePointReached) {
  const std::string dir = PairDirectory();
  const Outcome out = Optimize(dir, Move("  - {column: load.position, value: 0.075}\n",
                                         "{tolerance: 1.0e-8, max_seconds: 1.0e-6}"));
  EXPECT_EQ(out.exit_code, 3) << out.err;
  EXPECT_THAT(out.summary, HasSubstr("\"status\": \"maximum_seconds_exceeded\""));
  EXPECT_TRUE(std::filesystem::exists(dir + "/problem_optimum.yaml"));
  const Outcome negative =
      Optimize(dir, Move("  - {column: load.position, value: 0.075}\n", "{max_seconds: -1}"));
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_THAT(negative.err, HasSubstr("optimizer.max_seconds"));
}

// A chain of `segments` actuators in series (scenarios/chain.yaml's, extended), its last node
// pulled: 2 states per node.
std::string LongChain(int segments) {
  const std::string chain = testing::ReadFile(testing::ScenarioPath("chain.yaml"));
  const std::size_t from = chain.find("name: chain");
  std::ostringstream nodes, elements;
  nodes << chain.substr(from, chain.find("nodes:") - from) << "nodes:\n"
        << "  - {name: wall, fixed: 0.0}\n";
  elements << "elements:\n";
  for (int i = 1; i <= segments; ++i) {
    nodes << "  - {name: n" << i << ", mass: 0.01, position: " << 0.145 * i << ", velocity: 0.0}\n";
    elements << "  - {name: muscle" << i << ", type: actuator, from: ";
    if (i == 1) {
      elements << "wall";
    } else {
      elements << "n" << i - 1;
    }
    elements << ", to: n" << i << ", model: muscle, activation: {type: constant, value: 0.2}}\n";
  }
  nodes << elements.str() << "loads:\n  - {node: n" << segments
        << ", type: constant, value: 100.0}\ntime: {start: 0.0, end: 1.0}\n"
        << "solver: {method: bdf, rtol: 1.0e-6, atol: 1.0e-10}\noutput: {interval: 0.1}\n";
  return nodes.str();
}

TEST(OptimizeBounds, AGridNoMachineCanHoldIsRefusedWithItsEstimate) {
  // 100,000 intervals of a 200-state chain: some 10 MiB each by the estimate (the states'
  // and columns' sensitivities, 64 (n + K)^2 bytes), a terabyte in all, refused when read
  const std::string dir = testing::FreshDirectory("optimize_bounds_chain");
  std::ofstream(dir + "/chain.yaml") << LongChain(100);
  const Outcome out = Optimize(dir,
                               "base: chain.yaml\nintervals: 100000\ncontrols:\n"
                               "  - {actuator: muscle1}\nfinal_values:\n"
                               "  - {column: n100.position, value: 14.5}\n");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err,
              HasSubstr("intervals = 100000 (problem.yaml:2:12): the program needs about"));
  EXPECT_THAT(out.err, HasSubstr("intervals of 200 states, more than the"));
  EXPECT_TRUE(out.summary.empty());
}

// AddressSanitizer reserves terabytes of address space for its shadow memory at start, so a
// limit on the address space cannot be run under it (the chain above is refused there too).
#if defined(__SANITIZE_ADDRESS__)
#define MUSCLESIM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MUSCLESIM_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef MUSCLESIM_ADDRESS_SANITIZER
TEST(OptimizeBounds, AGridTheProcessCannotHoldIsRefusedWithItsEstimate) {
  // 100,000 intervals need some 780 MiB by the estimate (435 MiB measured); under a 400 MB
  // address-space limit the problem is refused when read, before IPOPT allocates anything
  const std::string dir = PairDirectory();
  const Outcome out = Optimize(
      dir, Move("  - {column: load.position, value: 0.075}\n", "{tolerance: 1.0e-8}", 100000),
      "ulimit -v 400000");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err,
              HasSubstr("intervals = 100000 (problem.yaml:2:12): the program needs about"));
  EXPECT_THAT(out.err, HasSubstr("MiB this process may allocate: use fewer intervals"));
  EXPECT_TRUE(out.summary.empty());
}
#endif

TEST(OptimizeBounds, AReferenceThatIsNoFileOrTooLongIsRefusedWhenRead) {
  const std::string dir = PairDirectory();
  ASSERT_EQ(::mkfifo((dir + "/fifo.csv").c_str(), 0600), 0);
  {
    std::ofstream big(dir + "/big.csv");
    big << "t,position\n";
    for (int i = 0; i <= 100001; ++i) big << 1.0 * i / 100001 << ",0.07\n";
  }
  const std::string head =
      "base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\ntracking:\n"
      "  - column: load.position\n    reference: {csv: ";
  const Outcome fifo = Optimize(dir, head + "fifo.csv, column: position}\n");
  EXPECT_EQ(fifo.exit_code, 2);
  EXPECT_THAT(fifo.err, HasSubstr("fifo.csv: is a FIFO (a named pipe), not a regular file"));
  const Outcome zero = Optimize(dir, head + "/dev/zero, column: position}\n");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_THAT(zero.err, HasSubstr("/dev/zero: is a device, not a regular file"));
  const Outcome big = Optimize(dir, head + "big.csv, column: position}\n");
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_THAT(big.err, HasSubstr("100002 points, more than the 100000 a reference may hold"));
}

}  // namespace
}  // namespace musclesim
