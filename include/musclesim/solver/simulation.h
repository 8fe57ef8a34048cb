// One simulation on SUNDIALS CVODE: of a network on a line (docs/model.md section 7), or of
// the single actuator, which is the network of section 7.4.
//
// A Simulation owns its SUNContext, CVODE memory, vector, matrix and linear solver (RAII)
// and shares nothing writable, so many may run on many threads. Running it again re-uses
// the CVODE memory through CVodeReInit. Every breakpoint of the inputs is a CVODE stop
// time, followed by a re-initialisation, so no step straddles a jump. CVODE takes one step
// at a time; the outputs inside a step come from its interpolant. Functions of the state,
// watched by their sign at each step's end and located on the interpolant when it changes
// (docs/solver.md), stop the run at the user's length limits and at zero length, and restart
// the integrator at every kink of NetworkSystem::kinks(): where an element's length crosses a
// passive or tendon slack length (dT/dl jumps), where an actuator with different
// tension-velocity slopes on either side of v = 0 reverses (docs/model.md section 9), and
// where an activation state meets its excitation (section 8).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/dynamics/actuator.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/solver/sensitivity.h"

namespace musclesim {

class CvodeWorkspace;  // src/solver/cvode_workspace.h

enum class IntegrationMethod { kBdf, kAdams };
std::string_view ToString(IntegrationMethod method);
IntegrationMethod ParseIntegrationMethod(std::string_view text);  // ParameterError("method")

enum class JacobianKind { kAnalytic, kDifferenceQuotient };
std::string_view ToString(JacobianKind kind);
JacobianKind ParseJacobianKind(std::string_view text);  // ParameterError("jacobian")

// How the Newton iteration solves its linear systems. `small` is musclesim's lean path for up
// to kSmallSystemMaxSize states: its own fixed-size N_Vector and dense LU (closed form for two
// states), docs/solver.md; dense, band (half-bandwidths from the Jacobian's pattern) and KLU
// sparse are SUNDIALS' own solvers on its serial vector; auto picks by size and structure.
enum class LinearSolverKind { kDense, kBand, kSparse, kAuto, kSmall };
std::string_view ToString(LinearSolverKind kind);
LinearSolverKind ParseLinearSolverKind(std::string_view text);  // ParameterError("linear_solver")

// The largest system the `small` linear solver serves.
inline constexpr int kSmallSystemMaxSize = 16;

// What `auto` picks for a system of `pattern`, whichever the Jacobian: small for a few states,
// band for a narrow band, else sparse (with a difference-quotient Jacobian, a coloured one on
// the sparse structure).
LinearSolverKind ChooseLinearSolver(const JacobianPattern& pattern);

// The smallest relative tolerance double precision can meet (about 100 ulps).
inline constexpr double kMinTolerance = 1e-14;

// How CVODE integrates a run.
struct SolverOptions {
  IntegrationMethod method = IntegrationMethod::kBdf;
  double rtol = 1e-6;  // relative tolerance, in [kMinTolerance, 1)
  double atol = 1e-9;  // absolute tolerance on x [m] and xdot [m/s], in (0, 1)
  JacobianKind jacobian = JacobianKind::kAnalytic;  // of the Newton iteration
  double max_step = 0.0;                            // largest internal step [s], >= 0; 0: no limit
  long max_steps = 10000000;  // internal steps allowed in one run, 1 to 1e12 (a guard)
  LinearSolverKind linear_solver = LinearSolverKind::kAuto;
};

// Throws ParameterError ("rtol", "atol", "max_step", "max_steps") for the first number outside
// its range in the solver block's description (solver_fields.h), with the rule a file's
// reader states. (Defined in solver_fields.cc.)
void Validate(const SolverOptions& options);

// What one run integrates: the time span, the initial state, the output grid, the limits.
struct RunRequest {
  double t_start = 0.0;              // [s], finite
  double t_end = 1.0;                // [s], finite, > t_start
  double length = 0.1;               // x(t_start) [m], finite, > 0
  double lengthening_rate = 0.0;     // xdot(t_start) [m/s], finite
  double output_interval = 1e-3;     // [s], > 0, at most 1e8 rows; 0 records every internal step
  std::optional<double> min_length;  // [m], in [0, length): reaching it ends the run (limit)
  std::optional<double> max_length;  // [m], > length: reaching it ends the run (limit)
};

// Throws ParameterError ("t_end", "length", "output_interval", "min_length", ...).
void Validate(const RunRequest& request);

enum class RunStatus { kCompleted, kLimit, kFailed };
std::string_view ToString(RunStatus status);

// Solver counters summed over the whole run (CVODE resets its own at each re-init).
struct RunStats {
  long steps = 0;      // internal steps taken
  long rhs_evals = 0;  // including those of a difference-quotient Jacobian
  long jac_evals = 0;
  long linear_setups = 0;      // Newton matrix factorisations
  long newton_iters = 0;       // nonlinear (Newton) iterations
  long newton_conv_fails = 0;  // nonlinear convergence failures
  long error_test_fails = 0;   // steps rejected by the local error test
  // with forward sensitivities (staggered corrector): their counters, summed over them all
  int sensitivities = 0;           // parameters
  long sensitivity_rhs_evals = 0;  // calls of the sensitivity right-hand side
  long sensitivity_newton_iters = 0;
  long sensitivity_newton_conv_fails = 0;
  long sensitivity_error_test_fails = 0;
  double wall_seconds = 0.0;  // [s] of wall-clock time for the whole run
  double final_time = 0.0;    // [s], where the run ended
  LinearSolverKind linear_solver = LinearSolverKind::kDense;  // the one used (never auto)
  RunStatus status = RunStatus::kCompleted;
  std::string message;  // why a run ended early (limit or failure)
};

struct TrajectoryPoint {
  double t;               // [s]
  ActuatorSample sample;  // the state and what it observes at t
};

// Receives the points of a run as they are recorded, so that a long run can be written
// out (or reduced to a few numbers) without keeping its trajectory in memory.
class TrajectorySink {
 public:
  virtual ~TrajectorySink() = default;
  virtual void Record(const TrajectoryPoint& point) = 0;
};

// A finished run: its recorded points and its counters.
struct RunResult {
  std::vector<TrajectoryPoint> trajectory;
  RunStats stats;
};

// A network's run: the time span, the output grid, the limits.
struct LengthLimit {
  std::string element;               // the element's name
  std::optional<double> min_length;  // [m], in [0, its initial length): reaching it ends the run
  std::optional<double> max_length;  // [m], above its initial length
};

struct NetworkRunRequest {
  double t_start = 0.0;           // [s], finite
  double t_end = 1.0;             // [s], finite, > t_start
  double output_interval = 1e-3;  // [s], > 0, at most 1e8 rows; 0 records every internal step
  std::vector<LengthLimit> limits;
  std::vector<double> initial_state;  // y(t_start) in NetworkSystem's state order; empty: the
                                      // nodes' own positions and velocities and the
                                      // activations' initial values (NetworkSystem::InitialState)
  std::vector<double> output_times;   // [s] when not empty: the rows' times instead of the
                                      // grid, strictly increasing within [t_start, t_end] (a
                                      // row at t_start only if listed)
};

// Throws ParameterError ("t_end", "output_interval", ...); the limits are checked against
// the system by Simulation::Run ("limits[0].element", "limits[0].min_length").
void Validate(const NetworkRunRequest& request);

// A single actuator's run request as its network's (docs/model.md 7.4): the limits on
// element `actuator`, the initial state (x, xdot) and, with activation dynamics, u.
NetworkRunRequest NetworkRequestOf(const ActuatorSystem& system, const RunRequest& request);

// Receives a network's recorded points as they are produced; `sample` is valid only during
// the call (the simulation re-uses it).
class NetworkSink {
 public:
  virtual ~NetworkSink() = default;
  virtual void Record(double t, const NetworkSample& sample) = 0;
  // A sink that records straight from the state y (the network's state vector) does so here
  // and returns true; the default returns false, and Record gets the observed sample.
  virtual bool RecordState(double /*t*/, const double* /*y*/) { return false; }
};

struct NetworkRunResult {
  std::vector<double> times;           // [s]
  std::vector<NetworkSample> samples;  // one per time
  RunStats stats;
};

class Simulation {
 public:
  Simulation();
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Integrates `system` as `request` says. Validates `options` and `request` first
  // (ParameterError). A solver failure does not throw: it returns status kFailed with
  // CVODE's flag name and the time reached in `message`, the points so far kept.
  RunResult Run(const ActuatorSystem& system, const SolverOptions& options,
                const RunRequest& request);
  // The same, recording into `trajectory` (cleared first), whose memory a caller running
  // many points (a sweep) re-uses.
  RunStats Run(const ActuatorSystem& system, const SolverOptions& options,
               const RunRequest& request, std::vector<TrajectoryPoint>& trajectory);
  // The same, handing every recorded point to `sink` as it is produced (memory does not
  // grow with the run's length). An exception from the sink ends the run and propagates.
  RunStats Run(const ActuatorSystem& system, const SolverOptions& options,
               const RunRequest& request, TrajectorySink& sink);

  // A network, as the above: validates `options` and `request`, the limits and that every
  // element starts longer than zero (ParameterError); a solver failure is status kFailed.
  NetworkRunResult Run(const NetworkSystem& system, const SolverOptions& options,
                       const NetworkRunRequest& request);
  RunStats Run(const NetworkSystem& system, const SolverOptions& options,
               const NetworkRunRequest& request, NetworkSink& sink);

  // With the forward sensitivities of `parameters` (CVODES, staggered corrector, their error
  // controlled): each row goes to `sink` with its sensitivities. The sensitivities carry over
  // every restart unchanged (the inputs' breakpoints must not depend on the parameters).
  RunStats Run(const NetworkSystem& system, const SolverOptions& options,
               const NetworkRunRequest& request,
               const std::vector<SensitivityParameter>& parameters, SensitivitySink& sink);

  // The CVODE memory runs re-use (an IntegrationSession integrates on it); opaque outside
  // the solver's sources.
  CvodeWorkspace& workspace() { return *workspace_; }

 private:
  std::unique_ptr<CvodeWorkspace> workspace_;
};

}  // namespace musclesim
