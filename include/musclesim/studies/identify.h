// Identification of the model's parameters from measured curves (the paper's
// "identification-ready" claim made a tool):
//   passive:  slack length by profile likelihood over candidate thresholds, then k_p and
//             alpha (and the slack length, jointly) by Levenberg-Marquardt with the analytic
//             Jacobian (Eigen's unsupported LevenbergMarquardt); the slack length's confidence
//             interval from the same profile;
//   active:   a sum of Gaussians by the closed-form samples fit; f_iso its maximum;
//   velocity: for each n in 1..10, f_iso and v_max by linear least squares in
//             s = sgn(v) |v|^(1/n) (T = f_iso - (f_iso / v_max^(1/n)) s), the best n kept.
// Standard errors come from the Jacobian at the optimum: sigma^2 (J^T J)^-1 with
// sigma^2 = RSS / (points - parameters).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/model/active_length.h"
#include "musclesim/studies/reference_fits.h"

namespace musclesim {

// A fitted parameter; both numbers are in the parameter's unit.
struct Estimate {
  double value = 0.0;           // the estimate [the parameter's unit]
  double standard_error = 0.0;  // [the parameter's unit]; NaN when it cannot be estimated
};

// A profile-likelihood confidence interval: the values of a parameter that the data do not
// reject at `level` once the other parameters are refitted to each. An end the data cannot
// bound is marked so and says how far the search went: -infinity below, or the last value
// the data can still fit above.
struct ProfileInterval {
  double low = 0.0;           // [the parameter's unit]
  double high = 0.0;          // [the parameter's unit]
  bool low_bounded = false;   // false: values down to `low` fit as well as the best
  bool high_bounded = false;  // false: values up to `high` fit as well as the best
  double level = 0.95;        // [-], the confidence level
  // not bounded on a side, or wider than kWideFraction of the span of the data's lengths:
  // the data place the parameter only coarsely, and its standard error (a linearisation at
  // the optimum) does not describe that
  bool wide = false;
  static constexpr double kWideFraction = 0.1;  // [-]
};

// The least and greatest of a quantity [its unit].
struct ValueRange {
  double low = 0.0;
  double high = 0.0;
};

struct PassiveIdentification {
  Estimate slack_length;  // [m]
  Estimate k_p;           // [N]
  Estimate alpha;         // [1/m]
  double rmse = 0.0;      // [N]
  // the slack length's profile-likelihood interval (F test: see identify_slack_interval.cc)
  ProfileInterval slack_length_interval;  // [m]
  // the best k_p [N] and alpha [1/m] at the slack lengths inside that interval: how far the
  // slack length's uncertainty carries them, which their standard errors (a linearisation
  // at the optimum) leave out when the interval is wide. Not confidence intervals themselves.
  ValueRange k_p_over_interval;    // [N]
  ValueRange alpha_over_interval;  // [1/m]
  // T_p(x) [N] at length x [m], through the model's PassiveTension.
  double Evaluate(double x) const;
};

struct ActiveIdentification {
  ActiveLengthParams curve;  // f_L: amplitudes scaled so that max f = 1 on optimal_range
  Estimate f_iso;            // [N], the fitted curve's maximum
  std::vector<Estimate> amplitudes;  // a_k of `curve` [-], with standard errors
  std::vector<Estimate> precisions;  // b_k of `curve` [1/m^2] (YAML key `width`)
  std::vector<Estimate> centers;     // d_k of `curve` [m]
  double rmse = 0.0;         // [N]
  GaussianSum sum;           // f of `curve` [-], built once by IdentifyActive
  // f_iso f(x) [N] at length x [m]; allocates nothing, so timing it times the curve.
  double Evaluate(double x) const { return f_iso.value * sum.Value(x); }
};

struct VelocityCandidate {
  int n = 1;           // the power is 1/n [-]
  Estimate v_max;      // [m/s]
  Estimate f_iso;      // [N]
  double rmse = 0.0;   // [N]
  bool valid = false;  // false when the fit gives no positive v_max (tension rising with v)
};

struct VelocityIdentification {
  VelocityCandidate best;                     // the valid candidate of least RMSE
  std::vector<VelocityCandidate> candidates;  // n = 1..10
  // Unregularised f_iso g(v) [N] at shortening velocity v [m/s].
  double Evaluate(double v) const;
};

// Each throws InputError when the data cannot determine the parameters.
// IdentifyPassive's `level` (0 < level < 1, else std::invalid_argument) is the slack length
// interval's confidence level [-].
PassiveIdentification IdentifyPassive(const std::vector<DataPoint>& data, double level = 0.95);
ActiveIdentification IdentifyActive(const std::vector<DataPoint>& data, int count, bool nonnegative);
VelocityIdentification IdentifyVelocity(const std::vector<DataPoint>& data,
                                        std::optional<double> f_iso);

// Reads columns `x_name`, `y_name` of a CSV (lines starting with # are comments) and checks
// the data rules: at least `min_points` rows, finite values, x strictly increasing (no
// duplicates), tension not zero everywhere. Throws InputError naming file, row and reason.
std::vector<DataPoint> ReadCurveCsv(const std::string& path, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points);

}  // namespace musclesim
