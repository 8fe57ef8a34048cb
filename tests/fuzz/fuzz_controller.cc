// libFuzzer target: the controller reader. The input is a `controllers:` block (its corpus:
// the shipped controllers and their variants), appended to a fixed antagonist pair so that
// the mutations are spent on the controllers rather than on the network around them. A block
// the reader accepts builds, and runs for 20 ms of simulated time: a run may fail (a status)
// but must end within its max_steps, without a crash or an exception other than the input
// errors.
#include <algorithm>
#include <optional>
#include <string>

#include "fuzz_input.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/solver/simulation.h"

namespace {

constexpr const char* kPair = R"(name: fuzz_pair
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length: {optimal_range: [0.095, 0.105], gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]}
    velocity: {v_max: 1.0, n: 1, epsilon: 1.0e-3}
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 1.0, position: 0.07, velocity: 0.0}
  - {name: wall_b, fixed: 0.14}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle}
  - {name: tendon, type: tendon, from: wall_a, to: load, slack_length: 0.2, stiffness: 100.0}
  - {name: own, type: actuator, from: wall_a, to: load, model: muscle, excitation: {type: constant, value: 0.2}, activation_dynamics: {tau_activation: 0.01, tau_deactivation: 0.04}}
time: {start: 0.0, end: 1.0}
solver: {method: bdf, rtol: 1.0e-6, atol: 1.0e-9, max_steps: 200000}
output: {file: out.csv, interval: 0.001}
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string block(reinterpret_cast<const char*>(data), size);
  const std::string text = std::string(kPair) + block;
  const std::string path = fuzz::WriteInput(reinterpret_cast<const std::uint8_t*>(text.data()),
                                            text.size(), "controller.yaml");
  std::optional<Scenario> scenario;
  fuzz::ExpectOnlyInputErrors([&] { scenario = LoadScenario(path); });
  if (!scenario) return 0;
  const NetworkSystem system = scenario->Build();
  NetworkRunRequest request = scenario->Request();
  request.t_end = std::min(request.t_end, request.t_start + 0.02);
  request.output_interval = 0.0;
  request.limits.clear();
  SolverOptions options = scenario->solver;
  options.max_steps = std::min(options.max_steps, 200000L);
  struct Discard : NetworkSink {
    void Record(double, const NetworkSample&) override {}
  } discard;
  Simulation simulation;
  (void)simulation.Run(system, options, request, discard);
  return 0;
}
