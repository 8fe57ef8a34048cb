// The cost of forward sensitivities (CVODES, staggered corrector): a run with k parameters
// against the plain run of the same scenario (both on the linear solver `auto` picks), on three
// scenarios, with the tension model's closed-form df/dp and with difference quotients of the
// scenario set at nearby values. Prints a Markdown table of the median integration time over
// repeated runs (stats.wall_seconds: setup and file reading excluded on both sides) and the steps
// taken. The goal: about (1 + k) times the plain run or less.
//   sensitivity_cost [REPEATS]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/sensitivity_run.h"

namespace {

using namespace musclesim;

struct Case {
  std::string scenario;               // under scenarios/
  std::vector<std::string> analytic;  // tension model parameters
  std::vector<std::string> quotient;  // parameters by difference quotient
};

std::string Path(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml";
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Timing {
  double seconds = 0.0;  // median integration time [s]
  long steps = 0;
};

Timing WithSensitivities(const std::string& scenario, const std::vector<std::string>& parameters,
                         int repeats) {
  std::vector<double> times;
  Timing timing;
  const Scenario loaded = LoadScenario(Path(scenario));
  for (int i = 0; i < repeats; ++i) {
    const SensitivityTable table = RunWithSensitivities(loaded, parameters);
    times.push_back(table.stats.wall_seconds);
    timing.steps = table.stats.steps;
  }
  timing.seconds = Median(times);
  return timing;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  const std::vector<Case> cases = {
      {"concentric",
       {"model.f_iso", "model.velocity.v_max", "model.passive.k_p",
        "model.active_length.gaussians[1].center"},
       {"actuator.mass", "load[0].after", "initial.length", "load[0].before"}},
      {"twitches",
       {"model.f_iso", "model.velocity.v_max", "model.passive.alpha",
        "model.active_length.gaussians[1].width"},
       {"activation_dynamics.tau_activation", "actuator.mass", "load[1].stiffness",
        "initial.length"}},
      {"antagonist_pair",
       {"models.muscle.f_iso", "models.muscle.velocity.v_max", "models.muscle.passive.k_p",
        "models.muscle.active_length.gaussians[1].center"},
       {"nodes[1].mass", "nodes[1].position", "elements[0].activation.value", "nodes[2].fixed"}},
  };
  std::printf("| scenario | plain run | df/dp | k = 1 | k = 2 | k = 4 |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    // the plain run records its rows the same way, into the same table
    const Timing fast = WithSensitivities(c.scenario, {}, repeats);
    for (int analytic = 1; analytic >= 0; --analytic) {
      const std::vector<std::string>& all = analytic ? c.analytic : c.quotient;
      std::printf("| %s | %.3f ms, %ld steps | %s |", c.scenario.c_str(), fast.seconds * 1e3,
                  fast.steps, analytic ? "closed form" : "difference quotient");
      for (std::size_t k : {1u, 2u, 4u}) {
        const std::vector<std::string> some(all.begin(), all.begin() + k);
        const Timing t = WithSensitivities(c.scenario, some, repeats);
        std::printf(" %.3f ms = %.2fx, %ld steps |", t.seconds * 1e3, t.seconds / fast.seconds,
                    t.steps);
      }
      std::printf("\n");
    }
  }
  return 0;
}
