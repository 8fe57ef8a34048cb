// Reading the `model:` block of a scenario file (docs/guide/model.md): validated
// parameters, with the Gaussian fit run at load time when the block asks for one.
#pragma once

#include <optional>
#include <string>

#include "musclesim/model/model_spec.h"

namespace musclesim {

// Reads the `model` block of `path`. A file of `name` and `model` only is a model file; a
// file with any other key of a scenario is read whole as a scenario (LoadScenario), so that
// no misspelt key anywhere in it passes. Throws InputError naming file:line:column, key,
// value and rule.
ModelSpec LoadModelSpec(const std::string& path);

// As LoadModelSpec, for `musclesim fit`: the block must ask for a fit (active_length.fit);
// explicit gaussians are an InputError placed at them. fit and fit_result are then set.
ModelSpec LoadModelFit(const std::string& path);

}  // namespace musclesim
