// The shipped optimal control problems (scenarios/*_problem.yaml) solved by `musclesim
// optimize` as the README runs them, each optimum then re-run by `musclesim run` as a plain
// scenario: the minimum-time move and the suspended mass reach their final values at rest;
// the tracking problem recovers the activation that made its record (data/quick_release*);
// an interrupted run writes the point it reached.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/scenario_files.h"

namespace musclesim {
namespace {

int Shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A CSV's column as numbers (the header names it).
std::vector<double> Column(const std::string& csv, const std::string& name) {
  std::stringstream in(testing::ReadFile(csv));
  std::string header, line;
  std::getline(in, header);
  std::stringstream names(header);
  std::string cell;
  int index = -1;
  for (int c = 0; std::getline(names, cell, ','); ++c) {
    if (cell == name) index = c;
  }
  EXPECT_GE(index, 0) << "no column " << name << " in " << csv;
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    for (int c = 0; std::getline(cells, cell, ','); ++c) {
      if (c == index) values.push_back(std::stod(cell));
    }
  }
  return values;
}

// A copy of the repository's scenarios/ and data/ (the problems name their files relative to
// themselves), the problem solved there and its optimum re-run into check.csv.
std::string CopyOfTheTrees(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "optimize_problems_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string source = MUSCLESIM_SOURCE_DIR;
  for (const char* tree : {"scenarios", "data"}) {
    std::filesystem::copy(source + "/" + tree, dir + "/" + tree,
                          std::filesystem::copy_options::recursive);
  }
  return dir;
}

std::string SolveAndRerun(const std::string& problem, const std::string& optimum) {
  const std::string dir = CopyOfTheTrees(problem);
  const std::string at = "cd '" + dir + "/scenarios' && '" + MUSCLESIM_BINARY + "' ";
  EXPECT_EQ(Shell(at + "optimize --quiet " + problem + ".yaml"), 0) << problem;
  EXPECT_EQ(Shell(at + "run " + optimum + ".yaml -o check.csv --quiet"), 0) << optimum;
  return dir + "/scenarios/check.csv";
}

TEST(OptimizeProblems, MinimumTimeMoveEndsAtRestWhereAsked) {
  const std::string csv =
      SolveAndRerun("antagonist_min_time_problem", "antagonist_min_time_optimum");
  const std::vector<double> t = Column(csv, "t");
  EXPECT_NEAR(Column(csv, "load.position").back(), 0.075, 1e-8);
  EXPECT_NEAR(Column(csv, "load.velocity").back(), 0.0, 1e-7);
  // far faster than the minimum-effort move's 1 s, within the final time's bounds
  EXPECT_GT(t.back(), 0.02);
  EXPECT_LT(t.back(), 0.2);
}

TEST(OptimizeProblems, SuspendedMassMovesToRestAtTheTarget) {
  const std::string csv =
      SolveAndRerun("suspended_mass_move_problem", "suspended_mass_move_optimum");
  EXPECT_NEAR(Column(csv, "mass.x").back(), 0.02, 1e-8);
  EXPECT_NEAR(Column(csv, "mass.y").back(), -0.07, 1e-8);
  EXPECT_NEAR(Column(csv, "mass.vx").back(), 0.0, 1e-7);
  EXPECT_NEAR(Column(csv, "mass.vy").back(), 0.0, 1e-7);
}

TEST(OptimizeProblems, TrackingRecoversTheActivationBehindTheRecord) {
  const std::string csv =
      SolveAndRerun("quick_release_tracking_problem", "quick_release_tracking_optimum");
  // the record is the run of scenarios/quick_release.yaml, fully activated from 0.05 s on, with
  // noise: the optimum on its 10 ms grid is 0 to 0.04 s and 1 from 0.06 s
  const std::vector<double> t = Column(csv, "t"), u = Column(csv, "activation");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] <= 0.04 + 1e-12) {
      EXPECT_LT(u[i], 1e-3) << "t = " << t[i];
    } else if (t[i] >= 0.06 - 1e-12) {
      EXPECT_GT(u[i], 1.0 - 1e-3) << "t = " << t[i];
    }
  }
}

// Ctrl-C while IPOPT iterates: it stops after the iteration under way, and every file is
// written with the point reached, the summary saying so; the exit code is 130. (Signalled
// again and again: one arriving before the handler is set is ignored, as a background job's
// SIGINT is, and later ones must not cut the writing short.)
TEST(OptimizeProblems, AnInterruptWritesThePointReached) {
  const std::string dir = CopyOfTheTrees("interrupt") + "/scenarios";
  const std::string command =
      "cd '" + dir + "' && ('" + MUSCLESIM_BINARY +
      "' optimize --quiet suspended_mass_move_problem.yaml & pid=$!; "
      "for i in 1 2 3 4; do sleep 0.4; kill -INT $pid 2>/dev/null; done; wait $pid)";
  EXPECT_EQ(Shell(command), 130);
  const std::string summary = testing::ReadFile(dir + "/suspended_mass_move_optimum.json");
  EXPECT_NE(summary.find("\"status\": \"user_requested_stop\""), std::string::npos) << summary;
  EXPECT_FALSE(Column(dir + "/suspended_mass_move_optimum.csv", "mass.x").empty());
  EXPECT_EQ(Shell("cd '" + dir + "' && '" + MUSCLESIM_BINARY +
                  "' run suspended_mass_move_optimum.yaml -o check.csv --quiet"),
            0);
}

}  // namespace
}  // namespace musclesim
