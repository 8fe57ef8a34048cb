#include "musclesim/model/velocity.h"

#include "musclesim/errors.h"

namespace musclesim {

void Validate(const VelocityParams& params) {
  Require(std::isfinite(params.v_max) && params.v_max > 0.0, "v_max", params.v_max,
          "must be finite and > 0 [m/s]");
  Require(params.n >= 1, "n", params.n, "must be an integer >= 1");
  Require(std::isfinite(params.epsilon) && params.epsilon > 0.0, "epsilon", params.epsilon,
          "must be finite and > 0 [m/s]");
}

VelocityCurve::VelocityCurve(const VelocityParams& params)
    : params_((Validate(params), params)),
      alpha_(1.0 / params.n),
      half_exponent_(0.5 * (alpha_ - 1.0)),
      epsilon_squared_(params.epsilon * params.epsilon),
      inverse_scale_(std::pow(params.v_max, -alpha_)),
      linear_(params.n == 1) {}

}  // namespace musclesim
