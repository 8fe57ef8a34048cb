// Eccentric identification: for each n_e, v_max_e of the unbounded branch by linear least
// squares, and (v_max_e, L) of the bounded one by Levenberg-Marquardt in
// (c, q) = (v_max_e^(-1/n_e), 1/(L - 1)^2), q >= 0. In q the bounded branch
// f_iso (1 + tanh(sqrt(q) psi) / sqrt(q)), psi = c (-v)^(1/n_e), is smooth down to q = 0,
// where it is the unbounded one: "no limit" is a point of the family, not a limit of it.
#include "identify/identify_eccentric.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/core/number_format.h"
#include "musclesim/model/velocity.h"
#include "identify/identify_fit_statistics.h"

namespace musclesim::identify_detail {

namespace {

constexpr int kMaxExponent = 10;            // n_e = 1..10, the concentric scan's range
constexpr std::size_t kMinPoints = 3;       // v_max_e and n_e, with two degrees of freedom
constexpr std::size_t kMinLimitPoints = 4;  // and L: two parameters, two degrees of freedom
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// m(psi, q) = tanh(sqrt(q) psi) / sqrt(q) (psi itself at q = 0), the excess g - 1, with its
// derivatives in psi and q.
struct Bend {
  double value;  // m [-]
  double d_psi;  // dm/dpsi [-]
  double d_q;    // dm/dq [-]
};

Bend Bent(double psi, double q) {
  if (q == 0.0) return {psi, 1.0, -psi * psi * psi / 3.0};
  const double r = std::sqrt(q), z = r * psi, t = std::tanh(z), sech2 = 1.0 - t * t;
  // dm/dq = (z sech^2 z - tanh z) / (2 q^(3/2)); its two terms cancel to O(z^3) for small z,
  // where the series -2/3 z^3 + 8/15 z^5 - 34/105 z^7 is exact to 1e-12 relative
  const double series = -1.0 / 3.0 + z * z * (4.0 / 15.0 - z * z * 17.0 / 105.0);
  const double d_q = z < 1e-2 ? psi * psi * psi * series : (z * sech2 - t) / (2.0 * q * r);
  return {t / r, sech2, d_q};
}

// The points of one n_e: s_i = (-v_i)^(1/n_e) and the tensions.
struct Branch {
  int n = 1;
  Eigen::VectorXd s;        // [(m/s)^(1/n_e)]
  Eigen::VectorXd tension;  // [N]
  double f_iso = 0.0;       // [N], held
};

// Residuals r = T - f_iso (1 + m(c s, q)) at (c, q), their Jacobian in (c, q) (the first
// column only when `bounded` is false) and their derivative in f_iso.
struct Linearisation {
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd by_f_iso;
  double rss() const { return residual.squaredNorm(); }
};

Linearisation Linearise(const Branch& b, double c, double q, bool bounded) {
  const Eigen::Index k = b.s.size();
  Linearisation out{Eigen::VectorXd(k), Eigen::MatrixXd(k, bounded ? 2 : 1), Eigen::VectorXd(k)};
  for (Eigen::Index i = 0; i < k; ++i) {
    const Bend m = Bent(c * b.s(i), q);
    out.residual(i) = b.tension(i) - b.f_iso * (1.0 + m.value);
    out.jacobian(i, 0) = -b.f_iso * m.d_psi * b.s(i);
    if (bounded) out.jacobian(i, 1) = -b.f_iso * m.d_q;
    out.by_f_iso(i) = -(1.0 + m.value);
  }
  return out;
}

// Whether J has full column rank, its columns scaled to unit length first (c and q have
// unrelated units): a column within 1e-10 of the others' span is no information.
bool FullRank(const Eigen::MatrixXd& jacobian) {
  Eigen::MatrixXd scaled = jacobian;
  for (Eigen::Index j = 0; j < scaled.cols(); ++j) {
    const double norm = scaled.col(j).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return false;
    scaled.col(j) /= norm;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(scaled);
  qr.setThreshold(1e-10);
  return qr.rank() == scaled.cols();
}

// One fitted candidate, with what the decision needs beyond the public candidate.
struct Fit {
  EccentricCandidate candidate;
  double rss = kInfinity;  // [N^2]
  double q = 0.0;          // 1/(L - 1)^2 [-]
  double q_error = kNaN;   // its standard error [-]
  bool full_rank = false;
};

// Standard errors of (c, q) at the optimum: sigma^2 (J^T J)^-1 from the eccentric points,
// plus f_iso's variance carried through d(c, q)/df_iso = -(J^T J)^-1 J^T dr/df_iso (the
// concentric points that gave f_iso are independent of these).
Eigen::MatrixXd ParameterCovariance(const Linearisation& at, double f_iso_variance) {
  const Eigen::Index p = at.jacobian.cols();
  if (!FullRank(at.jacobian)) return Eigen::MatrixXd::Constant(p, p, kNaN);
  Eigen::MatrixXd cov = Covariance(at.jacobian, at.rss());
  if (f_iso_variance > 0.0) {
    const Eigen::MatrixXd normal = at.jacobian.transpose() * at.jacobian;
    const Eigen::VectorXd sensitivity = -normal.ldlt().solve(at.jacobian.transpose() * at.by_f_iso);
    cov += f_iso_variance * sensitivity * sensitivity.transpose();
  }
  return cov;
}

// The candidate of (c, q): v_max_e = c^-n_e and L = 1 + 1/sqrt(q), by the delta method.
Fit Finish(const Branch& b, double c, double q, bool bounded, double f_iso_variance) {
  Fit fit;
  fit.candidate.n = b.n;
  const Linearisation at = Linearise(b, c, q, bounded);
  fit.rss = at.rss();
  fit.candidate.rmse = Rmse(fit.rss, static_cast<std::size_t>(b.s.size()));
  const double v_max = std::pow(c, -b.n);
  fit.candidate.valid = c > 0.0 && std::isfinite(v_max) && v_max > 0.0;
  if (!fit.candidate.valid) return fit;
  const Eigen::MatrixXd cov = ParameterCovariance(at, f_iso_variance);
  fit.full_rank = !std::isnan(cov(0, 0));
  // dv/dc = -n_e v / c
  fit.candidate.v_max = {v_max, b.n * v_max / c * std::sqrt(cov(0, 0))};
  fit.candidate.limit = {kInfinity, kNaN};
  if (bounded) {
    fit.q = q;
    fit.q_error = std::sqrt(cov(1, 1));
    // dL/dq = -q^(-3/2) / 2
    if (q > 0.0) {
      fit.candidate.limit = {1.0 + 1.0 / std::sqrt(q), fit.q_error / (2.0 * q * std::sqrt(q))};
    }
  }
  return fit;
}

// The unbounded branch: T - f_iso = (f_iso c) s, a line through the origin.
Fit FitUnbounded(const Branch& b, double f_iso_variance) {
  const double c = b.s.dot((b.tension.array() - b.f_iso).matrix()) / (b.f_iso * b.s.squaredNorm());
  return Finish(b, c, 0.0, false, f_iso_variance);
}

// Levenberg-Marquardt (Marquardt's diagonal scaling) on (c, q) from (c0, q0), keeping q >= 0:
// a step that would leave it moves c alone with q on the bound.
std::pair<double, double> Minimise(const Branch& b, double c, double q) {
  double lambda = 1e-3;
  Linearisation at = Linearise(b, c, q, true);
  for (int iteration = 0; iteration < 500 && lambda < 1e16; ++iteration) {
    const Eigen::Matrix2d normal = at.jacobian.transpose() * at.jacobian;
    const Eigen::Vector2d gradient = at.jacobian.transpose() * at.residual;
    Eigen::Matrix2d damped = normal;
    damped.diagonal() *= 1.0 + lambda;
    Eigen::Vector2d step = damped.ldlt().solve(-gradient);
    if (q + step(1) < 0.0) step = {-gradient(0) / damped(0, 0), -q};  // to the bound
    const double c_trial = c + step(0), q_trial = std::max(0.0, q + step(1));
    const Linearisation trial = Linearise(b, c_trial, q_trial, true);
    if (c_trial > 0.0 && trial.rss() < at.rss()) {
      const bool settled = at.rss() - trial.rss() <= 1e-15 * at.rss();
      c = c_trial;
      q = q_trial;
      at = trial;
      lambda = std::max(1e-12, 0.3 * lambda);
      if (settled) break;
    } else {
      lambda *= 4.0;
    }
  }
  return {c, q};
}

// The bounded branch from a few starting limits: none (q = 0) and L - 1 at the largest psi
// the unbounded fit reaches and at a quarter of it; the least squares kept.
Fit FitBounded(const Branch& b, const Fit& unbounded, double f_iso_variance) {
  Fit best;
  if (!unbounded.candidate.valid) return best;
  const double c0 = std::pow(unbounded.candidate.v_max.value, -1.0 / b.n);
  const double psi_max = c0 * b.s.maxCoeff();
  for (double q0 : {0.0, 1.0 / (psi_max * psi_max), 16.0 / (psi_max * psi_max)}) {
    const auto [c, q] = Minimise(b, c0, q0);
    Fit fit = Finish(b, c, q, true, f_iso_variance);
    if (fit.candidate.valid && fit.rss < best.rss) best = fit;
  }
  return best;
}

const Fit* LeastSquares(const std::vector<Fit>& fits) {
  const Fit* best = nullptr;
  for (const Fit& f : fits) {
    if (f.candidate.valid && (!best || f.rss < best->rss)) best = &f;
  }
  return best;
}

// Whether the Bayesian information criterion prefers a fit with one parameter more, of
// residual sum of squares `rss`, to one of `simpler_rss`, both over `points` points:
// points ln(simpler_rss / rss) > ln(points).
bool BicPrefers(double simpler_rss, double rss, std::size_t points) {
  const auto k = static_cast<double>(points);
  return k * std::log(simpler_rss / rss) > std::log(k);
}

std::string PlusMinus(const Estimate& e, const char* unit) {
  return FormatNumber(e.value) + " +- " + FormatNumber(e.standard_error) + unit;
}

// Whether `fit`'s v_max_e is determined: a finite standard error below the value.
bool Determined(const Fit& fit) {
  const Estimate& v = fit.candidate.v_max;
  return fit.full_rank && std::isfinite(v.standard_error) && v.standard_error < v.value;
}

// Every n_e's fits of the eccentric points: the unbounded branch's, and the bounded one's
// (an invalid fit when there are too few points for a limit).
struct ExponentScan {
  std::vector<Fit> unbounded, bounded;
};

ExponentScan FitEveryExponent(const std::vector<DataPoint>& lengthening,
                              const Eigen::VectorXd& tension, double f_iso, double f_iso_variance) {
  ExponentScan scan;
  const Eigen::Index k = tension.size();
  for (int n = 1; n <= kMaxExponent && k > 0; ++n) {
    Branch b{n, Eigen::VectorXd(k), tension, f_iso};
    for (Eigen::Index i = 0; i < k; ++i) {
      b.s(i) = std::pow(-lengthening[static_cast<std::size_t>(i)].x, 1.0 / n);
    }
    scan.unbounded.push_back(FitUnbounded(b, f_iso_variance));
    scan.bounded.push_back(lengthening.size() >= kMinLimitPoints
                               ? FitBounded(b, scan.unbounded.back(), f_iso_variance)
                               : Fit{});
    scan.bounded.back().candidate.n = n;
  }
  return scan;
}

std::string PointCount(std::size_t points) { return std::to_string(points) + " with v < 0"; }

// Whether the unbounded branch is identified (out.identified, out.best), or why not.
void DecideBranch(const std::vector<DataPoint>& lengthening, const Fit* free, const Fit* bound,
                  EccentricIdentification& out) {
  // a tension flat over the eccentric points (at f_iso, or saturated at L f_iso) has no
  // v_max_e to show: the branch must beat a constant by the Bayesian information criterion
  double mean = 0.0, flat_rss = 0.0;
  for (const DataPoint& p : lengthening) mean += p.y / static_cast<double>(out.points);
  for (const DataPoint& p : lengthening) flat_rss += (p.y - mean) * (p.y - mean);
  const double branch_rss = std::min(free ? free->rss : kInfinity, bound ? bound->rss : kInfinity);
  const bool beats_flat = BicPrefers(flat_rss, branch_rss, out.points);
  if (out.points < kMinPoints) {
    out.why_not = "too few eccentric points: " + PointCount(out.points) +
                  ", need at least 3 for v_max_e and n_e";
  } else if (free && !beats_flat) {
    out.why_not = "the tension shows no trend with the lengthening speed (flat at " +
                  FormatNumber(mean) + " N to within the noise, RMSE " +
                  FormatNumber(std::sqrt(flat_rss / static_cast<double>(out.points))) +
                  " N): nothing determines v_max_e and n_e";
  } else if (!free) {
    out.why_not = "the tension does not rise with the lengthening speed for any n_e in 1..10";
  } else if (!Determined(*free)) {
    out.why_not = "v_max_e = " + PlusMinus(free->candidate.v_max, " m/s") +
                  ": the standard error is not below the value";
  } else {
    out.identified = true;
    out.best = free->candidate;
  }
}

// Whether the branch's limit is identified too (out.limit_identified, out.best), or why not.
// `rounding`: the residual sum of squares that is rounding alone [N^2].
void DecideLimit(const Fit* free, const Fit* bound, double rounding, EccentricIdentification& out) {
  if (!out.identified) {
    out.why_no_limit = "the eccentric branch itself is not identified";
  } else if (out.points < kMinLimitPoints) {
    out.why_no_limit =
        "too few eccentric points: " + PointCount(out.points) + ", need at least 4 for a limit too";
  } else if (!bound) {
    out.why_no_limit = "no bounded fit with the tension rising with the lengthening speed";
  } else if (!bound->full_rank) {
    out.why_no_limit = "the bounded fit's Jacobian is singular: v_max_e and L cannot be told apart";
  } else if (free->rss <= rounding) {
    out.why_no_limit = "the unbounded branch fits the eccentric points to rounding";
  } else if (!BicPrefers(free->rss, bound->rss, out.points)) {
    out.why_no_limit = "no sign of levelling off: a limit fits no better than no limit (RMSE " +
                       FormatNumber(bound->candidate.rmse) + " N against " +
                       FormatNumber(free->candidate.rmse) +
                       " N, not enough for one more parameter by the Bayesian information "
                       "criterion)";
  } else if (!(bound->q > 2.0 * bound->q_error)) {
    out.why_no_limit = "no sign of levelling off: 1/(L - 1)^2 = " + FormatNumber(bound->q) +
                       " +- " + FormatNumber(bound->q_error) +
                       " is within two standard errors of 0 (no limit)";
  } else if (!(bound->candidate.limit.value <= kMaxEccentricLimit)) {
    out.why_no_limit = "L = " + FormatNumber(bound->candidate.limit.value) +
                       " is beyond 1e6, the largest limit the model takes";
  } else if (!Determined(*bound)) {
    out.why_no_limit = "with a limit, v_max_e = " + PlusMinus(bound->candidate.v_max, " m/s") +
                       " is not determined (the standard error is not below the value)";
  } else {
    out.limit_identified = true;
    out.best = bound->candidate;
  }
}

}  // namespace

double EccentricFactor(const EccentricCandidate& branch, double v) {
  const double psi = std::pow(-v / branch.v_max.value, 1.0 / branch.n);
  if (!std::isfinite(branch.limit.value)) return 1.0 + psi;
  const double headroom = branch.limit.value - 1.0;
  return 1.0 + headroom * std::tanh(psi / headroom);
}

EccentricIdentification IdentifyEccentric(const std::vector<DataPoint>& lengthening,
                                          const Estimate& f_iso) {
  EccentricIdentification out;
  out.points = lengthening.size();
  // 0 when f_iso was given; the concentric fit always leaves a degree of freedom (it needs 3
  // points for 2 parameters), so its error is finite when fitted
  const double f_iso_variance =
      std::isfinite(f_iso.standard_error) ? f_iso.standard_error * f_iso.standard_error : 0.0;
  const auto k = static_cast<Eigen::Index>(lengthening.size());
  Eigen::VectorXd tension(k);
  for (Eigen::Index i = 0; i < k; ++i) tension(i) = lengthening[static_cast<std::size_t>(i)].y;
  const double scale = k > 0 ? tension.cwiseAbs().maxCoeff() : 0.0;  // [N]
  const ExponentScan scan = FitEveryExponent(lengthening, tension, f_iso.value, f_iso_variance);
  for (const Fit& fit : scan.unbounded) out.unbounded.push_back(fit.candidate);
  for (const Fit& fit : scan.bounded) out.bounded.push_back(fit.candidate);
  const Fit* free = LeastSquares(scan.unbounded);
  const Fit* bound = LeastSquares(scan.bounded);
  DecideBranch(lengthening, free, bound, out);
  // residuals of 1e-12 of the tensions are rounding: a fit that good leaves nothing to explain
  const double rounding = static_cast<double>(out.points) * std::pow(1e-12 * scale, 2);
  DecideLimit(free, bound, rounding, out);
  return out;
}

}  // namespace musclesim::identify_detail
