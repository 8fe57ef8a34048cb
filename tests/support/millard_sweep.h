// Test helper: the shipped scenarios/millard_benchmark_sweep.yaml, runnable in a tree that
// does not hold its base scenarios/millard_benchmark.yaml yet: then the sweep file is copied
// beside tests/support/millard_benchmark_standin.yaml, a copy of that base, named as the base.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "support/scenario_files.h"

namespace musclesim::testing {

// The text of scenarios/millard_benchmark.yaml, or of its stand-in.
inline std::string MillardBaseText() {
  const std::string base = ScenarioPath("millard_benchmark.yaml");
  return ReadFile(std::filesystem::exists(base)
                      ? base
                      : std::string(MUSCLESIM_SOURCE_DIR) +
                            "/tests/support/millard_benchmark_standin.yaml");
}

// The path of the shipped sweep, or of a copy of it beside the stand-in.
inline std::string MillardSweepPath() {
  const std::string sweep = ScenarioPath("millard_benchmark_sweep.yaml");
  if (std::filesystem::exists(ScenarioPath("millard_benchmark.yaml"))) return sweep;
  // a folder per test: ctest runs tests in parallel processes
  const std::string dir = ::testing::TempDir() +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                          "_millard/";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "millard_benchmark.yaml") << MillardBaseText();
  std::ofstream(dir + "millard_benchmark_sweep.yaml") << ReadFile(sweep);
  return dir + "millard_benchmark_sweep.yaml";
}

}  // namespace musclesim::testing
