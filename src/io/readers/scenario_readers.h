// Private: the readers of the two forms of a scenario file, on a document already parsed (and
// overridden), shared by LoadScenario, ScenarioTemplate and the model reader (which validates
// a model file that is a scenario as one).
#pragma once

#include "io/readers/yaml_fields.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

// The single-actuator form of the top-level map `root`, as written (InputError naming
// file:line:column, key path, value and rule).
ActuatorScenarioSpec ReadActuatorScenarioSpec(const yaml::Source& source, const Document& root);
// The same, built into its network (docs/model.md 7.4).
Scenario ReadActuatorScenario(const yaml::Source& source, const Document& root);

// The network form of the top-level map `root` (a `nodes:` key), validated as a whole, and the
// system that validation built.
LoadedScenario ReadNetworkScenario(const yaml::Source& source, const Document& root);

}  // namespace musclesim
