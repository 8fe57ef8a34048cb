// Identification of the model's parameters from measured curves (the paper's
// "identification-ready" claim made a tool):
//   passive:  slack length by profile likelihood over candidate thresholds, then k_p and
//             alpha (and the slack length, jointly) by Levenberg-Marquardt with the analytic
//             Jacobian (Eigen's unsupported LevenbergMarquardt); the slack length's confidence
//             interval from the same profile;
//   active:   a sum of Gaussians by the closed-form samples fit; f_iso its maximum;
//   velocity: for each n in 1..10, f_iso and v_max by linear least squares in
//             s = sgn(v) |v|^(1/n) (T = f_iso - (f_iso / v_max^(1/n)) s), the best n kept;
//             when the data hold eccentric points (v < 0), this from the points v >= 0
//             only, and the eccentric branch (docs/model.md section 9) from those v < 0.
// Standard errors come from the Jacobian at the optimum: sigma^2 (J^T J)^-1 with
// sigma^2 = RSS / (points - parameters).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/model/active_length.h"
#include "musclesim/identify/reference_fits.h"

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
  ActiveLengthParams curve;          // f_L: amplitudes scaled so that max f = 1 on optimal_range
  Estimate f_iso;                    // [N], the fitted curve's maximum
  std::vector<Estimate> amplitudes;  // a_k of `curve` [-], with standard errors
  std::vector<Estimate> precisions;  // b_k of `curve` [1/m^2] (YAML key `width`)
  std::vector<Estimate> centers;     // d_k of `curve` [m]
  double rmse = 0.0;                 // [N]
  GaussianSum sum;                   // f of `curve` [-], built once by IdentifyActive
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

// One fit of the eccentric branch, T = f_iso (1 + psi) or f_iso (1 + (L - 1) tanh(psi /
// (L - 1))), psi = (-v / v_max_e)^(1/n_e), to the points with v < 0.
struct EccentricCandidate {
  int n = 1;           // n_e [-]
  Estimate v_max;      // v_max_e [m/s]
  Estimate limit;      // L [-]; value infinity (and error NaN) for the unbounded form
  double rmse = 0.0;   // over the eccentric points [N]
  bool valid = false;  // false when the tension does not rise with lengthening speed
};

// The eccentric branch, when the data hold points with v < 0. f_iso is held at the
// concentric estimate (its standard error carried into the ones here). For each n_e in
// 1..10 the unbounded form is a linear least-squares fit; the bounded one a Levenberg-
// Marquardt fit in (v_max_e^(-1/n_e), q = 1/(L - 1)^2 >= 0), q = 0 being the unbounded form.
// What the data cannot determine is said so, never guessed:
//   identified: at least 3 eccentric points, the tension rising with lengthening speed,
//     v_max_e's standard error finite and below its value, and the two-branch curve preferred
//     to the symmetric one fitted to every point by the Bayesian information criterion
//     (IdentifyVelocity decides this last rule; the symmetric fit is kept otherwise);
//   limit_identified: besides, at least 4 eccentric points, the bounded fit's Jacobian of
//     full rank, q more than two standard errors above 0 (a sign of levelling off), a better
//     fit than the unbounded form by the Bayesian information criterion, and L <= 1e6.
struct EccentricIdentification {
  std::size_t points = 0;                     // data points with v < 0 [-]
  bool identified = false;                    // v_max_e and n_e determined
  bool limit_identified = false;              // L determined (implies `identified`)
  std::string why_not;                        // when !identified: the reason, one sentence
  std::string why_no_limit;                   // when !limit_identified: the reason
  EccentricCandidate best;                    // what the model takes: the bounded candidate
                                              // when limit_identified, else the unbounded one
  std::vector<EccentricCandidate> unbounded;  // n_e = 1..10, no limit
  std::vector<EccentricCandidate> bounded;    // n_e = 1..10, with a limit
};

struct VelocityIdentification {
  VelocityCandidate best;                            // the valid candidate of least RMSE
  std::vector<VelocityCandidate> candidates;         // n = 1..10
  std::optional<EccentricIdentification> eccentric;  // when the data hold points v < 0
  // Unregularised f_iso g(v) [N] at shortening velocity v [m/s]: for v < 0 the identified
  // eccentric branch, or the concentric power law mirrored when there is none (the model
  // written out then has no `eccentric` block either).
  double Evaluate(double v) const;
};

// Each throws InputError when the data cannot determine the parameters.
// IdentifyPassive's `level` (0 < level < 1, else std::invalid_argument) is the slack length
// interval's confidence level [-].
PassiveIdentification IdentifyPassive(const std::vector<DataPoint>& data, double level = 0.95);
ActiveIdentification IdentifyActive(const std::vector<DataPoint>& data, int count,
                                    bool nonnegative);
VelocityIdentification IdentifyVelocity(const std::vector<DataPoint>& data,
                                        std::optional<double> f_iso);

// Reads columns `x_name`, `y_name` of a CSV (lines starting with # are comments) and checks
// the data rules: at least `min_points` rows, finite values, x strictly increasing (no
// duplicates), tension not zero everywhere. Throws InputError naming file, row and reason.
std::vector<DataPoint> ReadCurveCsv(const std::string& path, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points);

}  // namespace musclesim
