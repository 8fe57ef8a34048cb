// A model block as written (docs/guide/model.md): the tension model's parameters and, when
// the block asks for one, the closed-form fit of its Gaussians, run again whenever the
// parameters it depends on change.
#pragma once

#include <memory>
#include <optional>

#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/tension.h"

namespace musclesim {

struct ModelSpec {
  ModelParams params;                   // valid: TensionModel(params) does not throw; units as
                                        // in ModelParams
  std::optional<FitSpec> fit;           // the fit the file asked for, if any; units as in FitSpec
  std::optional<FitResult> fit_result;  // that fit's result; units as in FitResult
};

// Runs spec.fit, when the block has one and fit_result is not yet set, over the optimal range
// and sigma of spec.params.active_length, and puts its components into spec.params
// (fit_result set too); then builds the tension model. A change of what the fit depends on
// (the range, sigma, the fit's own settings) clears fit_result first. Throws ParameterError (paths
// relative to the block: "velocity.n", "active_length.fit.count") for parameters the model or the
// fit refuses.
std::shared_ptr<const TensionModel> BuildModel(ModelSpec& spec);

}  // namespace musclesim
