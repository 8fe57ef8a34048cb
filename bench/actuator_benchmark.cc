// Cost of one right-hand side (the acceleration) and one Jacobian row of the actuator/load
// dynamics: what CVODE calls in its innermost loop.
#include <benchmark/benchmark.h>

#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/io/readers/scenario_yaml.h"

namespace musclesim {
namespace {

ActuatorSystem Concentric() {
  const ActuatorScenarioSpec s =
      LoadActuatorScenarioSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/concentric.yaml");
  return MakeActuatorSystem(s);
}

void BM_ActuatorAcceleration(benchmark::State& state) {
  const ActuatorSystem system = Concentric();
  double x = 0.1, xdot = -0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(system.Acceleration(0.2, x, xdot));
    x += 1e-9;
    xdot = -xdot;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ActuatorAcceleration);

void BM_ActuatorJacobian(benchmark::State& state) {
  const ActuatorSystem system = Concentric();
  double x = 0.1, xdot = -0.01;
  for (auto _ : state) {
    benchmark::DoNotOptimize(system.Jacobian(0.2, x, xdot));
    x += 1e-9;
    xdot = -xdot;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ActuatorJacobian);

}  // namespace
}  // namespace musclesim
