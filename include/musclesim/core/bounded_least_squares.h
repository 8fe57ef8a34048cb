// Private: the weighted least-squares fit behind `musclesim identify` on time series, a
// Levenberg-Marquardt iteration kept inside box bounds by projection.
//
// Our own rather than Eigen's unsupported LevenbergMarquardt: each evaluation of the model is
// a whole simulation that yields the predictions and their Jacobian together (Eigen's module
// asks for them in separate calls), a failed simulation must reject a step rather than end
// the fit, and bounds enter as a projection onto the box, which keeps the parameters
// themselves (not a transformation of them) in the Jacobian that the standard errors and the
// identifiability analysis read.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace musclesim {

// The model at one parameter vector: its predictions of the measured values and their
// derivatives d prediction_i / d parameter_j.
struct ModelPoint {
  Eigen::VectorXd predictions;  // N, in the measured values' units
  Eigen::MatrixXd jacobian;     // N x P
};

// Thrown by a model that cannot be evaluated at a trial point (a solver failure, a value
// outside the model's rules): the iteration rejects that step and tries a shorter one. The
// model's own InputError and ParameterError are treated alike at trial points; at the start
// every exception propagates.
class EvaluationFailure : public std::runtime_error {
 public:
  explicit EvaluationFailure(const std::string& message) : std::runtime_error(message) {}
};

using ModelFunction = std::function<ModelPoint(const Eigen::VectorXd& parameters)>;

// Minimise sum_i (weight_i (data_i - prediction_i(p)))^2 over lower <= p <= upper.
struct BoundedLeastSquaresProblem {
  ModelFunction model;
  Eigen::VectorXd data;     // N measured values
  Eigen::VectorXd weights;  // N, 1 / (the value's noise standard deviation), or 1
  Eigen::VectorXd start;    // P, within the bounds
  Eigen::VectorXd lower;    // P, -infinity for none
  Eigen::VectorXd upper;    // P, +infinity for none
};

struct LeastSquaresOptions {
  int max_evaluations = 200;          // model evaluations [-], each a simulation
  double step_tolerance = 1e-10;      // stop when a step moves every parameter by less than
                                      // this fraction of its magnitude [-]
  double gradient_tolerance = 1e-12;  // stop when every residual column is this close to
                                      // orthogonal to the residual (cosine) [-]
  double cost_tolerance = 1e-14;      // stop when a step lowers the cost by less than this
                                      // fraction, and the model predicted no more [-]
  // stop when even the Gauss-Newton step would lower the cost by less than this fraction
  // (or a rejected step was predicted to): with noisy data the cost is about the number of
  // values N and a step of k standard errors lowers it by about k^2, so this is a step of
  // about 1e-4 sqrt(N) (2e-3 for 250 values) standard errors, far below what matters, and
  // above the numerical noise of the runs' cost, which would otherwise keep it going [-]
  double improvement_tolerance = 1e-8;
};

struct LeastSquaresResult {
  Eigen::VectorXd parameters;  // P, the last accepted point
  ModelPoint at_solution;      // the model there
  double cost = 0.0;           // sum of squared weighted residuals there
  int iterations = 0;          // accepted steps
  int evaluations = 0;         // model evaluations, the start included
  bool converged = false;      // a tolerance met (false: the evaluation budget ran out)
  std::string stop_reason;     // which, in words
  std::vector<bool> at_bound;  // P: held at a bound that the gradient pushes against
};

// Runs the iteration from problem.start. Each step solves the damped problem
// min |J d + r|^2 + lambda |D d|^2 (D: the largest column norms of J seen so far, Moré's
// scaling, so that parameters of very different sizes are treated alike) on the parameters
// not held at a bound (one the gradient pushes against); a parameter whose step would cross
// its bound is put on it and the others solved again, and the trial point is accepted when
// the cost falls (lambda by Nielsen's rule, from 1e-2). It stops when the Gauss-Newton step is
// below the step tolerance, the cost falls by less than the cost tolerance, the residual is
// orthogonal to every free column, a step shrunk below the step tolerance (or predicted to
// gain less than the improvement tolerance) still does not lower the cost (the model's
// numerical precision), or the evaluations run out. A parameter
// whose column is zero stays at its start. Throws whatever the model throws at the start;
// std::invalid_argument for inconsistent sizes or a start outside the bounds.
LeastSquaresResult SolveBoundedLeastSquares(const BoundedLeastSquaresProblem& problem,
                                            const LeastSquaresOptions& options = {});

}  // namespace musclesim
