// A network scenario: the nodes, elements and loads of a network on a line (docs/model.md
// section 7), its feedback controllers (section 11), their tension models, the solver, the
// output and the limits of one run, read from YAML and validated before anything runs. A
// file with a top-level `nodes:` key is a network; any other is the single-actuator form of
// io/scenario.h.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/io/model_yaml.h"
#include "musclesim/io/scenario.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

struct NetworkScenarioSpec {
  std::string name;                        // the scenario's name, for messages [-]
  std::string source;                      // the file it came from [-]
  std::map<std::string, ModelSpec> models;  // the `models:` blocks by name, as read; units as
                                           // in ModelParams. The actuators already hold the
                                           // tension models built from them (Element::model):
                                           // changing a block here changes no element
  std::map<std::string, std::shared_ptr<const TensionModel>> tension_models;  // built from
                                           // `models`, by name: what the actuators hold
  std::vector<Node> nodes;                 // in the file's order, the CSV's column order
  std::vector<Element> elements;           // in the file's order
  std::vector<NodeLoad> loads;             // in the file's order
  std::vector<Controller> controllers;     // in the file's order, the CSV's column order;
                                           // the actuators they drive are controlled ones
  double t_start = 0.0, t_end = 1.0;       // the simulated interval [s], t_end > t_start
  SolverOptions solver;                    // units as in SolverOptions
  OutputSpec output;                       // units as in OutputSpec
  std::vector<LengthLimit> limits;         // stop when an element's length leaves them [m]
  std::vector<std::string> sensitivities, sensitivities_at;  // as ScenarioSpec's

  // The system the scenario describes. Throws ParameterError if parts changed in code break
  // a rule (the reader has validated everything it read).
  NetworkSystem Build() const;
  NetworkRunRequest Request() const;
};

// Whether `path` holds a network: a look at the top-level keys of its first YAML document,
// stopping at `nodes`, without building the document. A file that is not a map (or is
// empty) is not a network; the single-actuator reader then says what is wrong with it.
// Throws InputError if the file cannot be read or is not YAML.
bool IsNetworkScenario(const std::string& path);

// Reads and validates the network scenario `path`, applying each "dotted.path=value"
// override first (as `--set` gives them, e.g. "elements[1].activation.after=0.5"). Checks
// everything a run would: names unique, references resolved, every free node joined to a
// fixed or prescribed node, every controller fitting the network (docs/model.md 11), every
// element longer than zero at the start, the limits against the elements' initial lengths.
// Throws InputError naming file:line:column (or --set), key path, value and rule.
NetworkScenarioSpec LoadNetworkScenario(const std::string& path,
                                        const std::vector<std::string>& overrides = {});

// LoadNetworkScenario, then one run on a new Simulation. A solver failure (an element's
// length reaching zero among them) is a result (stats.status kFailed), not an exception.
NetworkRunResult RunNetworkScenarioFile(const std::string& path,
                                        const std::vector<std::string>& overrides = {});

}  // namespace musclesim
