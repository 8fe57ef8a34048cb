// One simulation of the actuator/load dynamics on SUNDIALS CVODE.
//
// A Simulation owns its SUNContext, CVODE memory, vector, matrix and linear solver (RAII)
// and shares nothing writable, so many may run on many threads. Running it again re-uses
// the CVODE memory through CVodeReInit. Every breakpoint of the inputs is a CVODE stop
// time, followed by a re-initialisation, so no step straddles a jump. Root functions stop
// the run at the user's length limits and at zero length, and restart the integrator where
// the length crosses the passive slack length (where dT_p/dx jumps).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/dynamics/actuator.h"

namespace musclesim {

enum class IntegrationMethod { kBdf, kAdams };
std::string_view ToString(IntegrationMethod method);
IntegrationMethod ParseIntegrationMethod(std::string_view text);  // ParameterError("method")

enum class JacobianKind { kAnalytic, kDifferenceQuotient };
std::string_view ToString(JacobianKind kind);
JacobianKind ParseJacobianKind(std::string_view text);  // ParameterError("jacobian")

struct SolverOptions {
  IntegrationMethod method = IntegrationMethod::kBdf;
  double rtol = 1e-6;            // relative tolerance, > 0
  double atol = 1e-9;            // absolute tolerance on x [m] and xdot [m/s], > 0
  JacobianKind jacobian = JacobianKind::kAnalytic;
  double max_step = 0.0;         // largest internal step [s], >= 0; 0: no limit
  long max_steps = 10000000;     // internal steps allowed in one run, >= 1 (a guard)
};

// Throws ParameterError ("method", "rtol", "atol", "max_step", "max_steps").
void Validate(const SolverOptions& options);

struct RunRequest {
  double t_start = 0.0;
  double t_end = 1.0;                 // > t_start
  double length = 0.1;                // x(t_start) [m], > 0
  double lengthening_rate = 0.0;      // xdot(t_start) [m/s]
  double output_interval = 1e-3;      // [s]; 0 records every internal step instead
  std::optional<double> min_length;   // reaching it ends the run, status limit
  std::optional<double> max_length;
};

enum class RunStatus { kCompleted, kLimit, kFailed };
std::string_view ToString(RunStatus status);

// Solver counters summed over the whole run (CVODE resets its own at each re-init).
struct RunStats {
  long steps = 0;
  long rhs_evals = 0;          // including those of a difference-quotient Jacobian
  long jac_evals = 0;
  long linear_setups = 0;
  long newton_iters = 0;
  long newton_conv_fails = 0;
  long error_test_fails = 0;
  double wall_seconds = 0.0;
  double final_time = 0.0;
  RunStatus status = RunStatus::kCompleted;
  std::string message;         // why a run ended early (limit or failure)
};

struct TrajectoryPoint {
  double t;
  ActuatorSample sample;
};

class Simulation {
 public:
  Simulation();
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Integrates `system` as `request` says, appending the recorded points to `trajectory`
  // (cleared first). A solver failure does not throw: it returns status kFailed with
  // CVODE's flag name and the time reached in `message`, the points so far kept.
  RunStats Run(const ActuatorSystem& system, const SolverOptions& options,
               const RunRequest& request, std::vector<TrajectoryPoint>& trajectory);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace musclesim
