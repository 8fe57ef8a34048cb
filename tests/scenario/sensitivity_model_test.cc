// Forward sensitivities to the tension model's parameters (closed-form df/dp,
// model/tension_parameter.h) against finite differences of full runs
// (support/sensitivity_reference.h): one test per part of the model, in a single actuator and
// through a network whose two actuators share one `models:` block.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "support/scenario_files.h"
#include "support/sensitivity_reference.h"

namespace musclesim {
namespace {

using testing::At;
using testing::Differentiated;
using testing::ExpectSensitivitiesMatchDifferences;

// The canonical actuator's curves with an asymmetric velocity curve (eccentric v_max, n and
// a limit: v = 0 is a kink) and eps = 1e-2 m/s (less stiff, so that tight tolerances stay
// cheap). A 85 +- 50 N, 4 Hz load on the fully active actuator, starting 1.3 mm below the
// slack length: it lengthens past the slack length (at 0.040 s), shortens below it again
// (0.161 s), and its velocity changes sign at 0.107 s and 0.244 s.
//
// Both sides, the run with sensitivities and the full runs of the reference, at rtol 1e-12
// and atol 1e-14 (lengths ~0.1 m, velocities ~0.1 m/s): the reference's share of the
// integrator's error, ~ rtol |C| / h, must stay below 1e-6 of a column's derivative. Rows
// every 25 ms, at least 5 ms from those crossings (7 ms from the slack length's; with the
// optimal ranges below too), so that the reference's smaller steps move no kink across a
// row: there a column is not differentiable in p, and a quotient measures neither side.
constexpr const char* kModelBlock = R"(  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    sigma: 1.0
    gaussians:
      - {amplitude: 0.35188944617853268, width: 20635.199147929347, center: 0.073556703926583866}
      - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
      - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2, eccentric: {v_max: 0.5, n: 2, limit: 1.8}}
)";

std::string SingleActuator() {
  return testing::WriteTempFile(
      "single.yaml", std::string("name: model_sensitivities\nmodel:\n") + kModelBlock + R"(
actuator: {mass: 0.1}
initial: {length: 0.1037}
activation: {type: constant, value: 1.0}
load: {type: sine, offset: 85.0, amplitude: 50.0, frequency: 4.0, phase: 0.3}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: single.csv, interval: 0.025}
)");
}

// The same model as `models.muscle`, held by two actuators on either side of a 0.1 kg mass
// (activations 0.6 and 0.4, so that they do not mirror each other), both 0.1036 m long at
// the start; a 30 +- 40 N, 4 Hz load on the mass stretches the flexor past the slack length
// (0.035 s) while the extensor shortens, and the mass turns back at 0.139 s and 0.235 s:
// rows every 25 ms are about 10 ms from each.
std::string SharedModelNetwork() {
  std::string model = kModelBlock;
  // indent the block under models.muscle
  std::string indented;
  for (std::size_t at = 0; at < model.size();) {
    const std::size_t end = model.find('\n', at);
    indented += "  " + model.substr(at, end - at + 1);
    at = end + 1;
  }
  return testing::WriteTempFile("network.yaml",
                                "name: shared_model\nmodels:\n  muscle:\n" + indented + R"(
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1036, velocity: 0.0}
  - {name: wall_b, fixed: 0.2072}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle, activation: {type: constant, value: 0.6}}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle, activation: {type: constant, value: 0.4}}
loads:
  - {node: load, type: sine, offset: 30.0, amplitude: 40.0, frequency: 4.0, phase: 0.0}
time: {start: 0.0, end: 0.25}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: network.csv, interval: 0.025}
)");
}

// Each part's parameters, relative to the model block ("f_iso", ...), with their values.
std::vector<Differentiated> Under(const std::string& prefix,
                                  const std::vector<std::pair<std::string, double>>& values) {
  std::vector<Differentiated> out;
  for (const auto& [path, value] : values) out.push_back(At(prefix + path, value));
  return out;
}

const std::vector<std::pair<std::string, double>> kIsometric = {{"f_iso", 100.0}};
const std::vector<std::pair<std::string, double>> kPassive = {
    {"passive.k_p", 1.0}, {"passive.alpha", 100.0}, {"passive.slack_length", 0.105}};
const std::vector<std::pair<std::string, double>> kGaussians = {
    {"active_length.gaussians[0].amplitude", 0.35188944617853268},
    {"active_length.gaussians[0].width", 20635.199147929347},
    {"active_length.gaussians[0].center", 0.073556703926583866},
    {"active_length.gaussians[1].amplitude", 2.2575025981825489},
    {"active_length.gaussians[1].width", 4125.1402656159307},
    {"active_length.gaussians[1].center", 0.097194271247335401},
    {"active_length.gaussians[2].amplitude", 1.3136662819543681},
    {"active_length.gaussians[2].width", 3009.3607405177986},
    {"active_length.gaussians[2].center", 0.1301541244400391}};
const std::vector<std::pair<std::string, double>> kSigma = {{"active_length.sigma", 1.0}};
const std::vector<std::pair<std::string, double>> kVelocity = {{"velocity.v_max", 1.0},
                                                               {"velocity.epsilon", 1e-2}};
const std::vector<std::pair<std::string, double>> kEccentric = {{"velocity.eccentric.v_max", 0.5},
                                                                {"velocity.eccentric.limit", 1.8}};

// f_peak, the maximum of f over L_opt, is interior in the file (near 0.1006 m), where the
// ends of L_opt do not move it. Two ranges put it at an end: [0.090, 0.098] below the
// maximum of f (at its upper end, f rising) and [0.102, 0.110] above it (at its lower end).
const std::vector<std::string> kPeakAtUpperEnd = {"optimal_range[0]=0.090",
                                                  "optimal_range[1]=0.098"};
const std::vector<std::string> kPeakAtLowerEnd = {"optimal_range[0]=0.102",
                                                  "optimal_range[1]=0.110"};

std::vector<std::string> RangeOverrides(const std::string& prefix,
                                        const std::vector<std::string>& range) {
  std::vector<std::string> out;
  for (const std::string& set : range) out.push_back(prefix + "active_length." + set);
  return out;
}

std::vector<Differentiated> RangeEnds(const std::string& prefix, double l1, double l2) {
  return {At(prefix + "active_length.optimal_range[0]", l1),
          At(prefix + "active_length.optimal_range[1]", l2)};
}

TEST(SensitivityModel, IsometricTension) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kIsometric));
}

TEST(SensitivityModel, PassiveAcrossTheSlackLength) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kPassive));
}

TEST(SensitivityModel, GaussiansWithAnInteriorPeak) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kGaussians));
}

TEST(SensitivityModel, Sigma) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kSigma));
}

TEST(SensitivityModel, OptimalRangeWithThePeakAtItsUpperEnd) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), RangeOverrides("model.", kPeakAtUpperEnd),
                                      RangeEnds("model.", 0.090, 0.098));
}

TEST(SensitivityModel, OptimalRangeWithThePeakAtItsLowerEnd) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), RangeOverrides("model.", kPeakAtLowerEnd),
                                      RangeEnds("model.", 0.102, 0.110));
}

TEST(SensitivityModel, ConcentricVelocity) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kVelocity));
}

TEST(SensitivityModel, EccentricVelocityAcrossZero) {
  ExpectSensitivitiesMatchDifferences(SingleActuator(), {}, Under("model.", kEccentric));
}

// the network: models.muscle.* moves both actuators at once
constexpr const char* kShared = "models.muscle.";

TEST(SensitivitySharedModel, IsometricTension) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kIsometric));
}

TEST(SensitivitySharedModel, PassiveAcrossTheSlackLength) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kPassive));
}

TEST(SensitivitySharedModel, GaussiansWithAnInteriorPeak) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kGaussians));
}

TEST(SensitivitySharedModel, Sigma) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kSigma));
}

TEST(SensitivitySharedModel, OptimalRangeWithThePeakAtItsUpperEnd) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(),
                                      RangeOverrides(kShared, kPeakAtUpperEnd),
                                      RangeEnds(kShared, 0.090, 0.098));
}

TEST(SensitivitySharedModel, OptimalRangeWithThePeakAtItsLowerEnd) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(),
                                      RangeOverrides(kShared, kPeakAtLowerEnd),
                                      RangeEnds(kShared, 0.102, 0.110));
}

TEST(SensitivitySharedModel, ConcentricVelocity) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kVelocity));
}

TEST(SensitivitySharedModel, EccentricVelocityAcrossZero) {
  ExpectSensitivitiesMatchDifferences(SharedModelNetwork(), {}, Under(kShared, kEccentric));
}

}  // namespace
}  // namespace musclesim
