// Optimal control (docs/model.md 13): the activations, piecewise linear on a time grid, that
// move a scenario's network to chosen final values with the least effort. Solved by direct
// multiple shooting (optimize/multiple_shooting.h) with IPOPT.
#pragma once

#include <string>
#include <vector>

#include "musclesim/scenario/scenario.h"

namespace musclesim {

// One control: an actuator's activation u(t), linear between the grid's points, whose values
// there are the optimisation's variables.
struct ControlSpec {
  std::string actuator;  // an actuator element of the scenario, without activation dynamics
  double lower = 0.0;    // bounds on u at every grid point, 0 <= lower <= upper <= 1
  double upper = 1.0;
  double effort_weight = 1.0;  // w in w * integral of u^q dt, >= 0
  int effort_power = 2;        // q: 2 or 3
};

// A bound on an output column's value at the final time: a free node's coordinate or
// velocity ("mass.position", "mass.velocity" on a line; "mass.x", "mass.vy", ... in the
// plane or in space). Equal bounds fix it.
struct FinalValue {
  std::string column;
  double lower = 0.0;
  double upper = 0.0;
};

struct OptimalControlProblem {
  Scenario scenario;   // the network, its initial state, its span [t_start, t_end], its solver
  int intervals = 20;  // N: the grid has N + 1 points, evenly spaced over the span
  std::vector<ControlSpec> controls;
  std::vector<FinalValue> final_values;
};

struct OptimizeOptions {
  double tolerance = 1e-9;   // IPOPT's tol: of the scaled optimality error
  int max_iterations = 500;  // IPOPT's max_iter
  int print_level = 0;       // IPOPT's print_level, 0 (silent) to 12
};

struct OptimalControlResult {
  std::string status;                 // IPOPT's, as its name ("success", ...)
  bool solved = false;                // IPOPT reached its tolerance
  double objective = 0.0;             // the effort at the best point
  double constraint_violation = 0.0;  // its largest constraint violation
  int iterations = 0;
  std::vector<double> times;                  // the grid's points [s]
  std::vector<std::vector<double>> controls;  // per control, its values at the grid's points
  Scenario scenario;  // the problem's scenario with each control's activation as its table
};

// Solves `problem` (InputError for a control or column the scenario does not have, a bound
// out of range, or fewer than 1 interval). IPOPT's failure to converge is no exception: the
// result carries its status and the best point it reached.
OptimalControlResult SolveOptimalControl(const OptimalControlProblem& problem,
                                         const OptimizeOptions& options = {});

}  // namespace musclesim
