// A scenario file loaded, changed in code and run: the force-velocity relation measured by
// re-running scenarios/concentric.yaml with a range of loads, each set through the load's
// parameter handle (the value itself, checked as the file's would be: no text).
//   build/examples/scenario_in_code scenarios/concentric.yaml
#include <cstdio>
#include <exception>
#include <string>

#include "musclesim/musclesim.h"

int main(int argc, char** argv) {
  using namespace musclesim;
  const std::string path = argc > 1 ? argv[1] : "scenarios/concentric.yaml";
  try {
    Scenario scenario = LoadScenario(path);
    const Parameter load = scenario.parameter("load[0].after");  // the step load, in N
    std::printf("%8s %22s\n", "load_N", "shortening_m/s_at_0.1s");
    for (double force = 10.0; force <= 90.0; force += 20.0) {
      load.Set(scenario, force);
      const RecordedRun run = RunScenario(scenario);
      if (run.stats.status == RunStatus::kFailed) {
        std::fprintf(stderr, "%s\n", run.stats.message.c_str());
        return 3;
      }
      // the single actuator's columns: t, length, shortening_velocity, ...; its velocity
      // 50 ms after the switch-on, when the isotonic phase has settled
      const std::vector<double>& t = run.values[0];
      for (std::size_t row = 0; row < t.size(); ++row) {
        if (t[row] >= 0.1) {
          std::printf("%8.1f %22.6f\n", force, run.values[2][row]);
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
