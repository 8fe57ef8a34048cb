// An isotonic (afterloaded) contraction built entirely in code, no file involved: a 10 cm
// actuator is switched on at t = 50 ms against a constant load and shortens. One tension
// model is built once and shared by the system of every load.
//   build/examples/isotonic_in_code
#include <cstdio>
#include <memory>
#include <string>

#include "musclesim/musclesim.h"

int main() {
  using namespace musclesim;

  ModelParams params;
  params.f_iso = 100.0;  // N
  params.passive = {.k_p = 1.0, .alpha = 100.0, .slack_length = 0.105};
  params.active_length.optimal_min = 0.095;  // m
  params.active_length.optimal_max = 0.105;  // m
  // amplitude, b_k [1/m^2], centre [m]: the three Gaussians of scenarios/concentric.yaml
  params.active_length.gaussians = {{0.35188944617853268, 20635.199147929347, 0.073556703926583866},
                                    {2.2575025981825489, 4125.1402656159307, 0.097194271247335401},
                                    {1.3136662819543681, 3009.3607405177986, 0.1301541244400391}};
  params.velocity = {.v_max = 1.0, .n = 3, .epsilon = 1e-3};  // m/s, -, m/s
  const auto model = std::make_shared<const TensionModel>(params);

  RunRequest request;
  request.t_end = 0.3;   // s
  request.length = 0.1;  // m
  request.output_interval = 0.01;
  request.min_length = 0.06;  // m: stop there rather than shorten without end

  Simulation simulation;  // one CVODE workspace, re-used for every run
  std::printf("%8s %20s %14s %10s\n", "load_N", "shortening_m/s_0.1s", "final_length_m", "status");
  for (double load : {10.0, 30.0, 50.0, 70.0, 90.0}) {
    ActuatorParams actuator;
    actuator.mass = 0.1;  // kg; no parallel spring or damper
    const ActuatorSystem system(model, actuator, Waveform::Step(0.05, 0.0, 1.0),
                                {Load::Force(Waveform::Step(0.05, 0.0, load))});
    const RunResult result = simulation.Run(system, SolverOptions{}, request);
    // rows every 10 ms from t = 0: row 10 is 50 ms after the switch-on
    const ActuatorSample& settled = result.trajectory.at(10).sample;
    const ActuatorSample& last = result.trajectory.back().sample;
    std::printf("%8.1f %20.6f %14.6f %10s\n", load, settled.shortening_velocity, last.length,
                std::string(ToString(result.stats.status)).c_str());
    if (result.stats.status == RunStatus::kFailed) return 1;
  }
  return 0;
}
