#include "musclesim/model/velocity.h"

#include <algorithm>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

bool IsExponent(int n) { return n >= 1 && n <= kMaxVelocityExponent; }

// (alpha - 1) / 2, the power of v^2 + eps^2 in phi_eps (docs/model.md section 4).
double HalfExponent(double alpha) { return 0.5 * (alpha - 1.0); }

}  // namespace

void Validate(const VelocityParams& params) {
  Require(std::isfinite(params.v_max) && params.v_max > 0.0, "v_max", params.v_max,
          "must be finite and > 0 [m/s]");
  Require(IsExponent(params.n), "n", params.n, "must be an integer >= 1 (at most 1000)");
  // Below 1e-12 v_max the slope at v = 0, (eps / v_max)^(1/n - 1) / v_max, reaches 1e12 / v_max:
  // the actuator's time constant falls below what double-precision time can resolve (and
  // eps^2 underflows further down). Above v_max the regularisation swamps the curve.
  Require(std::isfinite(params.epsilon) && params.epsilon >= 1e-12 * params.v_max &&
              params.epsilon <= params.v_max,
          "epsilon", params.epsilon,
          "must be between 1e-12 v_max and v_max = " + FormatNumber(params.v_max) +
              " [m/s] (smaller: too stiff to integrate in double precision; larger: the "
              "regularisation replaces the power law)");

  const EccentricParams& e = params.eccentric;
  if (e.v_max) {
    Require(std::isfinite(*e.v_max) && *e.v_max > 0.0, "eccentric.v_max", *e.v_max,
            "must be finite and > 0 [m/s]");
    // the lengthening branch is regularised with the same eps: the same rule, read for v_max_e
    Require(params.epsilon >= 1e-12 * *e.v_max && params.epsilon <= *e.v_max, "eccentric.v_max",
            *e.v_max,
            "must be between epsilon = " + FormatNumber(params.epsilon) +
                " and 1e12 epsilon "
                "[m/s] (epsilon's rule, between 1e-12 v_max and v_max, holds for the eccentric "
                "v_max too)");
  }
  if (e.n) {
    Require(IsExponent(*e.n), "eccentric.n", *e.n, "must be an integer >= 1 (at most 1000)");
  }
  if (e.limit) {
    Require(std::isfinite(*e.limit) && *e.limit > 1.0 && *e.limit <= kMaxEccentricLimit,
            "eccentric.limit", *e.limit,
            "must be > 1 and <= 1e6 [-]: the bound of g as the lengthening velocity grows lies "
            "above g(0) = 1, and a bound beyond 1e6 bounds nothing (leave it out for none)");
  }
}

VelocityCurve::VelocityCurve(const VelocityParams& params)
    : params_((Validate(params), params)),
      alpha_(1.0 / params.n),
      half_exponent_(HalfExponent(alpha_)),
      epsilon_squared_(params.epsilon * params.epsilon),
      inverse_scale_(std::pow(params.v_max, -alpha_)),
      linear_(params.n == 1) {
  const EccentricParams& e = params.eccentric;
  const int n_e = e.n.value_or(params.n);
  const double v_max_e = e.v_max.value_or(params.v_max);
  asymmetric_ = n_e != params.n || v_max_e != params.v_max || e.limit.has_value();
  eccentric_.alpha = 1.0 / n_e;
  eccentric_.half_exponent = HalfExponent(eccentric_.alpha);
  eccentric_.inverse_scale = std::pow(v_max_e, -eccentric_.alpha);
  eccentric_.linear = n_e == 1;
  if (e.limit) {
    eccentric_.bounded = true;
    eccentric_.headroom = *e.limit - 1.0;
    eccentric_.inverse_headroom = 1.0 / eccentric_.headroom;
  }
  // the one-sided slopes at v = 0 (sech^2(0) = 1: the limit does not change them)
  const double right = Evaluate(0.0).slope;
  const double left = asymmetric_ ? Lengthening(-0.0).slope : right;
  has_kink_ = std::abs(left - right) > 1e-13 * std::max(std::abs(left), std::abs(right));
}

}  // namespace musclesim
