#include "musclesim/model/gaussian_fit.h"

#include <nlopt.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

// "one of degroote2016, thelen2003, ...": the names a preset may have
std::string PresetNamesRule() {
  std::string rule = "one of ";
  for (const ForceLengthPreset preset : AllForceLengthPresets()) {
    if (preset != AllForceLengthPresets().front()) rule += ", ";
    rule += ToString(preset);
  }
  return rule;
}

std::string PointName(std::size_t i) { return "points[" + std::to_string(i) + "]"; }

std::string PointCount(const FitSpec& spec) {
  return std::to_string(spec.points.size()) + " points";
}

void ValidatePolygon(const FitSpec& spec) {
  if (spec.points.size() < 2) {
    throw ParameterError("points", PointCount(spec), "a polygon needs at least 2 points");
  }
  for (std::size_t i = 1; i < spec.points.size(); ++i) {
    Require(spec.points[i].x > spec.points[i - 1].x, PointName(i) + "[0]", spec.points[i].x,
            "polygon x must be strictly increasing (previous x = " +
                FormatNumber(spec.points[i - 1].x) + ")");
  }
}

void ValidatePreset(const FitSpec& spec) {
  if (!spec.points.empty()) {
    throw ParameterError("points", PointCount(spec),
                         "must be absent for target preset (it uses name and optimal_length)");
  }
  if (!spec.preset) {
    throw ParameterError("name", "~",
                         "target preset needs the name of a curve: " + PresetNamesRule());
  }
  if (!spec.optimal_length) {
    throw ParameterError("optimal_length", "~",
                         "target preset needs optimal_length, the length [m] where the "
                         "curve peaks");
  }
  Require(std::isfinite(*spec.optimal_length) && *spec.optimal_length > 0.0, "optimal_length",
          *spec.optimal_length, "must be finite and > 0 [m]");
}

// What the target asks of the points (and a preset of its name and length).
void ValidateTarget(const FitSpec& spec) {
  switch (spec.target) {
    case FitTargetKind::kIndicator:
      if (!spec.points.empty()) {
        throw ParameterError("points", PointCount(spec),
                             "must be absent for target indicator (it uses optimal_range)");
      }
      break;
    case FitTargetKind::kPolygon: ValidatePolygon(spec); break;
    case FitTargetKind::kPreset: ValidatePreset(spec); break;
    case FitTargetKind::kSamples: {
      const bool shapes_fixed = !spec.precisions.empty();
      const std::size_t needed = static_cast<std::size_t>(spec.count) * (shapes_fixed ? 1 : 3);
      if (spec.points.size() < needed) {
        throw ParameterError("points", PointCount(spec),
                             "samples need at least " + std::to_string(needed) + " points for " +
                                 std::to_string(spec.count) +
                                 " Gaussians (3 parameters each, 1 with shapes fixed)");
      }
      break;
    }
  }
}

// Fixed shapes: widths and centers together, count of each, widths > 0, all finite.
void ValidateShapes(const FitSpec& spec) {
  if (spec.precisions.empty() != spec.centers.empty()) {
    throw ParameterError(spec.precisions.empty() ? "centers" : "widths", "given alone",
                         "widths and centers fix the shapes together: give both or neither");
  }
  if (spec.precisions.empty()) return;
  for (const char* key : {"widths", "centers"}) {
    const auto& list = std::string(key) == "widths" ? spec.precisions : spec.centers;
    if (list.size() != static_cast<std::size_t>(spec.count)) {
      throw ParameterError(key, std::to_string(list.size()) + " values",
                           "must have count = " + std::to_string(spec.count) + " values");
    }
  }
  for (std::size_t k = 0; k < spec.precisions.size(); ++k) {
    Require(std::isfinite(spec.precisions[k]) && spec.precisions[k] > 0.0,
            "widths[" + std::to_string(k) + "]", spec.precisions[k], "must be finite and > 0");
    Require(std::isfinite(spec.centers[k]), "centers[" + std::to_string(k) + "]", spec.centers[k],
            "must be finite");
  }
}

}  // namespace

void Validate(const FitSpec& spec) {
  Require(
      kGaussianCountRange.Contains(spec.count), "count", spec.count,
      "must be an integer " + kGaussianCountRange.Bounds() + " [-]: " + kGaussianCountRange.why);
  for (std::size_t i = 0; i < spec.points.size(); ++i) {
    Require(std::isfinite(spec.points[i].x), PointName(i) + "[0]", spec.points[i].x,
            "must be finite");
    Require(std::isfinite(spec.points[i].y), PointName(i) + "[1]", spec.points[i].y,
            "must be finite");
  }
  ValidateTarget(spec);
  if (spec.target != FitTargetKind::kPreset && (spec.preset || spec.optimal_length)) {
    throw ParameterError(
        spec.preset ? "name" : "optimal_length",
        spec.preset ? std::string(ToString(*spec.preset)) : FormatNumber(*spec.optimal_length),
        "only for target preset (this target is " + std::string(ToString(spec.target)) + ")");
  }
  ValidateShapes(spec);
}

std::unique_ptr<FitTarget> MakeFitTarget(const FitSpec& spec, double l1, double l2, double sigma) {
  switch (spec.target) {
    case FitTargetKind::kIndicator: return MakePiecewiseLinearTarget({{l1, 1.0}, {l2, 1.0}}, sigma);
    case FitTargetKind::kPolygon: return MakePiecewiseLinearTarget(spec.points, sigma);
    case FitTargetKind::kSamples: return MakeSampleTarget(spec.points, sigma);
    case FitTargetKind::kPreset: return MakePresetTarget(*spec.preset, *spec.optimal_length, sigma);
  }
  return nullptr;
}

Eigen::VectorXd SolveAmplitudes(const Eigen::MatrixXd& gram, const Eigen::VectorXd& projection,
                                bool nonnegative) {
  if (!nonnegative) return gram.completeOrthogonalDecomposition().solve(projection);

  // Lawson-Hanson on the normal equations: grow the set of free (positive) amplitudes by
  // the steepest descent direction, step back to feasibility when a solve goes negative
  const Eigen::Index m = projection.size();
  const double tolerance = 1e-13 * std::max(1.0, projection.cwiseAbs().maxCoeff());
  Eigen::VectorXd a = Eigen::VectorXd::Zero(m);
  std::vector<bool> free(m, false);
  const auto solve_free = [&] {
    std::vector<Eigen::Index> index;
    for (Eigen::Index i = 0; i < m; ++i) {
      if (free[i]) index.push_back(i);
    }
    const auto n = static_cast<Eigen::Index>(index.size());
    Eigen::MatrixXd sub(n, n);
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      rhs(i) = projection(index[i]);
      for (Eigen::Index j = 0; j < n; ++j) sub(i, j) = gram(index[i], index[j]);
    }
    const Eigen::VectorXd solution = sub.completeOrthogonalDecomposition().solve(rhs);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(m);
    for (Eigen::Index i = 0; i < n; ++i) full(index[i]) = solution(i);
    return full;
  };

  for (int outer = 0; outer < 3 * m + 10; ++outer) {
    const Eigen::VectorXd descent = projection - gram * a;
    Eigen::Index entering = -1;
    double steepest = tolerance;
    for (Eigen::Index i = 0; i < m; ++i) {
      if (!free[i] && descent(i) > steepest) {
        steepest = descent(i);
        entering = i;
      }
    }
    if (entering < 0) break;
    free[entering] = true;
    for (int inner = 0; inner < 3 * m + 10; ++inner) {
      const Eigen::VectorXd trial = solve_free();
      double step = 1.0;
      for (Eigen::Index i = 0; i < m; ++i) {
        if (free[i] && trial(i) <= 0.0) step = std::min(step, a(i) / (a(i) - trial(i)));
      }
      a += step * (trial - a);
      if (step >= 1.0) break;
      for (Eigen::Index i = 0; i < m; ++i) {
        if (free[i] && a(i) <= tolerance) {
          free[i] = false;
          a(i) = 0.0;
        }
      }
    }
  }
  return a.cwiseMax(0.0);
}

namespace {

// The reduced problem: minimise N(b, d) / c over u = log(b / b_ref), t = (d - lo) / W,
// which are of order one whatever units the lengths are in.
class ReducedCost {
 public:
  ReducedCost(const FitTarget& target, double sigma, bool nonnegative)
      : target_(target),
        nonnegative_(nonnegative),
        lo_(target.SupportMin()),
        scale_(target.SupportMax() - target.SupportMin()),
        precision_ref_(sigma / (scale_ * scale_)),
        norm_(target.NormSquared()) {}

  GaussianShapes Shapes(const double* theta, int m) const {
    GaussianShapes shapes{Eigen::VectorXd(m), Eigen::VectorXd(m)};
    for (int k = 0; k < m; ++k) {
      shapes.precisions(k) = precision_ref_ * std::exp(theta[k]);
      shapes.centers(k) = lo_ + scale_ * theta[m + k];
    }
    return shapes;
  }

  // value of N / c at theta, its gradient written into `gradient` when not null
  double operator()(const double* theta, double* gradient, int m) {
    ++evaluations_;
    const GaussianShapes shapes = Shapes(theta, m);
    Eigen::MatrixXd gram;
    Eigen::VectorXd projection;
    target_.NormalEquations(shapes, gram, projection);
    const Eigen::VectorXd a = SolveAmplitudes(gram, projection, nonnegative_);
    CostGradient g;
    // the amplitudes are optimal, so the reduced gradient is the partial one in (b, d)
    const double cost = target_.Cost(a, shapes, gradient != nullptr ? &g : nullptr) / norm_;
    if (gradient != nullptr) {
      for (int k = 0; k < m; ++k) {
        gradient[k] = g.precisions(k) * shapes.precisions(k) / norm_;
        gradient[m + k] = g.centers(k) * scale_ / norm_;
      }
    }
    if (!std::isfinite(cost)) return std::numeric_limits<double>::max();
    return cost;
  }

  int evaluations() const { return evaluations_; }
  void ResetEvaluations() { evaluations_ = 0; }

 private:
  const FitTarget& target_;
  bool nonnegative_;
  double lo_, scale_, precision_ref_, norm_;
  int evaluations_ = 0;
};

struct Problem {
  ReducedCost* cost;
  int m;
};

double NloptObjective(unsigned n, const double* theta, double* gradient, void* data) {
  (void)n;
  auto* problem = static_cast<Problem*>(data);
  return (*problem->cost)(theta, gradient, problem->m);
}

// Starting points: centres spread evenly over the support (tightly or fully) and spreads
// (standard deviations) of a fraction of each component's share of it. Fixed, so fits are
// reproducible.
std::vector<std::vector<double>> StartingPoints(int m) {
  std::vector<std::vector<double>> starts;
  for (double spread : {1.0, 0.5}) {
    for (double fraction : {0.3, 0.15, 0.6}) {
      std::vector<double> theta(2 * m);
      const double deviation = fraction / m;  // in units of the support width
      for (int k = 0; k < m; ++k) {
        theta[k] = -2.0 * std::log(deviation);  // b = sigma / (W deviation)^2
        theta[m + k] = 0.5 + spread * ((k + 0.5) / m - 0.5);
      }
      starts.push_back(std::move(theta));
    }
    if (m == 1) break;  // one centre: the spread changes nothing
  }
  return starts;
}

FitResult Finish(const FitTarget& target, const GaussianShapes& shapes, bool nonnegative) {
  Eigen::MatrixXd gram;
  Eigen::VectorXd projection;
  target.NormalEquations(shapes, gram, projection);
  const Eigen::VectorXd a = SolveAmplitudes(gram, projection, nonnegative);
  FitResult result;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    result.gaussians.push_back({a(k), shapes.precisions(k), shapes.centers(k)});
  }
  result.cost = std::max(0.0, target.Cost(a, shapes, nullptr));
  result.relative_residual = result.cost / target.NormSquared();
  return result;
}

}  // namespace

FitResult FitGaussians(const FitSpec& spec, double l1, double l2, double sigma) {
  Validate(spec);
  const std::unique_ptr<FitTarget> target = MakeFitTarget(spec, l1, l2, sigma);
  if (!(target->NormSquared() > 0.0)) {
    throw ParameterError("points", "all y = 0", "the target must not be zero everywhere");
  }
  const int m = spec.count;

  if (!spec.precisions.empty()) {
    GaussianShapes fixed{Eigen::Map<const Eigen::VectorXd>(spec.precisions.data(), m),
                         Eigen::Map<const Eigen::VectorXd>(spec.centers.data(), m)};
    FitResult result = Finish(*target, fixed, spec.nonnegative);
    result.starts = 0;
    return result;
  }

  ReducedCost cost(*target, sigma, spec.nonnegative);
  Problem problem{&cost, m};
  const std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> owner(
      nlopt_create(NLOPT_LD_LBFGS, static_cast<unsigned>(2 * m)), &nlopt_destroy);
  nlopt_opt optimiser = owner.get();
  std::vector<double> lower(2 * m), upper(2 * m);
  for (int k = 0; k < m; ++k) {
    // spreads from 100 support widths down to 1e-4 of one; centres near the support
    lower[k] = -2.0 * std::log(100.0);
    upper[k] = -2.0 * std::log(1e-4);
    lower[m + k] = -3.0;
    upper[m + k] = 4.0;
  }
  nlopt_set_lower_bounds(optimiser, lower.data());
  nlopt_set_upper_bounds(optimiser, upper.data());
  nlopt_set_min_objective(optimiser, NloptObjective, &problem);
  nlopt_set_ftol_rel(optimiser, 1e-15);
  nlopt_set_xtol_rel(optimiser, 1e-12);
  nlopt_set_maxeval(optimiser, 5000);

  std::vector<double> best_theta;
  double best_value = std::numeric_limits<double>::infinity();
  int best_evaluations = 0;
  const std::vector<std::vector<double>> starts = StartingPoints(m);
  for (std::vector<double> theta : starts) {
    cost.ResetEvaluations();
    double value = std::numeric_limits<double>::infinity();
    // a negative code such as "roundoff limited" still leaves the best point in theta
    nlopt_optimize(optimiser, theta.data(), &value);
    if (std::isfinite(value) && value < best_value) {
      best_value = value;
      best_theta = theta;
      best_evaluations = cost.evaluations();
    }
  }
  if (best_theta.empty()) {
    throw ParameterError("fit", "no finite cost", "the minimiser found no usable start");
  }
  FitResult result = Finish(*target, cost.Shapes(best_theta.data(), m), spec.nonnegative);
  result.iterations = best_evaluations;
  result.starts = static_cast<int>(starts.size());
  return result;
}

}  // namespace musclesim
