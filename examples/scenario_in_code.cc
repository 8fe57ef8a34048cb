// A scenario file loaded, changed in code and run: the force-velocity relation measured
// by re-running scenarios/concentric.yaml with a range of loads, each through the same
// validated ScenarioSpec with one field changed.
//   build/examples/scenario_in_code scenarios/concentric.yaml
#include <cstdio>
#include <exception>
#include <string>

#include "musclesim/musclesim.h"

int main(int argc, char** argv) {
  using namespace musclesim;
  const std::string path = argc > 1 ? argv[1] : "scenarios/concentric.yaml";
  try {
    ScenarioSpec spec = LoadScenario(path);
    std::printf("%8s %22s\n", "load_N", "shortening_m/s_at_0.1s");
    for (double load = 10.0; load <= 90.0; load += 20.0) {
      spec.loads.at(0).force.after = load;  // the step load of the file, now `load` newtons
      const RunResult result = RunScenario(spec);
      if (result.stats.status == RunStatus::kFailed) {
        std::fprintf(stderr, "%s\n", result.stats.message.c_str());
        return 3;
      }
      // velocity 50 ms after the switch-on, when the isotonic phase has settled
      for (const TrajectoryPoint& p : result.trajectory) {
        if (p.t >= 0.1) {
          std::printf("%8.1f %22.6f\n", load, p.sample.shortening_velocity);
          break;
        }
      }
    }
  } catch (const std::exception& e) {  // InputError: file, line, key, value and rule
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
