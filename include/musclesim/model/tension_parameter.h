// Partial derivatives of the tension with respect to the tension model's continuous parameters
// at a fixed state (x, v, u): the dT/dp|_y that forward sensitivity analysis adds to J s_p
// (docs/model.md section 10). Each parameter is named by its YAML path inside the model block, as
// `--set` writes it after "model.", so that messages and options speak the file's language.
//
// Every derivative is a closed form of the curves of docs/model.md sections 2-5 and 9. The
// normalisation f_L = f / f_peak, f_peak = max over L_opt of f, is differentiated by the
// envelope theorem: d f_peak/dp = (df/dp)(x*) at the maximiser x*, interior or an end of L_opt;
// for an end of L_opt itself, d f_peak/dl = f'(l) when x* is that end and 0 otherwise. Where
// the maximum is reached at two places at once f_peak has no derivative; the one at the
// maximiser ActiveLengthCurve found is returned.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "musclesim/model/tension.h"

namespace musclesim {

// Which continuous parameter of ModelParams; the comment gives its path (the YAML key).
enum class TensionParameterKind {
  kIsometricTension,      // f_iso [N]
  kPassiveScale,          // passive.k_p [N]
  kPassiveRate,           // passive.alpha [1/m]
  kSlackLength,           // passive.slack_length [m]
  kOptimalMin,            // active_length.optimal_range[0], l1 [m]
  kOptimalMax,            // active_length.optimal_range[1], l2 [m]
  kSigma,                 // active_length.sigma [-]
  kAmplitude,             // active_length.gaussians[k].amplitude, a_k [-]
  kWidth,                 // active_length.gaussians[k].width, b_k (Gaussian::precision)
  kCenter,                // active_length.gaussians[k].center, d_k [m]
  kMaxVelocity,           // velocity.v_max [m/s]
  kEpsilon,               // velocity.epsilon [m/s]
  kEccentricMaxVelocity,  // velocity.eccentric.v_max [m/s]
  kEccentricLimit,        // velocity.eccentric.limit, L [-]
};

// One continuous parameter of ModelParams. The integers (velocity.n, velocity.eccentric.n)
// are not parameters in this sense: nothing is differentiable in them.
struct TensionParameter {
  TensionParameterKind kind = TensionParameterKind::kIsometricTension;
  std::size_t gaussian = 0;  // k, the component, for kAmplitude, kWidth, kCenter; else 0

  friend bool operator==(const TensionParameter&, const TensionParameter&) = default;
};

// The parameter at `path`, relative to the model block ("f_iso", "passive.k_p",
// "active_length.optimal_range[1]", "active_length.gaussians[1].width", "velocity.epsilon",
// "velocity.eccentric.limit", ...). Paths are split as `--set` splits them: a dot on either
// side of an index is optional and one trailing dot is ignored. Returns nullopt for a path
// that names no continuous parameter: an unknown key, a block, an integer (velocity.n), an
// index of optimal_range other than 0 or 1, a malformed index. Whether a Gaussian index or an
// eccentric parameter exists depends on the model: ParameterValue and
// TensionParameterDerivative check that.
std::optional<TensionParameter> ParseTensionParameter(std::string_view path);

// The path ParseTensionParameter reads back, in its canonical form
// ("active_length.gaussians[1].width"), for messages.
std::string ToString(const TensionParameter& parameter);

// The parameter's value in `params`, in its unit above. Throws ParameterError, its path
// ToString(parameter) and its value "~", when `params` lacks the parameter: a Gaussian index
// past the last component, or velocity.eccentric.v_max or velocity.eccentric.limit not given
// (an eccentric v_max left out is the concentric one, whose derivative then covers both
// branches; a limit left out is no bound at all).
double ParameterValue(const ModelParams& params, const TensionParameter& parameter);

// dT/dp at fixed (x, v, u), split as TensionSample is [N per unit of p].
struct TensionPartials {
  double passive = 0.0;  // dT_p/dp
  double active = 0.0;   // dT_a/dp
  double total = 0.0;    // dT/dp = dT_p/dp + dT_a/dp
};

// The derivative of one model's tension in one parameter, prepared once: d f_peak/dp is
// found at construction, so each evaluation costs about one TensionModel::Evaluate and
// allocates nothing. Keeps a pointer to `model`, which must outlive it; copyable, immutable,
// shareable between threads.
class TensionParameterDerivative {
 public:
  // Throws ParameterError, as ParameterValue, when the model lacks `parameter`.
  TensionParameterDerivative(const TensionModel& model, TensionParameter parameter);

  // x the length [m], v the shortening velocity [m/s], u the activation [-]. The passive
  // tension's derivatives are 0 for x <= slack_length (at x == slack_length exactly the
  // left branch, as PassiveTension); g's are taken on the branch Evaluate takes (v < 0 the
  // lengthening one), and are 0 at v = 0, where phi_eps = 0 on both sides.
  TensionPartials operator()(double x, double v, double u) const;

  const TensionParameter& parameter() const { return parameter_; }

 private:
  // df/dp at x, f the unnormalised sum of Gaussians; 0 for the ends of L_opt.
  double SumDerivative(double x) const;
  // dg/dp at v for the velocity parameters.
  double VelocityDerivative(double v) const;

  const TensionModel* model_;
  TensionParameter parameter_;
  double peak_derivative_ = 0.0;  // d f_peak/dp [1/unit of p], active-length parameters
  // velocity constants (docs/model.md sections 4 and 9), each branch as VelocityCurve has it
  double epsilon_ = 0.0;                  // eps [m/s]
  double epsilon_squared_ = 0.0;          // eps^2 [m^2/s^2]
  double alpha_ = 1.0;                    // 1 / n [-]
  double v_max_ = 1.0;                    // [m/s]
  double inverse_scale_ = 1.0;            // v_max^-alpha
  double eccentric_alpha_ = 1.0;          // 1 / n_e [-]
  double eccentric_v_max_ = 1.0;          // v_max_e, given or the concentric v_max [m/s]
  double eccentric_inverse_scale_ = 1.0;  // v_max_e^-alpha_e
  bool eccentric_v_max_given_ = false;    // velocity.eccentric.v_max is its own parameter
  double headroom_ = 0.0;                 // L - 1 [-], 0 without a limit
};

// One evaluation without preparing: TensionParameterDerivative(model, parameter)(x, v, u).
// Allocates nothing (except in the ParameterError it throws as the constructor does), but
// recomputes d f_peak/dp and the velocity constants at each call: a loop should build the
// TensionParameterDerivative once.
TensionPartials TensionPartialsAt(const TensionModel& model, const TensionParameter& parameter,
                                  double x, double v, double u);

}  // namespace musclesim
