// Tension-velocity factor g(v) (paper eq. 12, docs/model.md section 4) with the paper's
// epsilon regularisation of sgn(v) |v|^(1/n), which makes g smooth at v = 0.
#pragma once

#include <cmath>

#include "musclesim/model/curve_point.h"

namespace musclesim {

// The largest curvature n accepted: the power 1/n is then 0.001, the curve a step.
inline constexpr int kMaxVelocityExponent = 1000;

struct VelocityParams {
  double v_max = 1.0;      // maximum shortening velocity [m/s], > 0
  int n = 1;               // curvature [-]: the power is 1/n, an integer >= 1
  double epsilon = 1e-3;   // regularisation width [m/s], > 0
};

// Throws ParameterError ("v_max", "n", "epsilon").
void Validate(const VelocityParams& params);

// phi_eps(v) = v (v^2 + eps^2)^((alpha - 1)/2) with alpha = 1/n, and its slope. Immutable
// after construction; evaluation costs one pow (none for n = 1) and allocates nothing.
class VelocityCurve {
 public:
  // Validates `params` (ParameterError).
  explicit VelocityCurve(const VelocityParams& params);

  // phi_eps and dphi_eps/dv, the regularised sgn(v)|v|^alpha.
  CurvePoint Phi(double v) const {
    const double w = v * v + epsilon_squared_;
    const double p = linear_ ? 1.0 : std::pow(w, half_exponent_);
    return {v * p, p * (alpha_ * v * v + epsilon_squared_) / w};
  }

  // g_eps(v) = 1 - phi_eps(v) / v_max^alpha and dg_eps/dv, v the shortening velocity.
  CurvePoint Evaluate(double v) const {
    const CurvePoint phi = Phi(v);
    return {1.0 - phi.value * inverse_scale_, -phi.slope * inverse_scale_};
  }

  const VelocityParams& params() const { return params_; }
  double alpha() const { return alpha_; }

 private:
  VelocityParams params_;
  double alpha_;             // 1 / n [-]
  double half_exponent_;     // (alpha - 1) / 2 [-]
  double epsilon_squared_;   // eps^2 [m^2/s^2]
  double inverse_scale_;     // v_max^-alpha [(s/m)^alpha]
  bool linear_;              // n == 1: phi_eps(v) = v exactly
};

}  // namespace musclesim
