// Direct multiple shooting of an optimal control problem (docs/model.md 13.2), as a nonlinear
// program: variables x = (U, s_1 .. s_(N-1), p, T), the controls' values at the grid's points,
// the state at each inner grid point, the free parameters and (when free) the final time;
// constraints g = (Phi_i - s_(i+1), i < N - 1; the final values at Phi_(N-1); the path bounds
// at every Phi_i), Phi_i the state at t_(i+1) integrated from s_i over interval i. Each
// interval's derivatives come from CVODES forward sensitivities in s_i, in the interval's two
// control values and in the free parameters; those in T from the interval's ends moving
// (docs/model.md 13.2), so the gradient and the constraint Jacobian are exact.
#pragma once

#include <memory>
#include <vector>

#include "musclesim/optimize/optimal_control.h"

namespace musclesim {

class MultipleShooting {
 public:
  // Checks the problem (InputError) and prepares its intervals.
  explicit MultipleShooting(const OptimalControlProblem& problem,
                            ShootingDerivatives derivatives = ShootingDerivatives::kSensitivities);
  ~MultipleShooting();
  MultipleShooting(const MultipleShooting&) = delete;
  MultipleShooting& operator=(const MultipleShooting&) = delete;

  int variable_count() const;
  int constraint_count() const;
  // Bounds of the variables and the constraints (-/+ infinity as -/+1e20).
  void VariableBounds(double* lower, double* upper) const;
  void ConstraintBounds(double* lower, double* upper) const;
  // Constraint `row` named for messages: "continuity of state 1 at t = 0.05 s",
  // "final_values[0] load.position", "path_bounds[1] flexor.tension at t = 0.2 s".
  std::string ConstraintName(int row, const double* x) const;
  // The scenario's own activations at the grid's points and its parameters (clamped to the
  // bounds), and the states a single run with them passes through.
  std::vector<double> StartingPoint();

  // The objective J(x), its terms and its gradient. False when an interval's integration
  // fails (the point is then unusable); the effort and the final time need none.
  bool Objective(const double* x, double& value);
  bool Terms(const double* x, ObjectiveTerms& terms);
  bool ObjectiveGradient(const double* x, double* gradient);
  // g(x) and its Jacobian's nonzeros, in the order of JacobianStructure; false as above.
  bool Constraints(const double* x, double* g);
  bool ConstraintJacobian(const double* x, double* values);
  void JacobianStructure(int* rows, int* columns) const;
  int jacobian_nonzeros() const;

  // What x holds: the grid's times (t_N its final time), control j's values on the grid, the
  // free parameters' values, and the state at every grid point, s_0 .. s_N row-major (s_N
  // integrated; empty when an integration fails).
  std::vector<double> Times(const double* x) const;
  std::vector<double> ControlValues(const double* x, int j) const;
  std::vector<double> ParameterValues(const double* x) const;
  std::vector<double> States(const double* x);
  int state_size() const;
  // Wall time spent integrating intervals so far [s].
  double integration_seconds() const;
  // The problem's scenario at x: the controls as tables, the parameters set, t_end = T.
  Scenario ScenarioAt(const double* x) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace musclesim
