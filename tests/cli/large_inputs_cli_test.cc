// Inputs a run cannot take, refused before the work with the reason and exit 2: a dense LU
// of a large network (its cost, and the solver to choose), and input files that are no
// regular files (a FIFO would block the reader until a writer came, /dev/zero never ends),
// for every verb that reads a YAML or CSV file. An earlier output is never touched.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_run.h"
#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// An n x n lattice of springs in the plane, its first column clamped: 4 n (n - 1) states.
// (A stream, not operator+: GCC 12 warns falsely, -Wrestrict, on such chains.)
std::string Lattice(int n, const std::string& solver) {
  std::ostringstream text;
  const auto name = [](int i, int j) {
    std::ostringstream out;
    out << "n" << i << "_" << j;
    return out.str();
  };
  text << "name: grid\ndimensions: 2\nnodes:\n";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      text << "  - {name: " << name(i, j) << (j == 0 ? ", fixed: [" : ", mass: 0.02, position: [")
           << 0.05 * j << ", " << 0.05 * i << "]}\n";
    }
  }
  text << "elements:\n";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      text << "  - {name: s" << name(i, j) << ", type: spring, from: " << name(i, j)
           << ", to: " << name(i, j + 1) << ", stiffness: 2000.0, rest_length: 0.05}\n";
      if (i + 1 < n) {
        text << "  - {name: v" << name(i, j) << ", type: spring, from: " << name(i, j + 1)
             << ", to: " << name(i + 1, j + 1) << ", stiffness: 2000.0, rest_length: 0.05}\n";
      }
    }
  }
  text << "time: {start: 0.0, end: 0.001}\nsolver: {linear_solver: " << solver << "}\n";
  return text.str();
}

TEST(LargeInputs, ADenseLuOfALargeNetworkIsRefusedWithItsCost) {
  const std::string dir = testing::FreshDirectory("large_inputs_");
  std::ofstream(dir + "/grid.yaml") << Lattice(30, "dense");
  std::ofstream(dir + "/out.csv") << "earlier\n";
  const testing::CliOutcome out =
      testing::RunMusclesim("run " + dir + "/grid.yaml -o " + dir + "/out.csv");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("linear_solver = dense: a dense LU of this system's 3480 states "
                                 "costs 1.4e+10 flops per factorisation"));
  EXPECT_THAT(out.err, HasSubstr("above 2000 states use auto or sparse"));
  EXPECT_EQ(testing::ReadText(dir + "/out.csv"), "earlier\n");
  // auto takes the sparse solver there and runs
  std::ofstream(dir + "/grid.yaml") << Lattice(30, "auto");
  EXPECT_EQ(testing::RunMusclesim("run " + dir + "/grid.yaml -o " + dir + "/out.csv").exit_code, 0);
}

TEST(LargeInputs, InputsThatAreNoRegularFilesAreRefusedForEveryReader) {
  const std::string dir = testing::FreshDirectory("large_inputs_");
  ASSERT_EQ(::mkfifo((dir + "/pipe").c_str(), 0600), 0);
  for (const std::string& input : {dir + "/pipe", std::string("/dev/zero")}) {
    const std::string what = input == "/dev/zero" ? "is a device" : "is a FIFO (a named pipe)";
    for (const std::string& command :
         {"run " + input + " -o " + dir + "/out.csv", "plot " + input + " -o " + dir + "/out.png",
          "identify " + input + " -o " + dir + "/out.yaml",
          "sweep " + input + " -o " + dir + "/out.csv",
          "curves " + input + " --length 0.05:0.15:11 -o " + dir + "/out.csv", "fit " + input,
          "optimize " + input}) {
      const testing::CliOutcome out = testing::RunMusclesim(command);
      EXPECT_EQ(out.exit_code, 2) << command << ": " << out.err;
      EXPECT_THAT(out.err, HasSubstr(what)) << command;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.csv"));
}

}  // namespace
}  // namespace musclesim
