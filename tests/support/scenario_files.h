// Test helpers: temporary scenario files and one-call simulations of them.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/io/run_scenario.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/scenario.h"
#include "musclesim/solver/simulation.h"

namespace musclesim::testing {

// Writes `text` to a temporary file named after the running test (ctest runs tests in
// parallel processes, which must not share files) and `name`.
inline std::string WriteTempFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                           "_" + name;
  std::ofstream(path) << text;
  return path;
}

// The message of the InputError that `load` throws for `path`, with the path (which varies
// per run) shown as FILE; "accepted" when nothing is thrown.
template <typename Load>
std::string InputErrorOf(const std::string& path, Load load) {
  try {
    load();
  } catch (const InputError& e) {
    std::string message = e.what();
    for (auto at = message.find(path); at != std::string::npos; at = message.find(path)) {
      message.replace(at, path.size(), "FILE");
    }
    return message;
  }
  return "accepted";
}

// The small model the readers' tests share (f_iso 100 N, slack at 0.105 m, one Gaussian
// at 0.1 m, the canonical tension-velocity curve) as the keys of a model block, each line
// indented by `indent` spaces.
inline std::string TestModelKeys(int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  return pad + "f_iso: 100.0\n" + pad +
         "passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}\n" + pad + "active_length:\n" +
         pad + "  optimal_range: [0.095, 0.105]\n" + pad +
         "  gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]\n" + pad +
         "velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}\n";
}

inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A sweep summary without its wall_seconds column (the third last), which cannot repeat
// from run to run. Messages in these tests hold no commas.
inline std::string SummaryWithoutWallTime(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string out;
  for (std::string line; std::getline(in, line);) {
    const auto last = line.rfind(',');
    const auto wall = line.rfind(',', last - 1);
    out += line.substr(0, wall) + line.substr(last) + "\n";
  }
  return out;
}

inline std::string ScenarioPath(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name;
}

struct Outcome {
  ScenarioSpec spec;
  RunStats stats;
  std::vector<TrajectoryPoint> trajectory;
};

inline Outcome Simulate(const std::string& path, const std::vector<std::string>& sets = {}) {
  Outcome out{LoadScenario(path, sets), {}, {}};
  const ActuatorSystem system = BuildSystem(out.spec);
  Simulation simulation;
  out.stats = simulation.Run(system, out.spec.solver, out.spec.Request(), out.trajectory);
  return out;
}

}  // namespace musclesim::testing
