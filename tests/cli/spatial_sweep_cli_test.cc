// A sweep over a network in the plane: its axes are coordinate handles (gravity[1]) and
// element coefficients, its metrics read an element's path, and each point's final length is
// the static stretch of a damped hanging spring, m |g| / k, worked out here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "support/scenario_files.h"

namespace musclesim {
namespace {

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  return cells;
}

TEST(SpatialSweep, FinalLengthsAreTheStaticStretches) {
  constexpr double kMass = 0.5, kRest = 0.2;
  const std::string base = testing::WriteTempFile("hanging.yaml", R"(name: hanging
dimensions: 2
gravity: [0.0, -9.81]
nodes:
  - {name: pivot, fixed: [0.0, 0.0]}
  - {name: weight, mass: 0.5, position: [0.0, -0.2]}
elements:
  - {name: spring, type: spring, from: pivot, to: weight, stiffness: 200.0, rest_length: 0.2}
  - {name: damper, type: damper, from: pivot, to: weight, damping: 50.0}
time: {start: 0.0, end: 8.0}
solver: {rtol: 1.0e-10, atol: 1.0e-13}
output: {file: hanging.csv, interval: 0.01}
)");
  const std::string sweep = testing::WriteTempFile(
      "hanging_sweep.yaml", "base: " + base +
                                "\nparameters:\n  gravity[1]: [-9.81, -3.0]\n"
                                "  elements[0].stiffness: [200.0, 500.0]\n"
                                "metrics: [final_length, min_length]\n"
                                "metric_options: {element: spring}\n");
  const std::string out = ::testing::TempDir() + "hanging_sweep.csv";
  const std::string command = std::string(MUSCLESIM_BINARY) + " sweep '" + sweep + "' -o '" + out +
                              "' --jobs 1 > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::stringstream rows(testing::ReadFile(out));
  std::string line;
  std::getline(rows, line);
  const std::vector<std::string> header = Split(line);
  const auto column = [&](const std::string& name) {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return c;
    }
    ADD_FAILURE() << "no column " << name;
    return std::size_t{0};
  };
  int points = 0;
  while (std::getline(rows, line)) {
    const std::vector<std::string> cells = Split(line);
    const double g = -std::stod(cells[column("gravity[1]")]);
    const double k = std::stod(cells[column("elements[0].stiffness")]);
    EXPECT_EQ(cells[column("status")], "ok");
    // over-damped, it has settled at the stretch that holds its weight
    EXPECT_NEAR(std::stod(cells[column("final_length")]), kRest + kMass * g / k, 1e-9);
    // it starts at rest length and only stretches
    EXPECT_NEAR(std::stod(cells[column("min_length")]), kRest, 1e-12);
    ++points;
  }
  EXPECT_EQ(points, 4);
}

TEST(SpatialSweep, AFixedViaPointsCoordinateIsAnAxisAndGarbageThereIsRefused) {
  // a spring of rest length 1 m from a pivot over a fixed via point at (0.5, y) to a heavy
  // bob at rest at (1.2, 0): over 1 ms it moves by T t^2 / 2m ~ 1e-11 m, so the final length
  // is the two segments' at the start
  const std::string base = testing::WriteTempFile("via.yaml", R"(name: via
dimensions: 2
nodes:
  - {name: pivot, fixed: [0.0, 0.0]}
  - {name: bob, mass: 1.0e6, position: [1.2, 0.0]}
elements:
  - {name: link, type: spring, from: pivot, to: bob, stiffness: 100.0, rest_length: 1.0,
     via: [[0.5, 0.2]]}
time: {start: 0.0, end: 0.001}
output: {interval: 0.0005}
)");
  const auto sweep = [&](const std::string& values, const std::string& out) {
    const std::string file = testing::WriteTempFile(
        "via_sweep.yaml", "base: " + base + "\nparameters:\n  elements[0].via[0][1]: " + values +
                              "\nmetrics: [final_length]\nmetric_options: {element: link}\n");
    const std::string command = std::string(MUSCLESIM_BINARY) + " sweep '" + file + "' -o '" + out +
                                "' --jobs 1 > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WEXITSTATUS(status);
  };
  const std::string out = ::testing::TempDir() + "via_sweep.csv";
  ASSERT_EQ(sweep("[0.0, 0.2]", out), 0);
  std::stringstream rows(testing::ReadFile(out));
  std::string line;
  std::getline(rows, line);
  const std::vector<std::string> header = Split(line);
  std::size_t column = 0;
  while (column < header.size() && header[column] != "final_length") ++column;
  ASSERT_LT(column, header.size());
  for (const double y : {0.0, 0.2}) {
    ASSERT_TRUE(std::getline(rows, line));
    // the path from (0, 0) over (0.5, y) to (1.2, 0)
    const double length = std::hypot(0.5, y) + std::hypot(0.7, y);
    EXPECT_NEAR(std::stod(Split(line)[column]), length, 1e-10) << "y = " << y;
  }
  for (const char* garbage : {"[abc]", "[\".nan\"]", "[1e400]", "[true]"}) {
    EXPECT_EQ(sweep(garbage, ::testing::TempDir() + "via_garbage.csv"), 2) << garbage;
  }
}

}  // namespace
}  // namespace musclesim
