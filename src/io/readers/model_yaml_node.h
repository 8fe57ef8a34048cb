// Private: reads a `model:` node into validated parameters (used by every file reader).
#pragma once

#include <initializer_list>

#include "musclesim/io/readers/model_yaml.h"
#include "io/readers/yaml_fields.h"

namespace musclesim {

// The top-level keys of a scenario file: readers of any part of one accept these and no
// others, so a misspelt key is caught whichever verb reads the file.
inline constexpr std::initializer_list<const char*> kScenarioKeys = {
    "name", "model", "actuator", "initial", "activation", "excitation",   "activation_dynamics",
    "load", "time",  "solver",   "output",  "limits",     "sensitivities"};

// A block whose `family` is not the paper's (model_family_yaml.cc).
ModelSpec ReadFamilyModelSpec(const yaml::Source& source, const Document& node,
                              const std::string& path, CurveFamily family);

// `node` is the value of the `model` key, `path` its key path ("model").
ModelSpec ReadModelSpec(const yaml::Source& source, const Document& node, const std::string& path);

}  // namespace musclesim
