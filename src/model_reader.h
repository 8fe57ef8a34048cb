// Private: reads a `model:` node into validated parameters (used by every file reader).
#pragma once

#include "musclesim/model_file.h"
#include "yaml_fields.h"

namespace musclesim {

// `node` is the value of the `model` key, `path` its key path ("model").
LoadedModel ReadModel(const yaml::Source& source, const YAML::Node& node,
                      const std::string& path);

}  // namespace musclesim
