// A scenario: everything one run needs, in memory. A network of nodes, elements, loads and
// controllers (docs/model.md sections 7 and 11) with the tension models its actuators share,
// the time span, the solver's options, the output grid and the limits; and how it was
// written, which decides how its runs are recorded (scenario/run_columns.h). The single
// actuator of a file's single-actuator form is the network of docs/model.md 7.4, built by
// scenario/actuator_scenario.h; there is no other kind of scenario.
//
// The YAML reader makes one (io/readers/scenario_yaml.h), C++ and Python build one directly, and
// parameter handles (scenario/parameter.h) change its numbers in place. A Scenario is a value:
// copies are independent, and building its system (Build) reads it without changing it.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/model/model_spec.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// How a scenario was written: which columns its runs record.
enum class ScenarioForm {
  kNetwork,   // nodes and elements: the network's columns (scenario/run_columns.h)
  kActuator,  // the single actuator (docs/model.md 7.4): t, length, ..., phase
};

// The rows a run records.
struct OutputRequest {
  std::string file;         // CSV path [-], relative to the working directory; "-": stdout
  double interval = 0.0;    // time between rows [s]; 0 with every_step
  bool every_step = false;  // `interval: steps`: a row per internal step [-]
  std::optional<double> phase_tolerance;  // v_tol [m/s]; default: each actuator's model's
                                          // velocity epsilon
};

// A named model block and the tension model built from it, which the actuators naming the
// block hold.
struct ScenarioModel {
  ModelSpec spec;                             // as written (units as in ModelParams)
  std::shared_ptr<const TensionModel> model;  // BuildModel(spec); never null once added
};

struct Scenario {
  std::string name;    // for messages [-]
  std::string source;  // the file it was read from, or a name for one built in code [-]
  ScenarioForm form = ScenarioForm::kNetwork;
  Space space;  // `dimensions` and `gravity` (docs/model.md 12); a line by default
  std::map<std::string, ScenarioModel> models;  // by name (the single actuator's: "model")
  std::vector<Node> nodes;                      // in the file's order, the CSV's column order
  std::vector<Element> elements;        // in the file's order; an actuator's model is one of
                                        // `models`' (AddModel, SetModel keep them so)
  std::vector<NodeLoad> loads;          // in the file's order
  std::vector<Controller> controllers;  // in the file's order
  // a skeleton (docs/model.md 15): its bodies and the joints joining them, in the file's order
  std::vector<Body> bodies;
  std::vector<Joint> joints;
  std::vector<WrapCylinder> wraps;  // wrap surfaces on the bodies (or the ground)
  // Whether it has a skeleton's parts: bodies, joints or wrap surfaces.
  bool HasSkeleton() const { return !bodies.empty() || !joints.empty() || !wraps.empty(); }
  double t_start = 0.0, t_end = 1.0;  // the simulated interval [s], t_end > t_start
  SolverOptions solver;               // units as in SolverOptions
  OutputRequest output;               // units as in OutputRequest
  std::vector<LengthLimit> limits;    // stop when an element's length leaves them [m]
  // `sensitivities:` the key paths of the parameters whose forward sensitivities a run adds
  // (docs/model.md 10), and where each was given ("file:line:column"; empty in code)
  std::vector<std::string> sensitivities, sensitivities_at;

  // Adds (or replaces) the model block `name`, built with BuildModel (ParameterError with
  // paths relative to the block), and returns the tension model an actuator should hold.
  std::shared_ptr<const TensionModel> AddModel(const std::string& block, ModelSpec spec);
  // Replaces block `name`'s spec, rebuilds its model (refitting its Gaussians when it asks
  // for a fit) and points every actuator that held the old model at the new one. Leaves the
  // scenario unchanged when BuildModel throws.
  void SetModel(const std::string& block, ModelSpec spec);
  // Rebuilds block `name`'s model from its spec as it now is (SetModel with that spec).
  void RebuildModel(const std::string& block) { SetModel(block, models.at(block).spec); }
  // The block whose model `model` is, or nullptr.
  const std::string* ModelName(const TensionModel* model) const;

  // The system the scenario describes. Throws ParameterError ("elements[2].to",
  // "controllers[0].drives", ...) when its parts do not fit.
  NetworkSystem Build() const;
  // The run's span, grid and limits (NetworkRunRequest's initial_state empty: the nodes').
  NetworkRunRequest Request() const;
  // Everything a run checks before it starts, without running: the system builds, every
  // element is longer than zero at t_start, the limits bracket their elements' initial
  // lengths, the solver options and the request are valid and a `small` solver fits. Throws
  // ParameterError with the scenario's key paths.
  void Validate() const;

  // The handle on the number at key path `path` (FindParameter, scenario/parameter.h):
  // scenario.parameter("model.f_iso").Set(scenario, 120.0).
  Parameter parameter(const std::string& path) const { return FindParameter(*this, path); }

  // v_tol [m/s] of actuator element `e`'s phase column: output.phase_tolerance, else its
  // model's velocity epsilon.
  double PhaseTolerance(int e) const;
};

// A scenario and its system, built once. A network's reader builds the system to check how the
// parts fit, placing every error in the file, and hands it on here, so that a run does not build
// it again. The system is of the scenario as read: whoever changes the scenario builds anew.
struct LoadedScenario {
  Scenario scenario;
  // scenario.Build()'s: never null from LoadBuiltScenario and ReadBuiltScenario; null where a
  // maker built none (ScenarioTemplate::InstantiateLoaded, a sweep's PointFactory)
  std::shared_ptr<const NetworkSystem> system;
};

}  // namespace musclesim
