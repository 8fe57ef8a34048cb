#include "musclesim/core/bounded_least_squares.h"

#include <algorithm>
#include <cmath>

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
                           std::to_string(n) + " values and " + std::to_string(p) +
                           " parameters");
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

}  // namespace

LeastSquaresResult SolveBoundedLeastSquares(const BoundedLeastSquaresProblem& problem,
                                            const LeastSquaresOptions& options) {
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

  LeastSquaresResult result;
  Eigen::VectorXd x = problem.start;
  ModelPoint point = problem.model(x);  // a failure here is the caller's to report
  result.evaluations = 1;
  CheckShape(point, n, p);
  Eigen::VectorXd r = WeightedResidual(problem, point);
  Eigen::MatrixXd jr = ResidualJacobian(problem, point);
  double cost = r.squaredNorm();
  Eigen::VectorXd scaling = jr.colwise().norm().transpose();  // Moré's D: the largest seen
  double lambda = kInitialDamping;
  double growth = 2.0;  // Nielsen's nu

  while (true) {
    if (cost == 0.0) {
      result.converged = true;
      result.stop_reason = "the model reproduces the data exactly";
      break;
    }
    // free parameters: not on a bound that the descent direction (-gradient) points through
    const Eigen::VectorXd gradient = jr.transpose() * r;
    std::vector<Eigen::Index> free;
    for (Eigen::Index j = 0; j < p; ++j) {
      const bool held = (x[j] <= problem.lower[j] && gradient[j] > 0.0) ||
                        (x[j] >= problem.upper[j] && gradient[j] < 0.0);
      if (!held) free.push_back(j);
    }
    // stationary: every free column (nearly) orthogonal to the residual
    double worst_cosine = 0.0;
    const double r_norm = r.norm();
    for (Eigen::Index j : free) {
      const double column = jr.col(j).norm();
      if (column > 0.0) {
        worst_cosine = std::max(worst_cosine, std::abs(gradient[j]) / (column * r_norm));
      }
    }
    if (free.empty() || worst_cosine <= options.gradient_tolerance) {
      result.converged = true;
      result.stop_reason = "the residual is orthogonal to every parameter's column";
      break;
    }
    if (result.evaluations >= options.max_evaluations) {
      result.stop_reason = "the budget of " + std::to_string(options.max_evaluations) +
                           " model evaluations ran out before a tolerance was met";
      break;
    }

    scaling = scaling.cwiseMax(jr.colwise().norm().transpose());
    // converged when even the undamped (Gauss-Newton) step is negligible, in size or in
    // what it would gain
    const Eigen::VectorXd full_step = ProjectedStep(jr, r, x, free, 0.0, scaling, problem);
    if (StepIsSmall(full_step, x, options.step_tolerance)) {
      result.converged = true;
      result.stop_reason = "the Gauss-Newton step fell below the step tolerance";
      break;
    }
    if (cost - (r + jr * full_step).squaredNorm() <= options.improvement_tolerance * cost) {
      result.converged = true;
      result.stop_reason = "the Gauss-Newton step would lower the cost by less than the "
                           "improvement tolerance";
      break;
    }
    const Eigen::VectorXd step = ProjectedStep(jr, r, x, free, lambda, scaling, problem);
    const double predicted = cost - (r + jr * step).squaredNorm();
    const Eigen::VectorXd trial = (x + step).cwiseMax(problem.lower).cwiseMin(problem.upper);

    bool accepted = false;
    double actual = 0.0;
    try {
      ModelPoint trial_point = problem.model(trial);
      ++result.evaluations;
      CheckShape(trial_point, n, p);
      const Eigen::VectorXd trial_r = WeightedResidual(problem, trial_point);
      const double trial_cost = trial_r.squaredNorm();
      actual = cost - trial_cost;
      if (std::isfinite(trial_cost) && actual > 0.0 && predicted > 0.0) {
        accepted = true;
        const double rho = actual / predicted;
        lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
        growth = 2.0;
        x = trial;
        point = std::move(trial_point);
        r = trial_r;
        jr = ResidualJacobian(problem, point);
        ++result.iterations;
      }
    } catch (const EvaluationFailure&) {
      ++result.evaluations;  // rejected: a shorter step may stay where the model runs
    } catch (const InputError&) {
      ++result.evaluations;
    } catch (const ParameterError&) {
      ++result.evaluations;
    }
    if (accepted) {
      const double before = cost;
      cost = r.squaredNorm();
      const double negligible = options.cost_tolerance * before;
      if (actual <= negligible && predicted <= negligible) {
        result.converged = true;
        result.stop_reason = "the cost fell by less than the cost tolerance";
        break;
      }
    } else if (StepIsSmall(step, x, options.step_tolerance) ||
               predicted <= options.improvement_tolerance * cost) {
      // the damping has shrunk the step to nothing (or to a gain the improvement tolerance
      // calls none) and still the cost does not fall: the minimum, to the model's numerical
      // precision
      result.converged = true;
      result.stop_reason = "no step lowers the cost further (the model's numerical precision)";
      break;
    } else {
      lambda *= growth;
      growth *= 2.0;
    }
  }

  result.parameters = x;
  result.cost = cost;
  result.at_bound.resize(static_cast<std::size_t>(p));
  for (Eigen::Index j = 0; j < p; ++j) {
    result.at_bound[static_cast<std::size_t>(j)] =
        x[j] <= problem.lower[j] || x[j] >= problem.upper[j];
  }
  result.at_solution = std::move(point);
  return result;
}

}  // namespace musclesim
