// Forward sensitivities of a network with a massless junction against finite differences of
// full runs (support/sensitivity_reference.h). The junction's velocity w is no state: it is
// the root of its force balance, so the sensitivity equations see it through the Jacobian's
// row dw/dy (the implicit function theorem), the columns through dw/dy s, and a parameter
// through dw/dp, taken by re-solving the balance of the scenario rebuilt at p +- h
// (docs/model.md 14.4).
#include <gtest/gtest.h>

#include <string>

#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::ExpectSensitivitiesMatchDifferences;

// De Groote's fiber (fiber damping 0.01) from a wall to a massless junction, activated from
// 0.2 towards 0.6 through its activation dynamics; De Groote's tendon from the junction to a
// 0.5 kg end pulled by 20 +- 10 N at 4 Hz. The junction's velocity moves with every state
// (its own position, the end's position and velocity, the activation) and with the fiber's and
// the tendon's parameters; no kink (the curves are smooth, the activation never meets its
// excitation). Both sides at rtol 1e-12.
constexpr const char* kNetwork = R"(name: junction_sensitivities
models:
  muscle: {family: degroote2016, f_iso: 100.0, optimal_fiber_length: 0.1,
           max_contraction_velocity: 10.0, fiber_damping: 0.01}
nodes:
  - {name: wall, fixed: 0.0}
  - {name: junction, mass: 0, position: 0.099}
  - {name: end, mass: 0.5, position: 0.3, velocity: 0.0}
elements:
  - {name: muscle, type: actuator, from: wall, to: junction, model: muscle,
     excitation: {type: constant, value: 0.6},
     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}, initial_activation: 0.2}
  - {name: tendon, type: tendon, from: junction, to: end, slack_length: 0.2,
     degroote2016: {max_isometric_force: 100.0, strain_at_one_norm_force: 0.049}}
loads:
  - {node: end, type: sine, offset: 20.0, amplitude: 10.0, frequency: 4.0}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: junction.csv, interval: 0.025}
)";

std::string Network() { return testing::WriteTempFile("junction.yaml", kNetwork); }

TEST(SensitivityJunction, FiberParameters) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {}, {At("models.muscle.f_iso", 100.0), At("models.muscle.fiber_damping", 0.01)});
}

TEST(SensitivityJunction, TendonSlackLength) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("elements[1].slack_length", 0.2)});
}

TEST(SensitivityJunction, TheJunctionsInitialPosition) {
  ExpectSensitivitiesMatchDifferences(Network(), {}, {At("nodes[1].position", 0.099)});
}

TEST(SensitivityJunction, ActivationAndLoad) {
  ExpectSensitivitiesMatchDifferences(
      Network(), {}, {At("elements[0].initial_activation", 0.2), At("loads[0].amplitude", 10.0)});
}

}  // namespace
}  // namespace musclesim
