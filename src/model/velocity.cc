#include "musclesim/model/velocity.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/model/tension_parameter.h"

namespace musclesim {

namespace {

// (alpha - 1) / 2, the power of v^2 + eps^2 in phi_eps (docs/model.md section 4).
double HalfExponent(double alpha) { return 0.5 * (alpha - 1.0); }

}  // namespace

namespace {

using Field = NumberField<VelocityParams>;

// v_max's range, the concentric and the eccentric one's.
constexpr InputRange kMaxVelocityRange{
    0.0, 1e12, "m/s",
    "a v_max far above every speed of the run makes g flat (a tension independent of the "
    "velocity), and epsilon's bounds, 1e-12 v_max to v_max, stay in range",
    true};
constexpr InputRange kExponentRange{1.0, kMaxVelocityExponent, "-",
                                    "the power 1/n; at 1000 it is 0.001, the curve a step"};

Field Exponent(const char* key, std::function<double(const VelocityParams&)> get,
               std::function<void(VelocityParams&, double)> set, const char* doc) {
  Field field{key, kExponentRange, std::nullopt, doc, std::move(get), std::move(set)};
  field.integer = true;
  return field;
}

std::vector<Field> VelocityFields() {
  using Kind = TensionParameterKind;
  Field epsilon = MemberField("epsilon", &VelocityParams::epsilon, InputRange{0.0, 0.0, "m/s", ""},
                              std::nullopt,
                              "the regularisation width: from 1e-12 v_max (below, too stiff to "
                              "integrate) to v_max (above, it replaces the power law)",
                              static_cast<int>(Kind::kEpsilon));
  epsilon.values = FieldValues::kFinite;
  Field eccentric_v_max{
      "eccentric.v_max",
      kMaxVelocityRange,
      std::nullopt,
      "the lengthening branch's v_max (absent: v_max); epsilon's rule holds for it too",
      [](const VelocityParams& v) { return v.eccentric.v_max.value_or(v.v_max); },
      [](VelocityParams& v, double x) { v.eccentric.v_max = x; },
      static_cast<int>(Kind::kEccentricMaxVelocity)};
  eccentric_v_max.given = [](const VelocityParams& v) { return v.eccentric.v_max.has_value(); };
  Field eccentric_n = Exponent(
      "eccentric.n", [](const VelocityParams& v) { return double(v.eccentric.n.value_or(v.n)); },
      [](VelocityParams& v, double x) { v.eccentric.n = static_cast<int>(x); },
      "the lengthening branch's n (absent: n)");
  eccentric_n.given = [](const VelocityParams& v) { return v.eccentric.n.has_value(); };
  Field limit{"eccentric.limit",
              InputRange{1.0, kMaxEccentricLimit, "-",
                         "the bound of g as the lengthening velocity grows lies above g(0) = 1, "
                         "and a bound beyond 1e6 bounds nothing (leave it out for none)",
                         true},
              std::nullopt,
              "L, the bound of g as the lengthening velocity grows (absent: none)",
              [](const VelocityParams& v) {
                return v.eccentric.limit.value_or(std::numeric_limits<double>::infinity());
              },
              [](VelocityParams& v, double x) { v.eccentric.limit = x; },
              static_cast<int>(Kind::kEccentricLimit)};
  limit.given = [](const VelocityParams& v) { return v.eccentric.limit.has_value(); };
  return {MemberField("v_max", &VelocityParams::v_max, kMaxVelocityRange, std::nullopt,
                      "the shortening velocity of zero active tension",
                      static_cast<int>(Kind::kMaxVelocity)),
          Exponent(
              "n", [](const VelocityParams& v) { return double(v.n); },
              [](VelocityParams& v, double x) { v.n = static_cast<int>(x); },
              "the curvature: g follows the power 1/n of the velocity"),
          std::move(epsilon),
          std::move(eccentric_v_max),
          std::move(eccentric_n),
          std::move(limit)};
}

}  // namespace

const PartVariant<VelocityParams>& VelocityBlock() {
  static const PartVariant<VelocityParams> block = OnlyVariant<VelocityParams>(
      "velocity", "g_eps(v) = 1 - phi_eps(v) / v_max^(1/n) (docs/model.md 4, 9)", VelocityFields());
  return block;
}

void Validate(const VelocityParams& params) {
  ValidateFields(VelocityBlock(), params);
  // Below 1e-12 v_max the slope at v = 0, (eps / v_max)^(1/n - 1) / v_max, reaches 1e12 / v_max:
  // the actuator's time constant falls below what double-precision time can resolve (and
  // eps^2 underflows further down). Above v_max the regularisation swamps the curve.
  Require(std::isfinite(params.epsilon) && params.epsilon >= 1e-12 * params.v_max &&
              params.epsilon <= params.v_max,
          "epsilon", params.epsilon,
          "must be between 1e-12 v_max and v_max = " + FormatNumber(params.v_max) +
              " [m/s] (smaller: too stiff to integrate in double precision; larger: the "
              "regularisation replaces the power law)");
  // the lengthening branch is regularised with the same eps: the same rule, read for v_max_e
  if (const std::optional<double> v_max = params.eccentric.v_max) {
    Require(params.epsilon >= 1e-12 * *v_max && params.epsilon <= *v_max, "eccentric.v_max", *v_max,
            "must be between epsilon = " + FormatNumber(params.epsilon) +
                " and 1e12 epsilon "
                "[m/s] (epsilon's rule, between 1e-12 v_max and v_max, holds for the eccentric "
                "v_max too)");
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
