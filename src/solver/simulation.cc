#include "musclesim/solver/simulation.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "musclesim/errors.h"
#include "musclesim/model/enum_names.h"

namespace musclesim {

constexpr EnumName<IntegrationMethod> kMethodNames[] = {
    {IntegrationMethod::kBdf, "bdf"},
    {IntegrationMethod::kAdams, "adams"},
};

std::string_view ToString(IntegrationMethod method) { return ToString(kMethodNames, method); }

IntegrationMethod ParseIntegrationMethod(std::string_view text) {
  return Parse(kMethodNames, "method", text);
}

constexpr EnumName<JacobianKind> kJacobianNames[] = {
    {JacobianKind::kAnalytic, "analytic"},
    {JacobianKind::kDifferenceQuotient, "difference_quotient"},
};

std::string_view ToString(JacobianKind kind) { return ToString(kJacobianNames, kind); }

JacobianKind ParseJacobianKind(std::string_view text) {
  return Parse(kJacobianNames, "jacobian", text);
}

constexpr EnumName<RunStatus> kStatusNames[] = {
    {RunStatus::kCompleted, "completed"},
    {RunStatus::kLimit, "limit"},
    {RunStatus::kFailed, "failed"},
};

std::string_view ToString(RunStatus status) { return ToString(kStatusNames, status); }

void Validate(const SolverOptions& o) {
  // below ~100 ulps double precision cannot meet a tolerance (CVODE: CV_TOO_MUCH_ACC); at 1
  // or more the error allowed is as large as the value itself
  Require(o.rtol >= kMinTolerance && o.rtol < 1.0, "rtol", o.rtol,
          "must be >= 1e-14 (what double precision can meet) and < 1 (an error as large as "
          "the value)");
  // an absolute error of a metre or a metre per second says nothing about an actuator
  Require(o.atol > 0.0 && o.atol < 1.0, "atol", o.atol,
          "must be > 0 and < 1 [m and m/s]");
  Require(std::isfinite(o.max_step) && o.max_step >= 0.0, "max_step", o.max_step,
          "must be finite and >= 0 (0: no limit) [s]");
  Require(o.max_steps >= 1, "max_steps", static_cast<double>(o.max_steps), "must be >= 1");
}

void Validate(const RunRequest& r) {
  Require(std::isfinite(r.t_start), "t_start", r.t_start, "must be finite [s]");
  Require(std::isfinite(r.t_end) && r.t_end > r.t_start, "t_end", r.t_end,
          "must be finite and greater than t_start = " + FormatNumber(r.t_start) + " [s]");
  Require(std::isfinite(r.length) && r.length > 0.0, "length", r.length,
          "must be finite and > 0 [m]");
  Require(std::isfinite(r.lengthening_rate), "lengthening_rate", r.lengthening_rate,
          "must be finite [m/s]");
  // 0 asks for every internal step; otherwise a positive grid of at most 1e8 rows
  Require(r.output_interval == 0.0 ||
              (std::isfinite(r.output_interval) && r.output_interval > 0.0 &&
               (r.t_end - r.t_start) / r.output_interval <= 1e8),
          "output_interval", r.output_interval,
          "must be > 0 with at most 1e8 rows over the run, or 0 for every step [s]");
  if (r.min_length) {
    Require(std::isfinite(*r.min_length) && *r.min_length >= 0.0 && *r.min_length < r.length,
            "min_length", *r.min_length,
            "must be >= 0 and below the initial length = " + FormatNumber(r.length) + " [m]");
  }
  if (r.max_length) {
    Require(std::isfinite(*r.max_length) && *r.max_length > r.length, "max_length",
            *r.max_length,
            "must be above the initial length = " + FormatNumber(r.length) + " [m]");
  }
}

namespace {

// What the C callbacks see through CVODE's user data.
struct Callbacks {
  const ActuatorSystem* system = nullptr;
  // root functions g_i(x) = x - level_i, in this order of kinds
  enum RootKind { kSlack, kMinLength, kMaxLength, kZeroLength };
  RootKind kinds[4] = {};
  double levels[4] = {};
  int root_count = 0;
  std::string last_error;
};

int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const auto* cb = static_cast<const Callbacks*>(data);
  const double* state = N_VGetArrayPointer(y);
  double* rate = N_VGetArrayPointer(ydot);
  rate[0] = state[1];
  rate[1] = cb->system->Acceleration(t, state[0], state[1]);
  // a non-finite value is a recoverable error: CVODE retries with a smaller step
  return std::isfinite(rate[1]) ? 0 : 1;
}

int AnalyticJacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix jacobian, void* data,
                     N_Vector, N_Vector, N_Vector) {
  const auto* cb = static_cast<const Callbacks*>(data);
  const double* state = N_VGetArrayPointer(y);
  const ActuatorSystem::JacobianRow row = cb->system->Jacobian(t, state[0], state[1]);
  SM_ELEMENT_D(jacobian, 0, 0) = 0.0;
  SM_ELEMENT_D(jacobian, 0, 1) = 1.0;
  SM_ELEMENT_D(jacobian, 1, 0) = row.by_length;
  SM_ELEMENT_D(jacobian, 1, 1) = row.by_rate;
  return 0;
}

int RootFunctions(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
  const auto* cb = static_cast<const Callbacks*>(data);
  const double x = N_VGetArrayPointer(y)[0];
  for (int i = 0; i < cb->root_count; ++i) g[i] = x - cb->levels[i];
  return 0;
}

// Keeps CVODE's error text for the exception message instead of printing it.
void KeepError(int, const char*, const char* function, char* message, void* data) {
  static_cast<Callbacks*>(data)->last_error = std::string(function) + ": " + message;
}

std::string FlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // allocated by SUNDIALS
  std::string text = name != nullptr ? name : std::to_string(flag);
  std::free(name);
  return text;
}

}  // namespace

struct Simulation::Workspace {
  SUNContext context = nullptr;
  N_Vector state = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  void* cvode = nullptr;
  IntegrationMethod method = IntegrationMethod::kBdf;
  Callbacks callbacks;

  Workspace() {
    if (SUNContext_Create(nullptr, &context) != 0) throw std::runtime_error("SUNContext_Create failed");
    state = N_VNew_Serial(2, context);
    // fused vector operations: fewer calls per step, which dominate on a 2-state system
    if (state != nullptr) N_VEnableFusedOps_Serial(state, SUNTRUE);
    matrix = SUNDenseMatrix(2, 2, context);
    solver = SUNLinSol_Dense(state, matrix, context);
    if (state == nullptr || matrix == nullptr || solver == nullptr) {
      Release();
      throw std::runtime_error("allocating the CVODE workspace failed");
    }
  }
  ~Workspace() { Release(); }

  void Release() {
    if (cvode != nullptr) CVodeFree(&cvode);
    if (solver != nullptr) SUNLinSolFree(solver);
    if (matrix != nullptr) SUNMatDestroy(matrix);
    if (state != nullptr) N_VDestroy(state);
    if (context != nullptr) SUNContext_Free(&context);
    cvode = nullptr;
    solver = nullptr;
    matrix = nullptr;
    state = nullptr;
  }

  // Creates the CVODE memory for `m`, or re-initialises the existing one at (t, state).
  void Start(IntegrationMethod m, double t) {
    if (cvode != nullptr && method == m) {
      Check(CVodeReInit(cvode, t, state), "CVodeReInit");
      return;
    }
    if (cvode != nullptr) CVodeFree(&cvode);
    cvode = CVodeCreate(m == IntegrationMethod::kBdf ? CV_BDF : CV_ADAMS, context);
    if (cvode == nullptr) throw std::runtime_error("CVodeCreate failed");
    method = m;
    Check(CVodeInit(cvode, RightHandSide, t, state), "CVodeInit");
    Check(CVodeSetLinearSolver(cvode, solver, matrix), "CVodeSetLinearSolver");
    Check(CVodeSetUserData(cvode, &callbacks), "CVodeSetUserData");
    Check(CVodeSetErrHandlerFn(cvode, KeepError, &callbacks), "CVodeSetErrHandlerFn");
    Check(CVodeSetNoInactiveRootWarn(cvode), "CVodeSetNoInactiveRootWarn");
  }

  void Check(int flag, const char* call) const {
    if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + FlagName(flag));
  }

  // Adds CVODE's counters since the last (re)initialisation to `stats`.
  void Accumulate(RunStats& stats) const {
    long value = 0;
    CVodeGetNumSteps(cvode, &value);
    stats.steps += value;
    CVodeGetNumRhsEvals(cvode, &value);
    stats.rhs_evals += value;
    CVodeGetNumLinRhsEvals(cvode, &value);
    stats.rhs_evals += value;
    CVodeGetNumJacEvals(cvode, &value);
    stats.jac_evals += value;
    CVodeGetNumLinSolvSetups(cvode, &value);
    stats.linear_setups += value;
    CVodeGetNumNonlinSolvIters(cvode, &value);
    stats.newton_iters += value;
    CVodeGetNumNonlinSolvConvFails(cvode, &value);
    stats.newton_conv_fails += value;
    CVodeGetNumErrTestFails(cvode, &value);
    stats.error_test_fails += value;
  }
};

Simulation::Simulation() : workspace_(std::make_unique<Workspace>()) {}
Simulation::~Simulation() = default;

RunResult Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                          const RunRequest& request) {
  RunResult result;
  result.stats = Run(system, options, request, result.trajectory);
  return result;
}

namespace {

// Collects the points in a vector.
class VectorSink final : public TrajectorySink {
 public:
  explicit VectorSink(std::vector<TrajectoryPoint>& points) : points_(points) { points_.clear(); }
  void Record(const TrajectoryPoint& point) override { points_.push_back(point); }

 private:
  std::vector<TrajectoryPoint>& points_;
};

}  // namespace

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, std::vector<TrajectoryPoint>& trajectory) {
  VectorSink sink(trajectory);
  return Run(system, options, request, sink);
}

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, TrajectorySink& sink) {
  Validate(options);
  Validate(request);
  const auto wall_start = std::chrono::steady_clock::now();
  Workspace& ws = *workspace_;

  // root functions: the passive kink, the user's limits, zero length
  Callbacks& cb = ws.callbacks;
  cb.system = &system;
  cb.root_count = 0;
  cb.last_error.clear();
  const auto add_root = [&cb](Callbacks::RootKind kind, double level) {
    cb.kinds[cb.root_count] = kind;
    cb.levels[cb.root_count++] = level;
  };
  if (system.model().params().passive.k_p > 0.0) {
    add_root(Callbacks::kSlack, system.model().params().passive.slack_length);
  }
  if (request.min_length) add_root(Callbacks::kMinLength, *request.min_length);
  if (request.max_length) add_root(Callbacks::kMaxLength, *request.max_length);
  add_root(Callbacks::kZeroLength, 0.0);

  double* y = N_VGetArrayPointer(ws.state);
  y[0] = request.length;
  y[1] = request.lengthening_rate;
  const auto configure = [&](double t) {
    ws.Start(options.method, t);
    ws.Check(CVodeSStolerances(ws.cvode, options.rtol, options.atol), "CVodeSStolerances");
    ws.Check(CVodeSetJacFn(ws.cvode, options.jacobian == JacobianKind::kAnalytic
                                         ? AnalyticJacobian : nullptr),
             "CVodeSetJacFn");
    ws.Check(CVodeSetMaxStep(ws.cvode, options.max_step), "CVodeSetMaxStep");
    ws.Check(CVodeSetMaxNumSteps(ws.cvode, options.max_steps), "CVodeSetMaxNumSteps");
    ws.Check(CVodeRootInit(ws.cvode, cb.root_count, RootFunctions), "CVodeRootInit");
  };

  RunStats stats;
  const auto record = [&](double t) {
    sink.Record({t, system.Observe(t, y[0], y[1])});
  };
  const auto finish = [&](RunStatus status, double t, std::string message) {
    ws.Accumulate(stats);
    stats.status = status;
    stats.final_time = t;
    stats.message = std::move(message);
    stats.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return stats;
  };

  // Times a rounding error apart (a pulse edge computed as start + k period + width and an
  // output time k interval, say) are one time: CVODE refuses to step over less than a few
  // ulps (CV_TOO_CLOSE), so nothing closer than `merge` is integrated over.
  const double merge =
      16.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(request.t_start), std::abs(request.t_end));
  std::vector<double> stops;
  for (double b : system.Breakpoints(request.t_start, request.t_end)) {
    const double previous = stops.empty() ? request.t_start : stops.back();
    if (b - previous > merge && request.t_end - b > merge) stops.push_back(b);
  }
  stops.push_back(request.t_end);
  const bool every_step = request.output_interval == 0.0;
  const double span = request.t_end - request.t_start;
  const long outputs = every_step ? 0 : static_cast<long>(std::ceil(span / request.output_interval - 1e-9));
  long next_output = 1;  // output k is at t_start + k * interval, the last one at t_end
  const auto output_time = [&](long k) {
    return k >= outputs ? request.t_end : request.t_start + k * request.output_interval;
  };

  double t = request.t_start;
  bool fresh = true;  // no step taken since the last (re)initialisation
  configure(t);
  record(t);
  for (double stop : stops) {
    ws.Check(CVodeSetStopTime(ws.cvode, stop), "CVodeSetStopTime");
    while (t < stop) {
      const double target = every_step ? stop : std::min(output_time(next_output), stop);
      if (fresh && target - t <= merge) {
        // a rounding error past a restart, too close for CVODE's first step (CV_TOO_CLOSE):
        // the state there is the state here (later in a run CVODE interpolates instead)
        t = target;
      } else {
        fresh = false;
        const int flag = CVode(ws.cvode, target, ws.state, &t, every_step ? CV_ONE_STEP : CV_NORMAL);
        if (flag < 0) {
          return finish(RunStatus::kFailed, t,
                        "CVODE failed at t = " + FormatNumber(t) + " s with " + FlagName(flag) +
                            (cb.last_error.empty() ? "" : " (" + cb.last_error + ")"));
        }
        long segment_steps = 0;
        CVodeGetNumSteps(ws.cvode, &segment_steps);
        if (stats.steps + segment_steps > options.max_steps) {
          return finish(RunStatus::kFailed, t,
                        "more than max_steps = " + std::to_string(options.max_steps) +
                            " internal steps by t = " + FormatNumber(t) + " s");
        }
        if (flag == CV_ROOT_RETURN) {
          int found[4] = {0, 0, 0, 0};
          CVodeGetRootInfo(ws.cvode, found);
          for (int i = 0; i < cb.root_count; ++i) {
            if (found[i] == 0) continue;
            const std::string where = "length " + FormatNumber(y[0]) + " m at t = " + FormatNumber(t) + " s";
            switch (cb.kinds[i]) {
              case Callbacks::kMinLength:
              case Callbacks::kMaxLength:
                record(t);
                return finish(RunStatus::kLimit, t,
                              std::string(cb.kinds[i] == Callbacks::kMinLength ? "min_length"
                                                                               : "max_length") +
                                  " = " + FormatNumber(cb.levels[i]) + " reached: " + where);
              case Callbacks::kZeroLength:
                record(t);
                return finish(RunStatus::kFailed, t, "the length reached zero at t = " +
                                                         FormatNumber(t) + " s: the actuator collapsed");
              case Callbacks::kSlack:
                break;
            }
          }
          // the slack kink: restart the integrator on its far side
          ws.Accumulate(stats);
          configure(t);
          fresh = true;
          ws.Check(CVodeSetStopTime(ws.cvode, stop), "CVodeSetStopTime");
          if (every_step) record(t);
          continue;
        }
      }
      if (every_step) {
        record(t);
      } else if (output_time(next_output) - t <= merge) {
        // labelled with the grid time, which t equals or misses by a rounding error
        record(output_time(next_output));
        ++next_output;
      }
    }
    if (stop < request.t_end) {
      // an input jumps at `stop`: restart with fresh history
      ws.Accumulate(stats);
      configure(t);
      fresh = true;
    }
  }
  return finish(RunStatus::kCompleted, t, "");
}

}  // namespace musclesim
