#include "musclesim/model/model_spec.h"

#include "musclesim/core/errors.h"

namespace musclesim {

std::shared_ptr<const TensionModel> BuildModel(ModelSpec& spec) {
  if (spec.fit && !spec.fit_result) {
    ActiveLengthParams& active = spec.params.active_length;
    try {
      spec.fit_result =
          FitGaussians(*spec.fit, active.optimal_min, active.optimal_max, active.sigma);
    } catch (const ParameterError& error) {
      throw ParameterError("active_length.fit." + error.path(), error.value(), error.rule());
    }
    active.gaussians = spec.fit_result->gaussians;
  }
  return std::make_shared<const TensionModel>(spec.params);
}

}  // namespace musclesim
