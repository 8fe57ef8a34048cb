// The single actuator (docs/model.md section 6) as the network of section 7.4: node `ground`
// fixed at 0 and node `tip` free, carrying the actuator's mass and the loads; elements
// `actuator` (its tension model), `damper` and `spring` from ground to tip. Its scenario's
// form is ScenarioForm::kActuator, so its runs record the single actuator's columns.
//
// The file's single-actuator keys name values of that network; ActuatorKeyPath and
// NetworkKeyPath translate between the two, so that a parameter, a message or a sensitivity
// column says `actuator.mass` where the network holds nodes[1].mass.
//
// This file is the form's whole vocabulary: code that serves both forms asks the functions
// taking a Scenario below (FileKeyPath, ElementColumn, ...) what the file calls a part or a
// value, rather than testing the form itself. Beside them only the reader that tells the form,
// the columns (run_columns.h, sensitivity_columns.h), the writers of a form's own keys and a
// sweep's signature (which leaves the single actuator's metric element out, as sweeps written
// before networks have it) tell the forms apart.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/actuator.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

// The single actuator as a file's single-actuator form gives it (docs/guide/scenarios.md).
struct ActuatorScenarioSpec {
  std::string name;                              // the scenario's name, for messages [-]
  std::string source;                            // the file it came from [-]
  ModelSpec model;                               // units as in ModelParams
  ActuatorParams actuator;                       // units as in ActuatorParams
  double initial_length = 0.0;                   // x(t_start) [m], > 0
  double initial_lengthening_rate = 0.0;         // dx/dt at t_start [m/s]
  Waveform activation;                           // u(t) [-], within [0, 1]; unused with excitation
  std::optional<ExcitationInput> excitation;     // activation dynamics (docs/model.md 8)
  std::vector<Load> loads;                       // units as in Load
  double t_start = 0.0, t_end = 1.0;             // the simulated interval [s], t_end > t_start
  SolverOptions solver;                          // units as in SolverOptions
  OutputRequest output;                          // units as in OutputRequest
  std::optional<double> min_length, max_length;  // stop when x leaves them [m]
  std::vector<std::string> sensitivities, sensitivities_at;  // as Scenario's
};

// The network of docs/model.md 7.4 for `spec`: the damper and the spring are there even when
// their coefficient is 0 (a zero term changes no sum), so that every key of the form has its
// value in the network. Throws ParameterError (as BuildModel, and Validate of the actuator)
// with the form's key paths.
Scenario MakeActuatorScenario(ActuatorScenarioSpec spec);

// The single actuator of `spec` as dynamics/actuator.h's closed-form system, and its run's
// request: the reference its network is checked against bit for bit, and what peers written
// for the two-state system (the benchmarks') integrate. Throws ParameterError as
// MakeActuatorScenario does.
ActuatorSystem MakeActuatorSystem(const ActuatorScenarioSpec& spec);
RunRequest MakeActuatorRunRequest(const ActuatorScenarioSpec& spec);

// The network's key path of a single-actuator key ("actuator.mass" -> "nodes[1].mass",
// "model.f_iso" -> "models.model.f_iso", "load[0].value" -> "loads[0].value"), or nullopt
// for a key outside the form's vocabulary.
std::optional<std::string> NetworkKeyPath(const std::string& actuator_path);
// The other way: the single-actuator key of a path into its network ("nodes[1].velocity" ->
// "initial.lengthening_rate"), or the path unchanged where the form has no key for it.
std::string ActuatorKeyPath(const std::string& network_path);

// The single actuator's sample (dynamics/actuator.h) as its network observes it: the
// actuator element's length, shortening velocity (+0 rather than -0 at rest), activation,
// excitation and tension, and the load on the tip.
ActuatorSample ActuatorSampleOf(const NetworkSample& sample);
// The same of the actuator element's sample and the load on the tip [N].
ActuatorSample ActuatorSampleOf(const ElementSample& actuator, double load);

// What the file of `scenario` calls things, for code that serves both forms. A network's file
// calls each by the network's own name.
bool IsSingleActuator(const Scenario& scenario);
// The file's key path of `network_path` (ActuatorKeyPath for the single actuator).
std::string FileKeyPath(const Scenario& scenario, const std::string& network_path);
// The network's key path of the file's `path`, or nullopt for a key the single actuator's
// form does not have (NetworkKeyPath); a network's `path` unchanged.
std::optional<std::string> NetworkPathOf(const Scenario& scenario, const std::string& path);
// The CSV column of element `element`'s `quantity` ("shortening_velocity"): the single
// actuator's bare, a network's "ELEMENT.quantity".
std::string ElementColumn(const Scenario& scenario, const std::string& element,
                          const std::string& quantity);
// " of ELEMENT", naming an element in a message; "" for the single actuator, the only one.
std::string OfElement(const Scenario& scenario, const std::string& element);
// An element's initial length as a message names it ("initial.length" for the single
// actuator, whose element starts there).
std::string InitialLengthName(const Scenario& scenario);

// The indices of the network's parts.
inline constexpr int kActuatorTipNode = 1;        // `tip`
inline constexpr int kActuatorElement = 0;        // `actuator`
inline constexpr int kActuatorDamperElement = 1;  // `damper`
inline constexpr int kActuatorSpringElement = 2;  // `spring`

}  // namespace musclesim
