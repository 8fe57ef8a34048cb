#include "musclesim/core/bounded_least_squares.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

// The first lambda: the damping term lambda |D d|^2 with D the column norms makes lambda
// a fraction of each diagonal entry of J^T J (Marquardt's scaling). 1e-2 starts near
// Gauss-Newton's step, which each run saved is worth, while damping the directions of
// strongly correlated parameters; a start so poor that this overshoots costs a rejected run
// or two (1e-3 leaps from a poor start of a decaying exponential to another valley).
constexpr double kInitialDamping = 1e-2;

Eigen::VectorXd WeightedResidual(const BoundedLeastSquaresProblem& problem, const ModelPoint& m) {
  return problem.weights.cwiseProduct(problem.data - m.predictions);
}

// d r / d p for r = W (data - prediction).
Eigen::MatrixXd ResidualJacobian(const BoundedLeastSquaresProblem& problem, const ModelPoint& m) {
  return -(problem.weights.asDiagonal() * m.jacobian);
}

void CheckShape(const ModelPoint& m, Eigen::Index n, Eigen::Index p) {
  if (m.predictions.size() != n || m.jacobian.rows() != n || m.jacobian.cols() != p) {
    throw std::logic_error("identify: the model returned " + std::to_string(m.predictions.size()) +
                           " predictions and a " + std::to_string(m.jacobian.rows()) + " x " +
                           std::to_string(m.jacobian.cols()) + " Jacobian for " +
                           std::to_string(n) + " values and " + std::to_string(p) + " parameters");
  }
}

// Whether every component of `step` is below `tolerance` relative to the parameter's size
// (absolute near zero).
bool StepIsSmall(const Eigen::VectorXd& step, const Eigen::VectorXd& x, double tolerance) {
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    if (std::abs(step[j]) > tolerance * (std::abs(x[j]) + tolerance)) return false;
  }
  return true;
}

// The step of the damped problem min |J d + r|^2 + lambda |D d|^2 on the `free` parameters
// (lambda = 0: Gauss-Newton's), kept in the box: a parameter whose step would cross its
// bound is put on it and the rest solved again with it there, until none crosses. Solved
// as a least-squares problem (QR, no normal equations, so that a nearly dependent pair of
// columns does not square its conditioning).
Eigen::VectorXd ProjectedStep(const Eigen::MatrixXd& jr, const Eigen::VectorXd& r,
                              const Eigen::VectorXd& x, std::vector<Eigen::Index> free,
                              double lambda, const Eigen::VectorXd& scaling,
                              const BoundedLeastSquaresProblem& problem) {
  const Eigen::Index n = r.size();
  Eigen::VectorXd step = Eigen::VectorXd::Zero(x.size());
  while (!free.empty()) {
    const Eigen::Index f = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + f, f);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + f);
    rhs.head(n) = -(r + jr * step);  // the clamped parameters' steps already taken
    for (Eigen::Index k = 0; k < f; ++k) {
      const Eigen::Index j = free[static_cast<std::size_t>(k)];
      augmented.col(k).head(n) = jr.col(j);
      // a column zero so far: any positive damping keeps its step at zero
      augmented(n + k, k) = std::sqrt(lambda) * (scaling[j] > 0.0 ? scaling[j] : 1.0);
    }
    const Eigen::VectorXd free_step = augmented.colPivHouseholderQr().solve(rhs);
    std::vector<Eigen::Index> still_free;
    for (Eigen::Index k = 0; k < f; ++k) {
      const Eigen::Index j = free[static_cast<std::size_t>(k)];
      const double target = x[j] + free_step[k];
      if (target < problem.lower[j] || target > problem.upper[j]) {
        step[j] = std::clamp(target, problem.lower[j], problem.upper[j]) - x[j];
      } else {
        still_free.push_back(j);
      }
    }
    if (still_free.size() == free.size()) {
      for (Eigen::Index k = 0; k < f; ++k) step[free[static_cast<std::size_t>(k)]] = free_step[k];
      break;
    }
    free = std::move(still_free);
  }
  return step;
}

// The iterate: the parameters, the model there, its weighted residual, their Jacobian and
// the cost |r|^2.
struct Iterate {
  Eigen::VectorXd x;
  ModelPoint point;
  Eigen::VectorXd r;
  Eigen::MatrixXd jr;
  double cost = 0.0;
};

// Marquardt's lambda and Nielsen's nu, by which a rejected step raises it.
struct Damping {
  double lambda = kInitialDamping;
  double growth = 2.0;
};

// Why the iteration ends.
struct Stop {
  bool converged = false;
  std::string reason;
};

void CheckProblem(const BoundedLeastSquaresProblem& problem) {
  const Eigen::Index n = problem.data.size(), p = problem.start.size();
  if (problem.weights.size() != n || problem.lower.size() != p || problem.upper.size() != p) {
    throw std::invalid_argument("identify: data, weights and bounds of different sizes");
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    if (!(problem.lower[j] <= problem.start[j] && problem.start[j] <= problem.upper[j])) {
      throw std::invalid_argument("identify: parameter " + std::to_string(j) +
                                  " starts outside its bounds");
    }
  }
}

// Free parameters: not on a bound that the descent direction (-gradient) points through.
std::vector<Eigen::Index> FreeParameters(const BoundedLeastSquaresProblem& problem,
                                         const Eigen::VectorXd& x,
                                         const Eigen::VectorXd& gradient) {
  std::vector<Eigen::Index> free;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const bool held = (x[j] <= problem.lower[j] && gradient[j] > 0.0) ||
                      (x[j] >= problem.upper[j] && gradient[j] < 0.0);
    if (!held) free.push_back(j);
  }
  return free;
}

// The largest cosine between a free column and the residual: near 0 where stationary.
double WorstCosine(const Iterate& it, const Eigen::VectorXd& gradient,
                   const std::vector<Eigen::Index>& free) {
  double worst_cosine = 0.0;
  const double r_norm = it.r.norm();
  for (Eigen::Index j : free) {
    const double column = it.jr.col(j).norm();
    if (column > 0.0) {
      worst_cosine = std::max(worst_cosine, std::abs(gradient[j]) / (column * r_norm));
    }
  }
  return worst_cosine;
}

// The tests at the iterate, before any step: an exact fit, a stationary point, the budget
// spent. Fills `free` with the parameters a step may move.
std::optional<Stop> StopAtIterate(const BoundedLeastSquaresProblem& problem,
                                  const LeastSquaresOptions& options, const Iterate& it,
                                  int evaluations, std::vector<Eigen::Index>& free) {
  if (it.cost == 0.0) return Stop{true, "the model reproduces the data exactly"};
  const Eigen::VectorXd gradient = it.jr.transpose() * it.r;
  free = FreeParameters(problem, it.x, gradient);
  if (free.empty() || WorstCosine(it, gradient, free) <= options.gradient_tolerance) {
    return Stop{true, "the residual is orthogonal to every parameter's column"};
  }
  if (evaluations >= options.max_evaluations) {
    return Stop{false, "the budget of " + std::to_string(options.max_evaluations) +
                           " model evaluations ran out before a tolerance was met"};
  }
  return std::nullopt;
}

// Converged when even the undamped (Gauss-Newton) step is negligible, in size or in what it
// would gain.
std::optional<Stop> StopAtGaussNewtonStep(const BoundedLeastSquaresProblem& problem,
                                          const LeastSquaresOptions& options, const Iterate& it,
                                          const std::vector<Eigen::Index>& free,
                                          const Eigen::VectorXd& scaling) {
  const Eigen::VectorXd full_step = ProjectedStep(it.jr, it.r, it.x, free, 0.0, scaling, problem);
  if (StepIsSmall(full_step, it.x, options.step_tolerance)) {
    return Stop{true, "the Gauss-Newton step fell below the step tolerance"};
  }
  if (it.cost - (it.r + it.jr * full_step).squaredNorm() <=
      options.improvement_tolerance * it.cost) {
    return Stop{true,
                "the Gauss-Newton step would lower the cost by less than the "
                "improvement tolerance"};
  }
  return std::nullopt;
}

// The model at a trial point (its Jacobian left for when the point is accepted), or nothing
// when the model cannot be run there: the step is then rejected, and a shorter one may stay
// where the model runs.
std::optional<Iterate> TrialIterate(const BoundedLeastSquaresProblem& problem,
                                    const Eigen::VectorXd& trial, int& evaluations) {
  try {
    ModelPoint point = problem.model(trial);
    ++evaluations;
    CheckShape(point, problem.data.size(), problem.start.size());
    Iterate it;
    it.x = trial;
    it.r = WeightedResidual(problem, point);
    it.cost = it.r.squaredNorm();
    it.point = std::move(point);
    return it;
  } catch (const EvaluationFailure&) {
    ++evaluations;
  } catch (const InputError&) {
    ++evaluations;
  } catch (const ParameterError&) {
    ++evaluations;
  }
  return std::nullopt;
}

// One damped step: taken when the model at its end lowers the cost (the damping eased by
// the gain against the prediction), else the damping raised. A stop when the step shows the
// minimum reached.
std::optional<Stop> DampedStep(const BoundedLeastSquaresProblem& problem,
                               const LeastSquaresOptions& options,
                               const std::vector<Eigen::Index>& free,
                               const Eigen::VectorXd& scaling, Iterate& it, Damping& damping,
                               LeastSquaresResult& result) {
  const Eigen::VectorXd step =
      ProjectedStep(it.jr, it.r, it.x, free, damping.lambda, scaling, problem);
  const double predicted = it.cost - (it.r + it.jr * step).squaredNorm();
  const Eigen::VectorXd trial = (it.x + step).cwiseMax(problem.lower).cwiseMin(problem.upper);
  std::optional<Iterate> next = TrialIterate(problem, trial, result.evaluations);
  const double actual = next ? it.cost - next->cost : 0.0;
  if (next && std::isfinite(next->cost) && actual > 0.0 && predicted > 0.0) {
    const double rho = actual / predicted;
    damping.lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
    damping.growth = 2.0;
    const double before = it.cost;
    it = std::move(*next);
    it.jr = ResidualJacobian(problem, it.point);
    ++result.iterations;
    const double negligible = options.cost_tolerance * before;
    if (actual <= negligible && predicted <= negligible) {
      return Stop{true, "the cost fell by less than the cost tolerance"};
    }
  } else if (StepIsSmall(step, it.x, options.step_tolerance) ||
             predicted <= options.improvement_tolerance * it.cost) {
    // the damping has shrunk the step to nothing (or to a gain the improvement tolerance
    // calls none) and still the cost does not fall: the minimum, to the model's numerical
    // precision
    return Stop{true, "no step lowers the cost further (the model's numerical precision)"};
  } else {
    damping.lambda *= damping.growth;
    damping.growth *= 2.0;
  }
  return std::nullopt;
}

}  // namespace

LeastSquaresResult SolveBoundedLeastSquares(const BoundedLeastSquaresProblem& problem,
                                            const LeastSquaresOptions& options) {
  CheckProblem(problem);
  LeastSquaresResult result;
  Iterate it;
  it.x = problem.start;
  it.point = problem.model(it.x);  // a failure here is the caller's to report
  result.evaluations = 1;
  CheckShape(it.point, problem.data.size(), problem.start.size());
  it.r = WeightedResidual(problem, it.point);
  it.jr = ResidualJacobian(problem, it.point);
  it.cost = it.r.squaredNorm();
  Eigen::VectorXd scaling = it.jr.colwise().norm().transpose();  // Moré's D: the largest seen
  Damping damping;

  std::optional<Stop> stop;
  while (!stop) {
    std::vector<Eigen::Index> free;
    stop = StopAtIterate(problem, options, it, result.evaluations, free);
    if (stop) break;
    scaling = scaling.cwiseMax(it.jr.colwise().norm().transpose());
    stop = StopAtGaussNewtonStep(problem, options, it, free, scaling);
    if (!stop) stop = DampedStep(problem, options, free, scaling, it, damping, result);
  }

  result.converged = stop->converged;
  result.stop_reason = stop->reason;
  result.parameters = it.x;
  result.cost = it.cost;
  const Eigen::Index p = problem.start.size();
  result.at_bound.resize(static_cast<std::size_t>(p));
  for (Eigen::Index j = 0; j < p; ++j) {
    result.at_bound[static_cast<std::size_t>(j)] =
        it.x[j] <= problem.lower[j] || it.x[j] >= problem.upper[j];
  }
  result.at_solution = std::move(it.point);
  return result;
}

}  // namespace musclesim
