#include "musclesim/model/active_length.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "musclesim/core/errors.h"

namespace musclesim {

void Validate(const ActiveLengthParams& params) {
  Require(std::isfinite(params.optimal_min), "optimal_range[0]", params.optimal_min,
          "must be finite [m]");
  Require(std::isfinite(params.optimal_max) && params.optimal_max > params.optimal_min,
          "optimal_range[1]", params.optimal_max,
          "must be finite and greater than optimal_range[0] = " + FormatNumber(params.optimal_min));
  Require(std::isfinite(params.sigma) && params.sigma > 0.0, "sigma", params.sigma,
          "must be finite and > 0");
  if (params.gaussians.empty()) {
    throw ParameterError("gaussians", "[]", "needs at least one component");
  }
  for (std::size_t k = 0; k < params.gaussians.size(); ++k) {
    const Gaussian& g = params.gaussians[k];
    const std::string at = "gaussians[" + std::to_string(k) + "].";
    Require(std::isfinite(g.amplitude), at + "amplitude", g.amplitude, "must be finite");
    Require(std::isfinite(g.precision) && g.precision > 0.0, at + "width", g.precision,
            "must be finite and > 0");
    // the normalisation searches L_opt on a grid of at most kMaxPeakSearchCells cells, a
    // quarter spread each: a narrower component could hide a maximum between two cells
    const double spread = std::sqrt(params.sigma / g.precision);
    Require(spread >= (params.optimal_max - params.optimal_min) / kMaxPeakSearchCells * 4.0,
            at + "width", g.precision,
            "gives a spread sqrt(sigma / width) = " + FormatNumber(spread) +
                " m, below 4e-6 of the optimal range: too narrow to locate max f on it");
    Require(std::isfinite(g.center), at + "center", g.center, "must be finite [m]");
  }
}

GaussianSum::GaussianSum(const std::vector<Gaussian>& gaussians, double sigma) {
  terms_.reserve(gaussians.size());
  for (const Gaussian& g : gaussians) terms_.push_back(GaussianTerm::Of(g, sigma));
}

double GaussianSum::Value(double x) const {
  double f = 0.0;
  for (const GaussianTerm& t : terms_) f += t(x);
  return f;
}

CurvePoint GaussianSum::ValueAndSlope(double x) const {
  CurvePoint out;
  for (const GaussianTerm& t : terms_) {
    const double psi = t(x);
    out.value += psi;
    out.slope -= 2.0 * t.rate * (x - t.center) * psi;
  }
  return out;
}

double GaussianSum::Curvature(double x) const {
  double curvature = 0.0;
  for (const GaussianTerm& t : terms_) {
    const double dx = x - t.center;
    curvature += t(x) * (4.0 * t.rate * t.rate * dx * dx - 2.0 * t.rate);
  }
  return curvature;
}

double GaussianSum::NarrowestSpread() const {
  double largest_rate = 0.0;
  for (const GaussianTerm& t : terms_) largest_rate = std::max(largest_rate, t.rate);
  // rate = b / (2 sigma) = 1 / (2 s^2)
  return 1.0 / std::sqrt(2.0 * largest_rate);
}

namespace {

// Root of f' in [lo, hi] where f' changes sign from + to -: bisection until the bracket
// stops shrinking, which is as exact as doubles allow and cannot diverge.
double BisectSlopeRoot(const GaussianSum& sum, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (sum.ValueAndSlope(mid).slope > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

Maximum MaximumOnInterval(const GaussianSum& sum, double lo, double hi) {
  Maximum best{lo, sum.Value(lo)};
  const auto consider = [&best, &sum](double x) {
    const double value = sum.Value(x);
    if (value > best.value) best = {x, value};
  };
  consider(hi);

  // a sum of m Gaussians has at most 2m - 1 critical points; a grid step of a quarter of
  // the narrowest spread cannot step over a maximum and the minimum next to it
  const double width = hi - lo;
  const double step = std::min(width / 64.0, 0.25 * sum.NarrowestSpread());
  // clamped as a double first: a cast of an out-of-range double is undefined
  const long cells = static_cast<long>(
      std::clamp(std::ceil(width / step), 64.0, static_cast<double>(kMaxPeakSearchCells)));
  double left = lo;
  double left_slope = sum.ValueAndSlope(lo).slope;
  for (long i = 1; i <= cells; ++i) {
    const double right = (i == cells) ? hi : lo + width * static_cast<double>(i) / cells;
    const double right_slope = sum.ValueAndSlope(right).slope;
    if (left_slope > 0.0 && right_slope <= 0.0) consider(BisectSlopeRoot(sum, left, right));
    left = right;
    left_slope = right_slope;
  }
  return best;
}

ActiveLengthCurve::ActiveLengthCurve(ActiveLengthParams params)
    : params_((Validate(params), std::move(params))), sum_(params_.gaussians, params_.sigma) {
  const Maximum peak = MaximumOnInterval(sum_, params_.optimal_min, params_.optimal_max);
  if (!(peak.value > 0.0) || !std::isfinite(peak.value)) {
    throw ParameterError("gaussians", "max f on optimal_range = " + FormatNumber(peak.value),
                         "the sum of Gaussians must be positive somewhere on optimal_range "
                         "so that f_L can be normalised");
  }
  peak_value_ = peak.value;
  peak_length_ = peak.x;
  inverse_peak_ = 1.0 / peak.value;
}

}  // namespace musclesim
