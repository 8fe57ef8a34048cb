// Private: the network scenario reader on a document already parsed (and overridden), shared
// by LoadNetworkScenario and NetworkScenarioTemplate.
#pragma once

#include <yaml-cpp/yaml.h>

#include "io/yaml_fields.h"
#include "musclesim/io/network_scenario.h"

namespace musclesim {

// Reads and validates the top-level map `root` of the network scenario `src.file`, as
// LoadNetworkScenario says (InputError naming file:line:column, key path, value and rule).
NetworkScenarioSpec ReadNetworkScenario(const yaml::Source& src, const YAML::Node& root);

}  // namespace musclesim
