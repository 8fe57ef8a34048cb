#include "musclesim/model/tension_parameter.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {

namespace {

using Kind = TensionParameterKind;

// One step of a key path: a map key, or a sequence index when `key` is empty.
struct PathStep {
  std::string_view key;
  std::size_t index = 0;
};

// "a.b[2].c" split into {a}, {b}, {[2]}, {c} by the rules of `--set` (io/key_path.h, which
// this layer cannot include): a dot on either side of an index optional, one trailing dot
// ignored; nullopt for an empty key, an empty or non-decimal index, an unclosed "[".
std::optional<std::vector<PathStep>> SplitPath(std::string_view path) {
  std::vector<PathStep> steps;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '[') {
      const std::size_t close = path.find(']', pos);
      if (close == std::string_view::npos || close == pos + 1) return std::nullopt;
      const std::string_view digits = path.substr(pos + 1, close - pos - 1);
      if (digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
      std::size_t index = 0;
      const auto [end, error] =
          std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (error != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
      steps.push_back({{}, index});
      pos = close + 1;
      if (pos < path.size() && path[pos] == '.') ++pos;
    } else {
      const std::size_t end = path.find_first_of(".[", pos);
      const std::string_view key = path.substr(pos, end - pos);
      if (key.empty()) return std::nullopt;
      steps.push_back({key, 0});
      // a dot separates keys; a "[" starts the next step itself
      pos = end == std::string_view::npos ? path.size() : (path[end] == '.' ? end + 1 : end);
    }
  }
  return steps;
}

// The paper's block (model/family_fields.h): its fields with a closed-form derivative carry
// their kind as their tag.
const ModelFamily& Paper() { return *VariantOf(ModelFamilies(), ModelParams{}); }

// The described field whose tag is `kind`; null for a kind of a list's items (a Gaussian's).
const NumberField<ModelParams>* FieldOf(Kind kind) {
  for (const NumberField<ModelParams>& field : Paper().fields) {
    if (field.partial == static_cast<int>(kind)) return &field;
  }
  return nullptr;
}

// The field of item k of a list of the paper's block whose tag is `kind`, with its key path
// ("active_length.gaussians[1].width"); none for a kind of no list.
std::optional<std::pair<std::string, NumberField<ModelParams>>> ItemFieldOf(Kind kind,
                                                                            std::size_t k) {
  for (const ListField<ModelParams>& list : Paper().lists) {
    for (NumberField<ModelParams>& field : list.item_fields(k)) {
      if (field.partial != static_cast<int>(kind)) continue;
      return std::pair{list.key + "[" + std::to_string(k) + "]." + field.key, std::move(field)};
    }
  }
  return std::nullopt;
}

std::optional<TensionParameter> Match(const std::vector<PathStep>& s) {
  std::string key;  // "velocity.eccentric.v_max", "active_length.gaussians[1].width"
  for (const PathStep& step : s) {
    if (step.key.empty()) {
      key.append("[").append(std::to_string(step.index)).append("]");
    } else {
      key.append(key.empty() ? "" : ".").append(step.key);
    }
  }
  int partial = -1;
  std::size_t gaussian = 0;
  if (const std::optional<ListItemKey<ModelParams>> item = FindListItem(Paper(), key)) {
    if (!item->index) return std::nullopt;
    for (const NumberField<ModelParams>& field : item->list->item_fields(*item->index)) {
      if (field.key == item->leaf) partial = field.partial;
    }
    gaussian = *item->index;
  } else if (const NumberField<ModelParams>* field = FindField(Paper(), key)) {
    partial = field->partial;
  }
  if (partial < 0) return std::nullopt;
  return TensionParameter{static_cast<Kind>(partial), gaussian};
}

// Throws ParameterError when `params` lacks `p` (see ParameterValue).
void RequirePresent(const ModelParams& params, const TensionParameter& p) {
  const std::size_t count = params.active_length.gaussians.size();
  switch (p.kind) {
    case Kind::kAmplitude:
    case Kind::kWidth:
    case Kind::kCenter:
      if (p.gaussian >= count) {
        throw ParameterError(ToString(p), "~",
                             "no such component: the model has " + std::to_string(count) +
                                 " Gaussian(s), gaussians[0] to gaussians[" +
                                 std::to_string(count - 1) + "]");
      }
      return;
    case Kind::kEccentricMaxVelocity:
      if (!params.velocity.eccentric.v_max) {
        throw ParameterError(ToString(p), "~",
                             "not given in this model: the lengthening branch takes "
                             "velocity.v_max, whose derivative covers both branches (give "
                             "eccentric.v_max to vary the lengthening branch on its own)");
      }
      return;
    case Kind::kEccentricLimit:
      if (!params.velocity.eccentric.limit) {
        throw ParameterError(ToString(p), "~",
                             "not given in this model: the lengthening branch is unbounded, "
                             "and a limit is a parameter only where one is given");
      }
      return;
    default: return;
  }
}

// d/dH of H tanh(psi / H) at z = psi / H: tanh z - z sech^2 z, which cancels to 2 z^3 / 3 for
// small z. Written there as (sinh 2z - 2z) / (2 cosh^2 z) with sinh y - y summed as its
// series (ten terms reach y^21 / 21!, below an ulp of y^3 / 6 for |y| <= 1).
double HeadroomDerivative(double z) {
  if (std::abs(z) >= 0.5) {
    const double sech = 1.0 / std::cosh(z);
    return std::tanh(z) - z * sech * sech;
  }
  const double y = 2.0 * z;
  double term = y * y * y / 6.0;
  double sinh_minus_y = term;
  for (int k = 2; k <= 10; ++k) {
    term *= y * y / ((2.0 * k) * (2.0 * k + 1.0));
    sinh_minus_y += term;
  }
  const double cosh = std::cosh(z);
  return sinh_minus_y / (2.0 * cosh * cosh);
}

// w^((alpha - 1) / 2), the power in phi_eps (docs/model.md section 4); exactly 1 for n = 1.
double PhiPower(double w, double alpha) {
  return alpha == 1.0 ? 1.0 : std::pow(w, 0.5 * (alpha - 1.0));
}

}  // namespace

std::optional<TensionParameter> ParseTensionParameter(std::string_view path) {
  const std::optional<std::vector<PathStep>> steps = SplitPath(path);
  if (!steps) return std::nullopt;
  return Match(*steps);
}

std::string ToString(const TensionParameter& parameter) {
  if (const auto item = ItemFieldOf(parameter.kind, parameter.gaussian)) return item->first;
  return FieldOf(parameter.kind)->key;
}

double ParameterValue(const ModelParams& params, const TensionParameter& parameter) {
  RequirePresent(params, parameter);
  if (const auto item = ItemFieldOf(parameter.kind, parameter.gaussian)) {
    return item->second.get(params);
  }
  return FieldOf(parameter.kind)->get(params);
}

TensionParameterDerivative::TensionParameterDerivative(const TensionModel& model,
                                                       TensionParameter parameter)
    : model_(&model), parameter_(parameter) {
  RequirePresent(model.params(), parameter);

  // the velocity curve's constants, both branches as VelocityCurve builds them
  const VelocityParams& velocity = model.params().velocity;
  epsilon_ = velocity.epsilon;
  epsilon_squared_ = velocity.epsilon * velocity.epsilon;
  alpha_ = 1.0 / velocity.n;
  v_max_ = velocity.v_max;
  inverse_scale_ = std::pow(v_max_, -alpha_);
  eccentric_alpha_ = 1.0 / velocity.eccentric.n.value_or(velocity.n);
  eccentric_v_max_given_ = velocity.eccentric.v_max.has_value();
  eccentric_v_max_ = velocity.eccentric.v_max.value_or(velocity.v_max);
  eccentric_inverse_scale_ = std::pow(eccentric_v_max_, -eccentric_alpha_);
  headroom_ = velocity.eccentric.limit ? *velocity.eccentric.limit - 1.0 : 0.0;

  // d f_peak/dp by the envelope theorem: at an interior maximum f' = 0, so only f's own
  // dependence on p counts; at an end of L_opt the maximiser stays at that end, unless p is
  // that end, which then carries the maximum along at the rate f'(end)
  const ActiveLengthCurve& length = model.active_length();
  const double peak_x = length.optimal_length();
  const ActiveLengthParams& active = length.params();
  switch (parameter.kind) {
    case Kind::kOptimalMin:
      peak_derivative_ =
          peak_x == active.optimal_min ? length.sum().ValueAndSlope(peak_x).slope : 0.0;
      break;
    case Kind::kOptimalMax:
      peak_derivative_ =
          peak_x == active.optimal_max ? length.sum().ValueAndSlope(peak_x).slope : 0.0;
      break;
    default: peak_derivative_ = SumDerivative(peak_x); break;
  }
}

double TensionParameterDerivative::SumDerivative(double x) const {
  const std::vector<GaussianTerm>& terms = model_->active_length().sum().terms();
  const double sigma = model_->params().active_length.sigma;
  const std::size_t k = parameter_.gaussian;
  // psi = a / sqrt(2 pi sigma) exp(-rate (x - d)^2), rate = b / (2 sigma) (eq. 3)
  switch (parameter_.kind) {
    case Kind::kAmplitude: {
      const double dx = x - terms[k].center;
      return std::exp(-terms[k].rate * dx * dx) / std::sqrt(2.0 * std::numbers::pi * sigma);
    }
    case Kind::kWidth: {
      const double dx = x - terms[k].center;
      return -terms[k](x) * dx * dx / (2.0 * sigma);
    }
    case Kind::kCenter: return terms[k](x) * 2.0 * terms[k].rate * (x - terms[k].center);
    case Kind::kSigma: {
      // sigma scales every component by sigma^-1/2 and its rate by 1 / sigma
      double sum = 0.0;
      for (const GaussianTerm& t : terms) {
        const double dx = x - t.center;
        sum += t(x) * (t.rate * dx * dx - 0.5);
      }
      return sum / sigma;
    }
    default: return 0.0;
  }
}

double TensionParameterDerivative::VelocityDerivative(double v) const {
  const double w = v * v + epsilon_squared_;
  if (!(v < 0.0)) {
    // g = 1 - phi / v_max^alpha, phi = v w^((alpha - 1) / 2), w = v^2 + eps^2 (section 4)
    const double phi = v * PhiPower(w, alpha_);
    switch (parameter_.kind) {
      case Kind::kMaxVelocity: return alpha_ * phi * inverse_scale_ / v_max_;
      case Kind::kEpsilon: return -(alpha_ - 1.0) * epsilon_ * phi * inverse_scale_ / w;
      default: return 0.0;
    }
  }
  // lengthening: g = 1 + psi or 1 + H tanh(psi / H), psi = -phi_e / v_max_e^alpha_e (section
  // 9); a symmetric curve is this with the concentric constants, so one form serves both
  const double psi = -v * PhiPower(w, eccentric_alpha_) * eccentric_inverse_scale_;
  double by_psi = 1.0;  // dg/dpsi
  if (headroom_ > 0.0) {
    const double z = psi / headroom_;
    if (parameter_.kind == Kind::kEccentricLimit) return HeadroomDerivative(z);
    const double sech = 1.0 / std::cosh(z);
    by_psi = sech * sech;
  }
  const double by_eccentric_v_max = -eccentric_alpha_ * psi / eccentric_v_max_;  // dpsi/dv_max_e
  switch (parameter_.kind) {
    case Kind::kMaxVelocity: return eccentric_v_max_given_ ? 0.0 : by_psi * by_eccentric_v_max;
    case Kind::kEccentricMaxVelocity: return by_psi * by_eccentric_v_max;
    case Kind::kEpsilon: return by_psi * (eccentric_alpha_ - 1.0) * epsilon_ * psi / w;
    default: return 0.0;
  }
}

TensionPartials TensionParameterDerivative::operator()(double x, double v, double u) const {
  const ModelParams& params = model_->params();
  const ActiveLengthCurve& length = model_->active_length();
  TensionPartials out;
  switch (parameter_.kind) {
    case Kind::kIsometricTension:
      out.active = u * length.Evaluate(x).value * model_->velocity().Evaluate(v).value;
      break;
    case Kind::kPassiveScale:
    case Kind::kPassiveRate:
    case Kind::kSlackLength: {
      // T_p = k_p (exp(alpha (x - x0)) - 1) above the slack length, 0 up to it (eq. 1)
      const PassiveParams& passive = params.passive;
      if (!(x > passive.slack_length)) break;
      const double stretch = x - passive.slack_length;
      const double growth = std::exp(passive.alpha * stretch);
      if (parameter_.kind == Kind::kPassiveScale) {
        out.passive = std::expm1(passive.alpha * stretch);
      } else if (parameter_.kind == Kind::kPassiveRate) {
        out.passive = passive.k_p * stretch * growth;
      } else {
        out.passive = -passive.k_p * passive.alpha * growth;
      }
      break;
    }
    case Kind::kOptimalMin:
    case Kind::kOptimalMax:
    case Kind::kSigma:
    case Kind::kAmplitude:
    case Kind::kWidth:
    case Kind::kCenter: {
      // f_L = f / f_peak: df_L/dp = (df/dp - f_L d f_peak/dp) / f_peak
      const double f_length = length.Evaluate(x).value;
      const double by_p = (SumDerivative(x) - f_length * peak_derivative_) / length.peak_value();
      out.active = u * params.f_iso * by_p * model_->velocity().Evaluate(v).value;
      break;
    }
    case Kind::kMaxVelocity:
    case Kind::kEpsilon:
    case Kind::kEccentricMaxVelocity:
    case Kind::kEccentricLimit:
      out.active = u * params.f_iso * length.Evaluate(x).value * VelocityDerivative(v);
      break;
  }
  out.total = out.passive + out.active;
  return out;
}

TensionPartials TensionPartialsAt(const TensionModel& model, const TensionParameter& parameter,
                                  double x, double v, double u) {
  return TensionParameterDerivative(model, parameter)(x, v, u);
}

}  // namespace musclesim
