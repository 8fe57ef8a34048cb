#include "musclesim/model/tension.h"

#include <cmath>
#include <numbers>

#include "musclesim/core/errors.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {

namespace {

// Re-throws a nested block's ParameterError with the block's name in front of its path.
template <typename Check>
void WithPrefix(const char* block, Check check) {
  try {
    check();
  } catch (const ParameterError& e) {
    throw ParameterError(std::string(block) + "." + e.path(), e.value(), e.rule());
  }
}

}  // namespace

void Validate(const ModelParams& params) {
  // each field's range (model/family_fields.h), then the rules between fields
  ValidateFields(*VariantOf(ModelFamilies(), params), params);
  Require(std::isfinite(params.pennation_angle) && params.pennation_angle >= 0.0 &&
              params.pennation_angle < 0.5 * std::numbers::pi,
          "pennation_angle", params.pennation_angle,
          "must be >= 0 and below pi/2 [rad] (the angle at the optimal fiber length)");
  switch (params.family) {
    case CurveFamily::kDeGroote2016: return;
    case CurveFamily::kMujoco: return Validate(params.mujoco);  // its lists and their rules
    case CurveFamily::kPaper: break;
  }
  WithPrefix("active_length", [&] { Validate(params.active_length); });
  WithPrefix("velocity", [&] { Validate(params.velocity); });
}

namespace {

// The paper's curves, which another family's model keeps unused: one Gaussian at 1 m.
ActiveLengthParams StandInActiveLength() {
  ActiveLengthParams p;
  p.optimal_min = 0.5;
  p.optimal_max = 1.5;
  p.gaussians = {Gaussian{1.0, 1.0, 1.0}};
  return p;
}

}  // namespace

TensionModel::TensionModel(const ModelParams& params)
    : params_((Validate(params), params)),
      active_length_([&] {
        if (params.family != CurveFamily::kPaper) return ActiveLengthCurve(StandInActiveLength());
        try {
          return ActiveLengthCurve(params.active_length);
        } catch (const ParameterError& e) {
          throw ParameterError("active_length." + e.path(), e.value(), e.rule());
        }
      }()),
      velocity_(params.family == CurveFamily::kPaper ? params.velocity : VelocityParams{}),
      pennation_width_(OptimalFiberLength() * std::sin(params.pennation_angle)) {}

double TensionModel::OptimalFiberLength() const {
  switch (params_.family) {
    case CurveFamily::kDeGroote2016: return params_.degroote2016.optimal_fiber_length;
    case CurveFamily::kMujoco: {
      const MujocoMuscleParams& m = params_.mujoco;
      return m.lengthrange[0] + (1.0 - m.range[0]) * mujoco_muscle::LengthScale(m);
    }
    case CurveFamily::kPaper: break;
  }
  return active_length_.optimal_length();
}

std::optional<double> TensionModel::LengthKink() const {
  if (params_.family != CurveFamily::kPaper || params_.passive.k_p == 0.0) return std::nullopt;
  // along the line of action with pennation: x^2 + w^2 = slack^2
  const double slack = params_.passive.slack_length;
  if (pennation_width_ == 0.0) return slack;
  if (slack <= pennation_width_) return std::nullopt;
  return std::sqrt(slack * slack - pennation_width_ * pennation_width_);
}

// T is affine in u: the active part's derivatives are those at u = 1 less those at u = 0.
CurvePoint TensionModel::ActiveLengthFactor(double x) const {
  const bool paper = params_.family == CurveFamily::kPaper && pennation_width_ == 0.0;
  if (paper) return active_length_.Evaluate(x);
  const TensionSample full = Evaluate(x, 0.0, 1.0), passive = Evaluate(x, 0.0, 0.0);
  return {full.d_activation / params_.f_iso, (full.d_length - passive.d_length) / params_.f_iso};
}

CurvePoint TensionModel::VelocityFactor(double v) const {
  const bool paper = params_.family == CurveFamily::kPaper && pennation_width_ == 0.0;
  if (paper) return velocity_.Evaluate(v);
  // at the optimal fiber length, along the line
  const double l_opt = OptimalFiberLength();
  const double x = std::sqrt(l_opt * l_opt - pennation_width_ * pennation_width_);
  const double isometric = Evaluate(x, 0.0, 1.0).d_activation;
  const TensionSample full = Evaluate(x, v, 1.0), passive = Evaluate(x, v, 0.0);
  return {full.d_activation / isometric, (full.d_velocity - passive.d_velocity) / isometric};
}

bool TensionModel::PassiveDependsOnRate() const {
  return params_.family == CurveFamily::kDeGroote2016 && params_.degroote2016.fiber_damping > 0.0;
}

bool TensionModel::HasVelocityKink() const {
  return params_.family == CurveFamily::kPaper && velocity_.has_kink();
}

TensionSample TensionModel::Pennate(double x, double v, double u) const {
  const double w = pennation_width_;
  const double fiber = std::hypot(x, w);
  const double cosine = x / fiber;
  const double cosine_slope = w * w / (fiber * fiber * fiber);  // d cos(alpha) / dx
  // the fiber shortens at cos(alpha) times the line's rate
  const TensionSample f = Fiber(fiber, cosine * v, u);
  TensionSample out;
  out.passive = f.passive * cosine;
  out.active = f.active * cosine;
  out.total = f.total * cosine;
  out.d_length =
      (f.d_length * cosine + f.d_velocity * v * cosine_slope) * cosine + f.total * cosine_slope;
  out.d_velocity = f.d_velocity * cosine * cosine;
  out.d_activation = f.d_activation * cosine;
  return out;
}

}  // namespace musclesim
