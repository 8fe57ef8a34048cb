#include "musclesim/studies/identify.h"

#include <unsupported/Eigen/LevenbergMarquardt>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/io/csv_table.h"
#include "musclesim/errors.h"
#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/passive.h"

namespace musclesim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// sigma^2 (J^T J)^-1 from residual Jacobian J and residual sum of squares; NaN when the
// data leave no degree of freedom. A pseudo-inverse keeps a degenerate fit finite.
Eigen::MatrixXd Covariance(const Eigen::MatrixXd& jacobian, double rss) {
  const Eigen::Index n = jacobian.rows(), p = jacobian.cols();
  if (n <= p) return Eigen::MatrixXd::Constant(p, p, kNaN);
  const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  return rss / static_cast<double>(n - p) *
         normal.completeOrthogonalDecomposition().pseudoInverse();
}

double Rmse(double rss, std::size_t n) { return std::sqrt(rss / static_cast<double>(n)); }

// ---- passive: the model's T_p (eq. 1) ------------------------------------------------

// Parameters (ln k, ln alpha) with x0 fixed, or (ln k, ln alpha, x0): logs keep k, alpha > 0.
struct PassiveResiduals : Eigen::DenseFunctor<double> {
  PassiveResiduals(const std::vector<DataPoint>& d, std::optional<double> slack)
      : Eigen::DenseFunctor<double>(slack ? 2 : 3, static_cast<int>(d.size())), data(d),
        fixed_slack(slack) {}

  PassiveParams Params(const Eigen::VectorXd& p) const {
    return {std::exp(p(0)), std::exp(p(1)), fixed_slack ? *fixed_slack : p(2)};
  }

  int operator()(const Eigen::VectorXd& p, Eigen::VectorXd& r) const {
    const PassiveParams params = Params(p);
    for (std::size_t i = 0; i < data.size(); ++i) {
      r(static_cast<Eigen::Index>(i)) = PassiveTension(params, data[i].x).value - data[i].y;
    }
    return 0;
  }

  // with T and dT/dx from PassiveTension, u = x - x0: dT/d(ln k) = T,
  // dT/d(ln alpha) = u dT/dx, dT/dx0 = -dT/dx
  int df(const Eigen::VectorXd& p, Eigen::MatrixXd& j) const {
    const PassiveParams params = Params(p);
    for (std::size_t i = 0; i < data.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      const CurvePoint t = PassiveTension(params, data[i].x);
      j(row, 0) = t.value;
      j(row, 1) = (data[i].x - params.slack_length) * t.slope;
      if (!fixed_slack) j(row, 2) = -t.slope;
    }
    return 0;
  }

  const std::vector<DataPoint>& data;
  std::optional<double> fixed_slack;
};

double Minimise(PassiveResiduals& residuals, Eigen::VectorXd& p) {
  Eigen::LevenbergMarquardt<PassiveResiduals> lm(residuals);
  lm.setXtol(1e-15);
  lm.setFtol(1e-15);
  lm.setMaxfev(2000);
  lm.minimize(p);
  Eigen::VectorXd r(residuals.values());
  residuals(p, r);
  return std::isfinite(r.squaredNorm()) ? r.squaredNorm() : std::numeric_limits<double>::infinity();
}

// (ln k, ln alpha) to start from for a slack length x0: a log-linear fit of the larger
// tensions, where T ~ k exp(alpha (x - x0)).
Eigen::VectorXd PassiveStart(const std::vector<DataPoint>& data, double x0, double span) {
  double top = 0.0;
  for (const DataPoint& d : data) top = std::max(top, d.y);
  double su = 0, sl = 0, suu = 0, sul = 0, n = 0;
  for (const DataPoint& d : data) {
    if (d.x <= x0 || d.y <= 0.05 * top) continue;
    const double u = d.x - x0, l = std::log(d.y);
    su += u; sl += l; suu += u * u; sul += u * l; n += 1;
  }
  double alpha = 3.0 / span, log_k = std::log(std::max(top, 1e-300)) - 3.0;
  if (n >= 2 && n * suu - su * su > 0) {
    const double slope = (n * sul - su * sl) / (n * suu - su * su);
    if (slope > 0) {
      alpha = slope;
      log_k = (sl - slope * su) / n;
    }
  }
  Eigen::VectorXd p(2);
  p << log_k, std::log(alpha);
  return p;
}

}  // namespace

double PassiveIdentification::Evaluate(double x) const {
  return PassiveTension({k_p.value, alpha.value, slack_length.value}, x).value;
}

PassiveIdentification IdentifyPassive(const std::vector<DataPoint>& data) {
  const double lo = data.front().x, hi = data.back().x, span = hi - lo;
  // the profile: the best (k, alpha) for each candidate slack length
  const auto profile = [&](double x0, Eigen::VectorXd* best) {
    std::size_t above = 0;
    for (const DataPoint& d : data) above += d.x > x0 && d.y > 0;
    if (above < 2) return std::numeric_limits<double>::infinity();
    PassiveResiduals residuals(data, x0);
    Eigen::VectorXd p = PassiveStart(data, x0, span);
    const double rss = Minimise(residuals, p);
    if (best != nullptr) *best = p;
    return rss;
  };
  const int candidates = 200;
  const double first = lo - 0.25 * span, step = (hi - first) / candidates;
  double best_x0 = first, best_rss = std::numeric_limits<double>::infinity();
  for (int i = 0; i < candidates; ++i) {
    const double x0 = first + step * i;
    const double rss = profile(x0, nullptr);
    if (rss < best_rss) {
      best_rss = rss;
      best_x0 = x0;
    }
  }
  if (!std::isfinite(best_rss)) {
    throw InputError("passive data: fewer than 2 points with positive tension; nothing to fit");
  }
  // golden-section refinement of the profile around the best candidate
  double a = best_x0 - step, b = best_x0 + step;
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double c = b - ratio * (b - a), d = a + ratio * (b - a);
    if (profile(c, nullptr) < profile(d, nullptr)) {
      b = d;
    } else {
      a = c;
    }
  }
  double x0 = 0.5 * (a + b);
  Eigen::VectorXd p2;
  if (!(profile(x0, &p2) <= best_rss)) {
    x0 = best_x0;
    profile(x0, &p2);
  }
  // all three jointly from the profile's optimum
  Eigen::VectorXd p(3);
  p << p2(0), p2(1), x0;
  PassiveResiduals joint(data, std::nullopt);
  Eigen::VectorXd q = p;
  const double joint_rss = Minimise(joint, q);
  PassiveResiduals fixed(data, x0);
  Eigen::VectorXd r2 = p2;
  const double profile_rss = Minimise(fixed, r2);
  if (joint_rss <= profile_rss) p = q; else p << r2(0), r2(1), x0;
  const double rss = std::min(joint_rss, profile_rss);

  Eigen::MatrixXd jacobian(joint.values(), 3);
  joint.df(p, jacobian);
  const Eigen::MatrixXd cov = Covariance(jacobian, rss);
  PassiveIdentification out;
  const double k = std::exp(p(0)), alpha = std::exp(p(1));
  out.k_p = {k, k * std::sqrt(cov(0, 0))};
  out.alpha = {alpha, alpha * std::sqrt(cov(1, 1))};
  out.slack_length = {p(2), std::sqrt(cov(2, 2))};
  out.rmse = Rmse(rss, data.size());
  return out;
}

// ---- active: the samples fit -----------------------------------------------------------

ActiveIdentification IdentifyActive(const std::vector<DataPoint>& data, int count, bool nonnegative) {
  double top = 0.0;
  for (const DataPoint& d : data) top = std::max(top, std::abs(d.y));
  FitSpec spec;
  spec.count = count;
  spec.target = FitTargetKind::kSamples;
  spec.nonnegative = nonnegative;
  for (const DataPoint& d : data) spec.points.push_back({d.x, d.y / top});  // of order one
  FitResult fit;
  try {
    fit = FitGaussians(spec, data.front().x, data.back().x, 1.0);
  } catch (const ParameterError& e) {
    throw InputError("active data: " + std::string(e.what()));
  }
  const GaussianSum sum(fit.gaussians, 1.0);
  const Maximum peak = MaximumOnInterval(sum, data.front().x, data.back().x);
  if (!(peak.value > 0.0)) throw InputError("active data: the fitted curve is nowhere positive");

  ActiveIdentification out;
  out.f_iso.value = peak.value * top;
  out.curve.sigma = 1.0;
  for (Gaussian g : fit.gaussians) {
    g.amplitude /= peak.value;  // so that max f = 1
    out.curve.gaussians.push_back(g);
  }
  // optimal_range: where the fitted curve stays within 2% of its maximum
  const double span = data.back().x - data.front().x, step = span / 4000.0;
  double l1 = peak.x, l2 = peak.x;
  while (l1 - step >= data.front().x && sum.Value(l1 - step) >= 0.98 * peak.value) l1 -= step;
  while (l2 + step <= data.back().x && sum.Value(l2 + step) >= 0.98 * peak.value) l2 += step;
  if (!(l2 > l1)) { l1 = peak.x - 1e-6 * span; l2 = peak.x + 1e-6 * span; }
  out.curve.optimal_min = l1;
  out.curve.optimal_max = l2;
  out.sum = GaussianSum(out.curve.gaussians, out.curve.sigma);

  // residual Jacobian of the normalised fit in (a, b, d), for the standard errors
  const auto m = static_cast<Eigen::Index>(fit.gaussians.size());
  Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(data.size()), 3 * m);
  double rss = 0.0;
  for (std::size_t s = 0; s < data.size(); ++s) {
    const auto row = static_cast<Eigen::Index>(s);
    rss += std::pow(sum.Value(data[s].x) - data[s].y / top, 2);
    for (Eigen::Index k = 0; k < m; ++k) {
      const Gaussian& g = fit.gaussians[static_cast<std::size_t>(k)];
      const double dx = data[s].x - g.center;
      // psi_k = a_k phi_k with sigma = 1: d/da = phi, d/db = -psi dx^2 / 2, d/dd = psi b dx
      const double phi = GaussianTerm::Unit(g.precision, g.center, 1.0)(data[s].x);
      jacobian(row, k) = phi;
      jacobian(row, m + k) = g.amplitude * phi * (-dx * dx / 2.0);
      jacobian(row, 2 * m + k) = g.amplitude * phi * g.precision * dx;
    }
  }
  const Eigen::MatrixXd cov = Covariance(jacobian, rss);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Gaussian& g = out.curve.gaussians[static_cast<std::size_t>(k)];
    out.amplitudes.push_back({g.amplitude, std::sqrt(cov(k, k)) / peak.value});
    out.precisions.push_back({g.precision, std::sqrt(cov(m + k, m + k))});
    out.centers.push_back({g.center, std::sqrt(cov(2 * m + k, 2 * m + k))});
  }
  // f_iso's error by the delta method, its gradient by central differences of the peak
  Eigen::VectorXd gradient(3 * m);
  for (Eigen::Index j = 0; j < 3 * m; ++j) {
    const auto shifted = [&](double sign) {
      std::vector<Gaussian> gs = fit.gaussians;
      Gaussian& g = gs[static_cast<std::size_t>(j % m)];
      double& value = j < m ? g.amplitude : (j < 2 * m ? g.precision : g.center);
      const double h = 1e-6 * std::max(std::abs(value), j < 2 * m ? 1e-12 : span);
      value += sign * h;
      return std::make_pair(MaximumOnInterval(GaussianSum(gs, 1.0), data.front().x, data.back().x).value, h);
    };
    const auto [up, h] = shifted(1.0);
    const auto [down, h2] = shifted(-1.0);
    (void)h2;
    gradient(j) = top * (up - down) / (2.0 * h);
  }
  out.f_iso.standard_error = std::sqrt(gradient.dot(cov * gradient));
  out.rmse = Rmse(rss, data.size()) * top;
  return out;
}

// ---- velocity: linear in s = sgn(v) |v|^(1/n) -----------------------------------------

double VelocityIdentification::Evaluate(double v) const {
  const double s = (v > 0) - (v < 0);
  return best.f_iso.value * (1.0 - s * std::pow(std::abs(v) / best.v_max.value, 1.0 / best.n));
}

VelocityIdentification IdentifyVelocity(const std::vector<DataPoint>& data,
                                        std::optional<double> f_iso) {
  VelocityIdentification out;
  const auto n_points = static_cast<Eigen::Index>(data.size());
  for (int n = 1; n <= 10; ++n) {
    VelocityCandidate c;
    c.n = n;
    Eigen::MatrixXd design(n_points, f_iso ? 1 : 2);
    Eigen::VectorXd y(n_points);
    for (Eigen::Index i = 0; i < n_points; ++i) {
      const double v = data[static_cast<std::size_t>(i)].x;
      const double s = ((v > 0) - (v < 0)) * std::pow(std::abs(v), 1.0 / n);
      y(i) = data[static_cast<std::size_t>(i)].y - (f_iso ? *f_iso : 0.0);
      if (f_iso) {
        design(i, 0) = s;
      } else {
        design(i, 0) = 1.0;
        design(i, 1) = s;
      }
    }
    const Eigen::VectorXd coef = design.colPivHouseholderQr().solve(y);
    const double rss = (design * coef - y).squaredNorm();
    const Eigen::MatrixXd cov = Covariance(design, rss);
    const double a = f_iso ? *f_iso : coef(0), b = f_iso ? coef(0) : coef(1);
    const double var_a = f_iso ? 0.0 : cov(0, 0), var_b = f_iso ? cov(0, 0) : cov(1, 1);
    const double cov_ab = f_iso ? 0.0 : cov(0, 1);
    c.rmse = Rmse(rss, data.size());
    c.valid = a > 0 && b < 0;
    if (c.valid) {
      const double v_max = std::pow(-a / b, n);
      // delta method: dv/da = n v / a, dv/db = -n v / b
      const double da = n * v_max / a, db = -n * v_max / b;
      c.v_max = {v_max, std::sqrt(da * da * var_a + db * db * var_b + 2 * da * db * cov_ab)};
      c.f_iso = {a, f_iso ? 0.0 : std::sqrt(var_a)};
    }
    out.candidates.push_back(c);
  }
  const auto best = std::min_element(out.candidates.begin(), out.candidates.end(),
                                     [](const VelocityCandidate& p, const VelocityCandidate& q) {
                                       if (p.valid != q.valid) return p.valid;
                                       return p.rmse < q.rmse;
                                     });
  if (!best->valid) {
    throw InputError("velocity data: tension does not fall with shortening velocity for any n "
                     "in 1..10; nothing to fit");
  }
  out.best = *best;
  return out;
}

std::vector<DataPoint> ReadCurveCsv(const std::string& path, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points) {
  const CsvTable table = ReadCsv(path);
  table.Require({x_name, y_name}, "columns " + x_name + "," + y_name);
  if (table.rows.size() < min_points) {
    throw InputError(path + ": too few points: " + std::to_string(table.rows.size()) +
                     ", need at least " + std::to_string(min_points));
  }
  const int xc = table.Find(x_name), yc = table.Find(y_name);
  std::vector<DataPoint> data;
  bool any_tension = false;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const DataPoint p{table.Number(r, xc), table.Number(r, yc)};
    const std::string where = path + ":" + std::to_string(table.lines[r]) + ": ";
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw InputError(where + x_name + " = " + FormatNumber(p.x) + ", " + y_name + " = " +
                       FormatNumber(p.y) + ": values must be finite");
    }
    if (!data.empty() && !(p.x > data.back().x)) {
      throw InputError(where + x_name + " = " + FormatNumber(p.x) + " is not greater than the row "
                       "before (" + FormatNumber(data.back().x) + "): rows must be sorted by " +
                       x_name + ", without duplicates");
    }
    any_tension = any_tension || p.y != 0.0;
    data.push_back(p);
  }
  if (!any_tension) throw InputError(path + ": every " + y_name + " is zero: nothing to fit");
  return data;
}

}  // namespace musclesim
