// musclesim optimize end to end: the antagonist pair's rest-to-rest move solved, its optimum
// written as a scenario that `musclesim run` (a separate run of the file) takes to the asked
// final values; bad problem files refused with the place and the rule.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

int Shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The last row of a CSV as name -> value.
double LastValue(const std::string& csv, const std::string& column) {
  std::stringstream in(testing::ReadFile(csv));
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line)) last = line;
  std::stringstream names(header), cells(last);
  std::string name, cell;
  while (std::getline(names, name, ',') && std::getline(cells, cell, ',')) {
    if (name == column) return std::stod(cell);
  }
  ADD_FAILURE() << "no column " << column << " in " << csv;
  return NAN;
}

std::string Directory(const std::string& name) {
  const std::string dir = ::testing::TempDir() + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(OptimizeCli, MovesThePairRestToRestAndItsOptimumReRuns) {
  const std::string dir = Directory("optimize_pair");
  for (const char* file : {"antagonist_move.yaml", "antagonist_move_problem.yaml"}) {
    std::filesystem::copy_file(testing::ScenarioPath(file), dir + "/" + file);
  }
  ASSERT_EQ(Shell("cd '" + dir + "' && '" + MUSCLESIM_BINARY +
                  "' optimize antagonist_move_problem.yaml --quiet"),
            0);
  const std::string summary = testing::ReadFile(dir + "/antagonist_move_optimum.json");
  EXPECT_THAT(summary, HasSubstr("\"solved\": true"));
  // the written optimum, run again as any scenario: it ends at rest at 0.075 m
  ASSERT_EQ(Shell("cd '" + dir + "' && '" + MUSCLESIM_BINARY +
                  "' run antagonist_move_optimum.yaml -o check.csv --quiet"),
            0);
  EXPECT_NEAR(LastValue(dir + "/check.csv", "load.position"), 0.075, 1e-7);
  EXPECT_NEAR(LastValue(dir + "/check.csv", "load.velocity"), 0.0, 1e-6);
  // and it is the trajectory the command wrote
  EXPECT_EQ(LastValue(dir + "/check.csv", "load.position"),
            LastValue(dir + "/antagonist_move_optimum.csv", "load.position"));
}

TEST(OptimizeCli, BadProblemsExitTwoNamingThePlace) {
  const std::string dir = Directory("optimize_bad");
  std::filesystem::copy_file(testing::ScenarioPath("antagonist_move.yaml"),
                             dir + "/antagonist_move.yaml");
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: biceps}\n",
       "controls[0].actuator = biceps (problem.yaml:3:16): is no actuator"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor, bounds: [0.5, 0.2]}\n",
       "must be [lower, upper] with lower <= upper"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\nfinal_values:\n"
       "  - {column: load.x, value: 0.1}\n",
       "final_values[0].column = load.x (problem.yaml:5:14): is no differentiated column"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\ntracking:\n"
       "  - {column: load.position, reference: {points: [[0, 0.07], [0.5, 0.07]]}}\n",
       "tracking[0].reference (problem.yaml:5:40): covers [0, 0.5] s but must cover the span"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\nparameters:\n"
       "  - {path: \"nodes[1].stiffness\", bounds: [0, 1]}\n",
       "parameters[0].path (problem.yaml:5:12)"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "final_time: {bounds: [0.5, 2.0]}\nfinal_values:\n  - {column: flexor.tension, value: 1}\n",
       "with a free final time, a column must be a state"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "final_time: {bounds: [-1.0, 2.0]}\n",
       "final_time.bounds = [-1, 2] (problem.yaml:4:22): must be finite and after the start"},
      // an output never replaces an input, nor another output, and its directory exists
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "output: {scenario: antagonist_move.yaml}\n",
       "output.scenario = 'antagonist_move.yaml' (problem.yaml:4:20): is antagonist_move.yaml, "
       "which the problem reads"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "output: {summary: ./problem.yaml}\n",
       "which the problem reads: it would be replaced"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "output: {scenario: a.yaml, trajectory: a.yaml}\n",
       "output.trajectory = 'a.yaml' (problem.yaml:4:40): is also output.scenario"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "output: {summary: missing/a.json}\n",
       "its directory missing does not exist"},
      // a parameter the control overrides; bounds the scenario refuses; a final time the
      // output grid cannot serve
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\nparameters:\n"
       "  - {path: \"elements[0].activation.value\", bounds: [0, 1]}\n",
       "which the control replaces: it cannot be a free parameter"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\nparameters:\n"
       "  - {path: \"nodes[1].mass\", bounds: [0, 20]}\n",
       "parameters[0].bounds = [0, 20] (problem.yaml:5:37): 0 is no valid value of nodes[1].mass"},
      {"base: antagonist_move.yaml\ncontrols:\n  - {actuator: flexor}\n"
       "final_time: {bounds: [1.0e+8, 1.0e+9]}\n",
       "as the final time breaks the scenario: output.interval"},
      {"base: antagonist_move.yaml\nintervals: 0\ncontrols:\n  - {actuator: flexor}\n",
       "problem.yaml:2:12"},
  };
  for (const Case& c : cases) {
    std::ofstream(dir + "/problem.yaml") << c.text;
    const std::string err = dir + "/err.txt";
    EXPECT_EQ(
        Shell("cd '" + dir + "' && '" + MUSCLESIM_BINARY + "' optimize problem.yaml 2> err.txt"), 2)
        << c.text;
    EXPECT_THAT(testing::ReadFile(err), HasSubstr(c.expected)) << c.text;
    // nothing the problem read was replaced
    EXPECT_EQ(testing::ReadFile(dir + "/antagonist_move.yaml"),
              testing::ReadFile(testing::ScenarioPath("antagonist_move.yaml")));
    EXPECT_EQ(testing::ReadFile(dir + "/problem.yaml"), c.text);
  }
}

}  // namespace
}  // namespace musclesim
