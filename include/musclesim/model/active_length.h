// Active tension-length factor: a sum of Gaussians (paper eqs. 3-4) normalised by its
// maximum over the optimal length range (eq. 13, docs/model.md section 3).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "musclesim/model/curve_point.h"

namespace musclesim {

// One component psi_k(x) = a / sqrt(2 pi sigma) * exp(-b (x - d)^2 / (2 sigma)).
struct Gaussian {
  double amplitude = 0.0;  // a_k [-], finite (may be negative)
  double precision = 1.0;  // b_k, inverse-variance factor [1/m^2 when sigma = 1], > 0;
                           // the YAML key is `width`
  double center = 0.0;     // d_k [m], finite
};

// The finest grid the search for max f over L_opt uses: a component must be at least four
// cells wide (a spread sqrt(sigma / b_k) of 4e-6 of the optimal range) to be resolved.
inline constexpr long kMaxPeakSearchCells = 1000000;

struct ActiveLengthParams {
  double optimal_min = 0.0;         // l1, start of L_opt [m]
  double optimal_max = 1.0;         // l2, end of L_opt [m], > l1
  double sigma = 1.0;               // common scale of the b_k [-], > 0; only
                                    // b_k / sigma [1/m^2] shapes the curve
  std::vector<Gaussian> gaussians;  // the components psi_k, at least one
};

// One component in the form it is evaluated in, psi(x) = scale * exp(-rate (x - center)^2):
// the single implementation of eq. 3's Gaussian, shared by the curve, the fit's basis, the
// identification's Jacobian and the plotted components.
struct GaussianTerm {
  double scale = 0.0;   // a_k / sqrt(2 pi sigma), the peak value [-]
  double rate = 0.0;    // b_k / (2 sigma) [1/m^2]
  double center = 0.0;  // d_k [m]

  // psi_k of `g` under the common scale `sigma`.
  static GaussianTerm Of(const Gaussian& g, double sigma) {
    const double norm = 1.0 / std::sqrt(2.0 * std::numbers::pi * sigma);
    return {g.amplitude * norm, g.precision / (2.0 * sigma), g.center};
  }
  // phi_k = psi_k / a_k, the unit-amplitude basis function: amplitudes enter the cost
  // linearly, so the fit and the standard errors work with these.
  static GaussianTerm Unit(double precision, double center, double sigma) {
    return Of({1.0, precision, center}, sigma);
  }

  double operator()(double x) const {
    const double dx = x - center;
    return scale * std::exp(-rate * dx * dx);
  }
};

// Throws ParameterError ("optimal_range", "sigma", "gaussians", "gaussians[k].width", ...),
// naming each field by its YAML key.
void Validate(const ActiveLengthParams& params);

// The unnormalised sum f(x) with its first two derivatives. Immutable; evaluation
// allocates nothing.
class GaussianSum {
 public:
  // The empty sum, zero everywhere: a placeholder to assign a built sum to.
  GaussianSum() = default;
  // `gaussians` and `sigma` must already be valid; they are copied.
  GaussianSum(const std::vector<Gaussian>& gaussians, double sigma);

  double Value(double x) const;
  CurvePoint ValueAndSlope(double x) const;
  double Curvature(double x) const;  // f''(x)

  // Smallest standard deviation sqrt(sigma / b_k) among the components [m].
  double NarrowestSpread() const;

  // The components psi_k, in the order they were given.
  const std::vector<GaussianTerm>& terms() const { return terms_; }

 private:
  std::vector<GaussianTerm> terms_;
};

// f_L(x) = f(x) / max over L_opt of f. Construction finds that maximum exactly: the
// larger of the end values and of f at every interior root of f' (bracketed on a grid
// finer than the narrowest component, then bisected to the last bit).
class ActiveLengthCurve {
 public:
  // Validates `params` (ParameterError) and throws ParameterError("gaussians") when f is
  // not positive anywhere on L_opt, since it then cannot be normalised.
  explicit ActiveLengthCurve(ActiveLengthParams params);

  // f_L(x) and df_L/dx.
  CurvePoint Evaluate(double x) const {
    const CurvePoint raw = sum_.ValueAndSlope(x);
    return {raw.value * inverse_peak_, raw.slope * inverse_peak_};
  }

  const ActiveLengthParams& params() const { return params_; }
  const GaussianSum& sum() const { return sum_; }
  double peak_value() const { return peak_value_; }       // max of f over L_opt [-]
  double optimal_length() const { return peak_length_; }  // where it is reached [m]

 private:
  ActiveLengthParams params_;  // as validated
  GaussianSum sum_;            // f [-], built from params_
  double peak_value_ = 0.0;    // max of f over L_opt [-]
  double peak_length_ = 0.0;   // where it is reached [m]
  double inverse_peak_ = 0.0;  // 1 / peak_value_ [-]
};

// Location and value of max f on [lo, hi], found as described for ActiveLengthCurve.
struct Maximum {
  double x = 0.0;      // where the maximum is reached [m]
  double value = 0.0;  // f there [-]
};
Maximum MaximumOnInterval(const GaussianSum& sum, double lo, double hi);

}  // namespace musclesim
