// A controller outside the simulation: a discrete PI loop at 1 kHz regulates the tension of
// an actuator pulling a transducer spring, stepping the network one sample at a time and
// holding the excitation it computes until the next sample (zero-order hold). The network is
// scenarios/force_regulation.yaml's, its actuator given an excitation of its own to set.
//   build/examples/closed_loop_in_code
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>

#include "musclesim/musclesim.h"

int main() {
  using namespace musclesim;
  try {
    // the canonical actuator (docs/model.md), as in the scenario's `models.muscle`
    ModelParams params;
    params.f_iso = 100.0;                  // N
    params.passive = {1.0, 100.0, 0.105};  // k_p [N], alpha [1/m], slack length [m]
    params.active_length = {0.095,
                            0.105,
                            1.0,
                            {{0.35188944617853268, 20635.199147929347, 0.073556703926583866},
                             {2.2575025981825489, 4125.1402656159307, 0.097194271247335401},
                             {1.3136662819543681, 3009.3607405177986, 0.1301541244400391}}};
    params.velocity = {1.0, 3, 1e-3};  // v_max [m/s], n, epsilon [m/s]
    const auto model = std::make_shared<const TensionModel>(params);
    const ExcitationInput excitation{Waveform::Constant(0.0), {0.03, 0.03}, 0.0};  // s, s
    NetworkSystem network(
        {Node::Fixed("wall", 0.0), Node::Free("tip", 0.05, 0.1), Node::Fixed("anchor", 0.2)},
        {Element::Actuator("muscle", "wall", "tip", model, excitation),
         Element::Spring("transducer", "tip", "anchor", 1e5, 0.1)});
    SolverOptions options;
    options.rtol = 1e-6;
    options.atol = 1e-10;
    Stepper stepper(std::move(network), options);

    constexpr double kPeriod = 1e-3;         // s: the loop's sample period
    constexpr double kp = 0.005, ki = 0.15;  // 1/N, 1/(N s): the scenario's gains
    constexpr double kReference = 33.0;      // N
    double integral = 0.0;                   // N s
    std::printf("%6s %12s %12s\n", "t_s", "tension_N", "excitation");
    for (int k = 0; k < 600; ++k) {
      const double tension = stepper.sample().elements[0].tension;
      const double error = kReference - tension;
      const double command = kp * error + ki * integral;
      const double excitation_now = std::clamp(command, 0.0, 1.0);
      // conditional integration: not while the output is held at a bound it pushes past
      if (command == excitation_now) integral += error * kPeriod;
      stepper.SetActivation("muscle", excitation_now);  // the excitation, with its dynamics
      if (stepper.Advance((k + 1) * kPeriod) != RunStatus::kCompleted) {
        std::fprintf(stderr, "%s\n", stepper.message().c_str());
        return 3;
      }
      if ((k + 1) % 50 == 0) {
        std::printf("%6.3f %12.6f %12.6f\n", stepper.time(), stepper.sample().elements[0].tension,
                    excitation_now);
      }
    }
    std::printf("steps %ld over %d samples\n", stepper.stats().steps, 600);
  } catch (const std::exception& e) {  // ParameterError: the field and the rule
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
