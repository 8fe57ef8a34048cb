// Private: reads a whole scenario document (used by LoadScenario and by the model reader,
// which validates a model file that is a scenario as one).
#pragma once

#include "io/yaml_fields.h"
#include "musclesim/io/scenario.h"

namespace musclesim {

// `root` is the document's top-level map. Throws InputError as LoadScenario says.
ScenarioSpec ReadScenario(const yaml::Source& source, const YAML::Node& root);

}  // namespace musclesim
