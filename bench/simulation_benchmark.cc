// Step cost of whole runs of the canonical scenarios, per integration method and Jacobian:
// wall time per run (RunScenario, the rows recorded in memory), and counters for steps, RHS
// and Jacobian evaluations and the time per step. Loading, building the system and CVODE
// allocation stay outside the timed loop.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"

namespace musclesim {
namespace {

const char* const kScenarios[] = {"isometric", "concentric",      "eccentric",   "twitches",
                                  "sine_load", "activation_ramp", "hanging_mass"};

// args: scenario index, method (0 bdf, 1 adams), jacobian (0 analytic, 1 difference quotient)
void BM_SimulationRun(benchmark::State& state) {
  const std::string name = kScenarios[state.range(0)];
  Scenario scenario =
      LoadScenario(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml");
  scenario.solver.method =
      state.range(1) == 0 ? IntegrationMethod::kBdf : IntegrationMethod::kAdams;
  scenario.solver.jacobian =
      state.range(2) == 0 ? JacobianKind::kAnalytic : JacobianKind::kDifferenceQuotient;
  const NetworkSystem system = scenario.Build();
  Simulation simulation;
  ColumnRecorder recorder(scenario, system);
  // one untimed run allocates the CVODE memory and the rows' storage
  RunStats stats = simulation.Run(system, scenario.solver, scenario.Request(), recorder);
  for (auto _ : state) {
    recorder.Clear();
    stats = simulation.Run(system, scenario.solver, scenario.Request(), recorder);
    benchmark::DoNotOptimize(recorder.column(0).data());
  }
  state.SetLabel(name + (state.range(1) == 0 ? " bdf" : " adams") +
                 (state.range(2) == 0 ? " analytic" : " dq"));
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["rhs"] = static_cast<double>(stats.rhs_evals);
  state.counters["jac"] = static_cast<double>(stats.jac_evals);
  // seconds per internal step (printed with an SI prefix: 1.2u is 1.2 microseconds)
  state.counters["time_per_step"] =
      benchmark::Counter(static_cast<double>(stats.steps) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  if (stats.status == RunStatus::kFailed) state.SkipWithError(stats.message.c_str());
}
BENCHMARK(BM_SimulationRun)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {0, 1}, {0, 1}})
    ->ArgNames({"scenario", "adams", "dq"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace musclesim
