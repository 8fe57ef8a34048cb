#include "musclesim/model/velocity.h"

#include "musclesim/errors.h"

namespace musclesim {

void Validate(const VelocityParams& params) {
  Require(std::isfinite(params.v_max) && params.v_max > 0.0, "v_max", params.v_max,
          "must be finite and > 0 [m/s]");
  Require(params.n >= 1 && params.n <= kMaxVelocityExponent, "n", params.n,
          "must be an integer >= 1 (at most 1000)");
  // Below 1e-12 v_max the slope at v = 0, (eps / v_max)^(1/n - 1) / v_max, reaches 1e12 / v_max:
  // the actuator's time constant falls below what double-precision time can resolve (and
  // eps^2 underflows further down). Above v_max the regularisation swamps the curve.
  Require(std::isfinite(params.epsilon) && params.epsilon >= 1e-12 * params.v_max &&
              params.epsilon <= params.v_max,
          "epsilon", params.epsilon,
          "must be between 1e-12 v_max and v_max = " + FormatNumber(params.v_max) +
              " [m/s] (smaller: too stiff to integrate in double precision; larger: the "
              "regularisation replaces the power law)");
}

VelocityCurve::VelocityCurve(const VelocityParams& params)
    : params_((Validate(params), params)),
      alpha_(1.0 / params.n),
      half_exponent_(0.5 * (alpha_ - 1.0)),
      epsilon_squared_(params.epsilon * params.epsilon),
      inverse_scale_(std::pow(params.v_max, -alpha_)),
      linear_(params.n == 1) {}

}  // namespace musclesim
