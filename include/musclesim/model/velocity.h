// Tension-velocity factor g(v) (paper eq. 12, docs/model.md section 4) with the paper's
// epsilon regularisation of sgn(v) |v|^(1/n), which makes g smooth at v = 0; and its
// asymmetric form (docs/model.md section 9): the lengthening branch with its own v_max and n
// and, optionally, a bound L on the eccentric tension.
#pragma once

#include <cmath>
#include <optional>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/curve_point.h"

namespace musclesim {

// The largest curvature n accepted: the power 1/n is then 0.001, the curve a step.
inline constexpr int kMaxVelocityExponent = 1000;

// The largest eccentric limit L accepted [-]. Muscle's eccentric tension levels off at 1.5 to
// 1.8 times the isometric one; a bound a million times higher bounds nothing a run reaches
// (for no bound, leave `limit` out).
inline constexpr double kMaxEccentricLimit = 1e6;

// The lengthening (eccentric, v < 0) branch's own parameters. Each one left out takes the
// default beside it; all left out is the paper's symmetric curve.
struct EccentricParams {
  std::optional<double> v_max = std::nullopt;  // [m/s], > 0; default: the concentric v_max
  std::optional<int> n = std::nullopt;         // [-], an integer 1..1000; default: concentric n
  std::optional<double> limit = std::nullopt;  // L [-], the bound of g as v -> -inf, in
                                               // (1, kMaxEccentricLimit]; default: none
};

struct VelocityParams {
  double v_max = 1.0;              // maximum shortening velocity [m/s], > 0
  int n = 1;                       // curvature [-]: the power is 1/n, an integer >= 1
  double epsilon = 1e-3;           // regularisation width [m/s], > 0
  EccentricParams eccentric = {};  // the lengthening branch; empty: symmetric (eq. 12)
};

// The curve's keys (core/part_fields.h): v_max, n, epsilon and the optional eccentric.v_max,
// eccentric.n, eccentric.limit, with their ranges; the model block's `velocity:` map
// (model/family_fields.h).
const PartVariant<VelocityParams>& VelocityBlock();

// Throws ParameterError ("v_max", "n", "epsilon", "eccentric.v_max", "eccentric.n",
// "eccentric.limit"): each field's range (VelocityBlock), then the rules between them.
// epsilon's rule (between 1e-12 v_max and v_max) holds for the eccentric
// v_max too; breaking it there is reported at "eccentric.v_max".
void Validate(const VelocityParams& params);

// g_eps(v) and its slope. Immutable after construction; evaluation allocates nothing and
// costs one pow (none for n = 1), plus one tanh on the lengthening side with a limit. Without
// eccentric parameters that differ from the concentric ones, g is eq. 12 bit for bit, at the
// cost of one well-predicted test.
class VelocityCurve {
 public:
  // Validates `params` (ParameterError).
  explicit VelocityCurve(const VelocityParams& params);

  // phi_eps and dphi_eps/dv, the regularised sgn(v)|v|^alpha of the concentric power.
  CurvePoint Phi(double v) const {
    const double w = v * v + epsilon_squared_;
    const double p = linear_ ? 1.0 : std::pow(w, half_exponent_);
    return {v * p, p * (alpha_ * v * v + epsilon_squared_) / w};
  }

  // g(v) and dg/dv, v the shortening velocity [m/s]: g_eps(v) = 1 - phi_eps(v) / v_max^alpha
  // for v >= 0, and for v < 0 too unless the curve is asymmetric (docs/model.md section 9).
  CurvePoint Evaluate(double v) const {
    if (asymmetric_ && v < 0.0) return Lengthening(v);
    const CurvePoint phi = Phi(v);
    return {1.0 - phi.value * inverse_scale_, -phi.slope * inverse_scale_};
  }

  // Whether the slopes of g on the two sides of v = 0 differ: -eps^(alpha-1) / v_max^alpha
  // against -eps^(alpha_e-1) / v_max_e^alpha_e, compared to 1e-13 relative (two pow
  // evaluations of equal slopes differ by a few ulps; a jump that small is no kink). The
  // simulator restarts its integrator where an actuator's v crosses 0 when this is true.
  bool has_kink() const { return has_kink_; }

  const VelocityParams& params() const { return params_; }
  double alpha() const { return alpha_; }

 private:
  // g on the lengthening side of an asymmetric curve: 1 + psi, or 1 + (L - 1) tanh(psi /
  // (L - 1)) with a limit, psi = -phi_eps,alpha_e(v) / v_max_e^alpha_e >= 0 (section 9).
  CurvePoint Lengthening(double v) const {
    const double w = v * v + epsilon_squared_;
    const double p = eccentric_.linear ? 1.0 : std::pow(w, eccentric_.half_exponent);
    const double psi = -v * p * eccentric_.inverse_scale;
    const double psi_slope =
        -p * (eccentric_.alpha * v * v + epsilon_squared_) / w * eccentric_.inverse_scale;
    if (!eccentric_.bounded) return {1.0 + psi, psi_slope};
    const double t = std::tanh(psi * eccentric_.inverse_headroom);
    return {1.0 + eccentric_.headroom * t, (1.0 - t * t) * psi_slope};
  }

  // The lengthening branch's constants, as the concentric ones below.
  struct Branch {
    double alpha = 1.0;             // 1 / n_e [-]
    double half_exponent = 0.0;     // (alpha_e - 1) / 2 [-]
    double inverse_scale = 1.0;     // v_max_e^-alpha_e [(s/m)^alpha_e]
    bool linear = true;             // n_e == 1
    bool bounded = false;           // a limit L is given
    double headroom = 0.0;          // L - 1 [-]
    double inverse_headroom = 0.0;  // 1 / (L - 1) [-]
  };

  VelocityParams params_;
  double alpha_;            // 1 / n [-]
  double half_exponent_;    // (alpha - 1) / 2 [-]
  double epsilon_squared_;  // eps^2 [m^2/s^2]
  double inverse_scale_;    // v_max^-alpha [(s/m)^alpha]
  bool linear_;             // n == 1: phi_eps(v) = v exactly
  bool asymmetric_;         // v < 0 takes Lengthening: eccentric n, v_max or a limit differ
  bool has_kink_;           // see has_kink()
  Branch eccentric_;        // used only when asymmetric_
};

}  // namespace musclesim
