// Direct multiple shooting of an optimal control problem (docs/model.md 13.2), as a nonlinear
// program: variables x = (U, s_1 .. s_(N-1)), the controls' values at the grid's points, then
// the state at each inner grid point; constraints g = (Phi_i - s_(i+1), i < N - 1; the final
// values of Phi_(N-1)), Phi_i the state at t_(i+1) integrated from s_i over interval i. Each
// interval's derivatives come from CVODES forward sensitivities in s_i and in the interval's
// two control values, so the gradient and the constraint Jacobian are exact.
#pragma once

#include <memory>
#include <vector>

#include "musclesim/optimize/optimal_control.h"

namespace musclesim {

class MultipleShooting {
 public:
  // Checks the problem (InputError) and prepares its intervals.
  explicit MultipleShooting(const OptimalControlProblem& problem);
  ~MultipleShooting();
  MultipleShooting(const MultipleShooting&) = delete;
  MultipleShooting& operator=(const MultipleShooting&) = delete;

  int variable_count() const;
  int constraint_count() const;
  // Bounds of the variables and the constraints (-/+ infinity as -/+1e20).
  void VariableBounds(double* lower, double* upper) const;
  void ConstraintBounds(double* lower, double* upper) const;
  // The scenario's own activations at the grid's points (clamped to the bounds) and the
  // states a single run with them passes through.
  std::vector<double> StartingPoint();

  // The effort J(x) and its gradient (closed forms of the piecewise-linear controls).
  double Objective(const double* x) const;
  void ObjectiveGradient(const double* x, double* gradient) const;
  // g(x) and its Jacobian's nonzeros, in the order of JacobianStructure. False when an
  // interval's integration fails (the point is then unusable).
  bool Constraints(const double* x, double* g);
  bool ConstraintJacobian(const double* x, double* values);
  void JacobianStructure(int* rows, int* columns) const;
  int jacobian_nonzeros() const;

  // The grid's times, and control j's values in x.
  const std::vector<double>& times() const;
  std::vector<double> ControlValues(const double* x, int j) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace musclesim
