// Test helpers: temporary scenario files, the shipped scenarios and the tests' fixtures, and
// one-call runs of a single actuator whose rows are read as the actuator's samples.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/simulation.h"

namespace musclesim::testing {

// Writes `text` to a temporary file named after the running test (ctest runs tests in
// parallel processes, which must not share files) and `name`.
inline std::string WriteTempFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                           name;
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
  return pad + "f_iso: 100.0\n" + pad + "passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}\n" +
         pad + "active_length:\n" + pad + "  optimal_range: [0.095, 0.105]\n" + pad +
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

// "line:column" (1-based) of the first `needle` in `text`: where a reader places it.
inline std::string LineColumn(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  const std::size_t line_start = text.rfind('\n', at);
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  const std::size_t column = line_start == std::string::npos ? at + 1 : at - line_start;
  return std::to_string(line) + ":" + std::to_string(column);
}

// A shipped scenario (scenarios/NAME), the data the CLI, tests and benchmarks share.
inline std::string ScenarioPath(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name;
}

// A scenario only the tests use, read by several of them (tests/fixtures/NAME).
inline std::string FixturePath(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/tests/fixtures/" + name;
}

// Records a single actuator's run (ScenarioForm::kActuator) as the actuator's samples: what
// its network observes of element `actuator` and node `tip` (ActuatorSampleOf).
class ActuatorTrajectory final : public NetworkSink {
 public:
  explicit ActuatorTrajectory(std::vector<TrajectoryPoint>& points) : points_(points) {}
  void Record(double t, const NetworkSample& sample) override {
    points_.push_back({t, ActuatorSampleOf(sample)});
  }

 private:
  std::vector<TrajectoryPoint>& points_;
};

// RunScenario of a single actuator into `trajectory` (cleared first).
inline RunStats RunActuator(const Scenario& scenario, std::vector<TrajectoryPoint>& trajectory) {
  EXPECT_EQ(scenario.form, ScenarioForm::kActuator) << scenario.source;
  trajectory.clear();
  ActuatorTrajectory sink(trajectory);
  Simulation simulation;
  return RunScenario(scenario, simulation, sink);
}

inline RunResult RunActuator(const Scenario& scenario) {
  RunResult result;
  result.stats = RunActuator(scenario, result.trajectory);
  return result;
}

struct Outcome {
  Scenario scenario;
  RunStats stats;
  std::vector<TrajectoryPoint> trajectory;
};

// LoadScenario(path, sets) of a single actuator, then its run.
inline Outcome Simulate(const std::string& path, const std::vector<std::string>& sets = {}) {
  Outcome out{LoadScenario(path, sets), {}, {}};
  out.stats = RunActuator(out.scenario, out.trajectory);
  return out;
}

// Column `name` of a recorded run; fails the test and returns an empty column when it has
// none.
inline const std::vector<double>& ColumnOf(const RecordedRun& run, const std::string& name) {
  static const std::vector<double> kNone;
  const std::vector<std::string>& names = run.columns.names();
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (names[c] == name) return run.values[c];
  }
  ADD_FAILURE() << "no column " << name;
  return kNone;
}

// Whether two runs recorded the same rows to the last bit: the same columns, every value's
// bits equal (so +0 and -0 differ, and a NaN equals only itself), the same step count.
inline ::testing::AssertionResult SameRecordedRun(const RecordedRun& a, const RecordedRun& b) {
  if (a.columns.names() != b.columns.names()) {
    return ::testing::AssertionFailure() << "the columns differ";
  }
  if (a.stats.steps != b.stats.steps || a.stats.status != b.stats.status) {
    return ::testing::AssertionFailure()
           << "steps " << a.stats.steps << " and " << b.stats.steps << ", status "
           << ToString(a.stats.status) << " and " << ToString(b.stats.status);
  }
  for (std::size_t c = 0; c < a.values.size(); ++c) {
    const std::vector<double>& x = a.values[c];
    const std::vector<double>& y = b.values[c];
    if (x.size() != y.size()) {
      return ::testing::AssertionFailure() << x.size() << " and " << y.size() << " rows";
    }
    for (std::size_t r = 0; r < x.size(); ++r) {
      if (std::bit_cast<std::uint64_t>(x[r]) != std::bit_cast<std::uint64_t>(y[r])) {
        return ::testing::AssertionFailure()
               << a.columns.names()[c] << " at row " << r << ": " << x[r] << " and " << y[r];
      }
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace musclesim::testing
