// Optimal control (docs/model.md 13): the activations, piecewise linear on a time grid, with
// free parameters and a free final time, that meet final values and path bounds at the least
// weighted sum of effort, tracking, terminal and final-time terms. Solved by direct multiple
// shooting (optimize/multiple_shooting.h) with IPOPT.
#pragma once

#include <functional>
#include <limits>
#include <optional>
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

// The columns the terms below name are a run's differentiated columns (those of
// scenario/sensitivity_run.h): a free node's "mass.position", "mass.velocity" on a line and
// "mass.x", "mass.vy", ... in the plane or in space; "ELEMENT.length", "ELEMENT.tension",
// "ACTUATOR.tension_active", ...; a single actuator's "length", "shortening_velocity",
// "tension_total", ....

// A bound on a column's value at the final time. Equal bounds fix it.
struct FinalValue {
  std::string column;
  double lower = 0.0;
  double upper = 0.0;
};

// A bound on a column's value at every grid point after the start.
struct PathBound {
  std::string column;
  double lower = -1e20;  // -/+1e20: no bound on that side
  double upper = 1e20;
};

// w * integral over the span of (column(t) - r(t))^2, r linear between the reference's
// points, which must cover the span (a fixed final time).
struct TrackingTerm {
  std::string column;
  std::vector<TablePoint> reference;  // (t [s], r), times strictly increasing
  double weight = 1.0;                // >= 0
};

// w * (column(t_end) - target)^2.
struct TerminalTerm {
  std::string column;
  double target = 0.0;
  double weight = 1.0;  // >= 0
};

// A number of the scenario the optimiser chooses with the controls (a stiffness, a rest
// length, f_iso): its key path (scenario/parameter.h), bounds, and its start, the
// scenario's own value clamped to them.
struct FreeParameter {
  std::string path;
  double lower = -1e20;
  double upper = 1e20;
};

// The final time as a variable within [lower, upper] (the span's end t_end is then its
// start), with weight * t_end in the objective (minimum time).
struct FreeFinalTime {
  double lower = 0.0, upper = 0.0;  // [s], t_start < lower <= upper
  double weight = 0.0;              // >= 0
};

struct OptimalControlProblem {
  Scenario scenario;   // the network, its initial state, its span [t_start, t_end], its solver
  int intervals = 20;  // N: the grid has N + 1 points, evenly spaced over the span
  std::vector<ControlSpec> controls;
  std::vector<FinalValue> final_values;
  std::vector<PathBound> path_bounds;
  std::vector<TrackingTerm> tracking;
  std::vector<TerminalTerm> terminal;
  std::vector<FreeParameter> parameters;
  std::optional<FreeFinalTime> final_time;
};

// IPOPT's progress after each iteration.
struct OptimizeProgress {
  int iteration = 0;
  double objective = 0.0;
  double infeasibility = 0.0;  // IPOPT's inf_pr: the largest constraint violation
  double dual_infeasibility = 0.0;
};

// How the shooting program's first derivatives are computed: CVODES forward sensitivities
// (exact), or forward difference quotients of the intervals' plain integrations, one
// evaluation of every interval per colour of variables that move no interval twice (for
// comparison: docs/performance.md).
enum class ShootingDerivatives { kSensitivities, kDifferenceQuotients };

struct OptimizeOptions {
  double tolerance = 1e-9;   // IPOPT's tol: of the scaled optimality error
  int max_iterations = 500;  // IPOPT's max_iter
  int print_level = 0;       // IPOPT's print_level, 0 (silent) to 12
  ShootingDerivatives derivatives = ShootingDerivatives::kSensitivities;
  // [s] of wall time the solve may take, checked after each iteration (status
  // maximum_seconds_exceeded, the point reached kept); infinite: no limit.
  double max_seconds = std::numeric_limits<double>::infinity();
  // Called after each iteration; returning false stops IPOPT there (status
  // user_requested_stop, the point reached kept).
  std::function<bool(const OptimizeProgress&)> progress;
};

// The most points a tracking reference may hold: each cuts the cost's quadrature, so an
// iteration's work grows with them (100,000: about 2 s per iteration on one core).
inline constexpr std::size_t kMaxReferencePoints = 100000;

// An infeasible problem (a move the muscles cannot make) is seldom declared so by IPOPT's
// limited-memory iterations: they hover at the least violation the controls can reach,
// trading it against the objective. When over kStallIterations iterations neither the least
// constraint violation has fallen by kStallReduction nor the least objective by 0.1
// kStallReduction (1 %) below their least over the kStallIterations before, the violation
// above kStallViolation, the solve stops with status infeasibility_stalled.
inline constexpr int kStallIterations = 30;
inline constexpr double kStallReduction = 0.1;   // a tenth of its value
inline constexpr double kStallViolation = 1e-6;  // [the constraints' units]

// The objective's terms at the optimum, each with its weight in it.
struct ObjectiveTerms {
  double effort = 0.0, tracking = 0.0, terminal = 0.0, final_time = 0.0;
};

struct OptimalControlResult {
  std::string status;                 // IPOPT's, as its name ("success", ...)
  bool solved = false;                // IPOPT reached its tolerance
  double objective = 0.0;             // the objective at the point returned
  ObjectiveTerms terms;               // its parts
  double constraint_violation = 0.0;  // its largest constraint violation
  // That constraint, named ("final_values[0] load.position (at t = 1 s): 0.14 where [0.3,
  // 0.3] is asked"); empty when no constraint is violated.
  std::string largest_violation;
  // IPOPT declared the problem locally infeasible (infeasible_problem_detected), its
  // restoration failed, or the violation stalled (infeasibility_stalled).
  bool infeasible = false;
  double dual_infeasibility = 0.0;  // IPOPT's, unscaled, at the last iteration
  int iterations = 0;
  double wall_seconds = 0.0;         // [s] of the solve, the checks after it included
  double integration_seconds = 0.0;  // [s] of it spent integrating the intervals
  // The gradient check at the point returned: the objective's derivative along a random
  // direction by central differences against the gradient's, relative difference.
  double gradient_check = 0.0;
  // One run of `scenario` over the whole span against the shooting states: the largest
  // |y(t_i) - s_i| over the grid's points and the state's components (as Moco reports it).
  double resimulation_deviation = 0.0;
  std::vector<double> times;                  // the grid's points [s]
  std::vector<double> states;                 // the shooting states s_0 .. s_N, row-major
  int state_size = 0;                         // n: the entries per grid point in `states`
  std::vector<std::vector<double>> controls;  // per control, its values at the grid's points
  std::vector<double> parameter_values;       // per free parameter
  double final_time = 0.0;                    // [s]: t_N
  // The problem's scenario with each control's activation as its table, the free parameters
  // at their values and the span's end at the final time.
  Scenario scenario;
};

// Solves `problem` (InputError for a control or column the scenario does not have, a bound
// out of range, or fewer than 1 interval). IPOPT's failure to converge is no exception: the
// result carries its status and the best point it reached.
OptimalControlResult SolveOptimalControl(const OptimalControlProblem& problem,
                                         const OptimizeOptions& options = {});

}  // namespace musclesim
