#include "musclesim/solver/simulation.h"

#include <cvodes/cvodes.h>
#include <cvodes/cvodes_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "musclesim/core/errors.h"
#include "musclesim/core/enum_names.h"
#include "crossing.h"
#include "linear_system.h"
#include "run_roots.h"
#include "small_vector.h"
#include "step_polynomial.h"

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

constexpr EnumName<LinearSolverKind> kLinearSolverNames[] = {
    {LinearSolverKind::kDense, "dense"},
    {LinearSolverKind::kBand, "band"},
    {LinearSolverKind::kSparse, "sparse"},
    {LinearSolverKind::kAuto, "auto"},
    {LinearSolverKind::kSmall, "small"},
};

std::string_view ToString(LinearSolverKind kind) { return ToString(kLinearSolverNames, kind); }

LinearSolverKind ParseLinearSolverKind(std::string_view text) {
  return Parse(kLinearSolverNames, "linear_solver", text);
}

LinearSolverKind ChooseLinearSolver(const JacobianPattern& pattern, JacobianKind jacobian) {
  // up to a few dozen states a dense LU costs less than band or sparse bookkeeping, and a
  // fixed-size one with its own vector least (docs/solver.md)
  // a band this narrow (a chain has 3 + 2) factors in O(n) with less overhead than KLU
  constexpr int kNarrowBand = 8;
  if (pattern.size <= kSmallSystemMaxSize) return LinearSolverKind::kSmall;
  if (pattern.lower_bandwidth + pattern.upper_bandwidth <= kNarrowBand) {
    return LinearSolverKind::kBand;
  }
  return jacobian == JacobianKind::kAnalytic ? LinearSolverKind::kSparse : LinearSolverKind::kBand;
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
  if (o.linear_solver == LinearSolverKind::kSparse && o.jacobian != JacobianKind::kAnalytic) {
    throw ParameterError("linear_solver", "sparse",
                         "needs jacobian: analytic (CVODE's difference-quotient Jacobian is "
                         "for dense and band matrices only)");
  }
}

namespace {

// The time span and the output grid, as both kinds of run request have them.
void ValidateSpan(double t_start, double t_end) {
  Require(std::isfinite(t_start), "t_start", t_start, "must be finite [s]");
  Require(std::isfinite(t_end) && t_end > t_start, "t_end", t_end,
          "must be finite and greater than t_start = " + FormatNumber(t_start) + " [s]");
}

void ValidateOutputInterval(double t_start, double t_end, double interval) {
  // 0 asks for every internal step; otherwise a positive grid of at most 1e8 rows
  Require(interval == 0.0 ||
              (std::isfinite(interval) && interval > 0.0 && (t_end - t_start) / interval <= 1e8),
          "output_interval", interval,
          "must be > 0 with at most 1e8 rows over the run, or 0 for every step [s]");
}

}  // namespace

void Validate(const RunRequest& r) {
  ValidateSpan(r.t_start, r.t_end);
  Require(std::isfinite(r.length) && r.length > 0.0, "length", r.length,
          "must be finite and > 0 [m]");
  Require(std::isfinite(r.lengthening_rate), "lengthening_rate", r.lengthening_rate,
          "must be finite [m/s]");
  ValidateOutputInterval(r.t_start, r.t_end, r.output_interval);
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

void Validate(const NetworkRunRequest& r) {
  ValidateSpan(r.t_start, r.t_end);
  ValidateOutputInterval(r.t_start, r.t_end, r.output_interval);
  for (double v : r.initial_state) Require(std::isfinite(v), "initial_state", v, "must be finite");
  for (std::size_t i = 0; i < r.output_times.size(); ++i) {
    const double t = r.output_times[i];
    const double previous = i == 0 ? -std::numeric_limits<double>::infinity() : r.output_times[i - 1];
    Require(std::isfinite(t) && t >= r.t_start && t <= r.t_end && t > previous, "output_times", t,
            "must be strictly increasing within [t_start, t_end] = [" + FormatNumber(r.t_start) +
                ", " + FormatNumber(r.t_end) + "] [s]");
  }
}

namespace {

constexpr double kNewtonConvergenceCoefficient = 0.03;
constexpr long kJacobianEvaluationFrequency = 10;  // steps

// What the C callbacks see through CVODE's user data.
struct Callbacks {
  const NetworkSystem* system = nullptr;
  // set when the network is a single actuator's (docs/model.md 7.4) without activation
  // dynamics: its own right-hand side and Jacobian are the network's bit for bit
  // (network_test checks) and cost less
  const ActuatorSystem* actuator = nullptr;
  LinearSystem* linear = nullptr;
  std::vector<Root> roots;
  std::string last_error;
  // The inputs (activation, excitation, loads) jump only at the stop times, and a step's
  // right-hand sides belong to the segment it is in: an implicit step ending on a stop
  // must see the input before the jump, a restart the input after it, whichever side of
  // the exact time the waveform puts its edge. The inputs are read at the time clamped into
  // [input_from, input_to], a few ulps inside the segment.
  double input_from = 0.0;
  double input_to = 0.0;
  double InputTime(double t) const { return std::clamp(t, input_from, input_to); }
  // a run with sensitivities: its parameters, and room for df/dy and one df/dp
  const std::vector<SensitivityParameter>* parameters = nullptr;
  std::vector<double> jacobian_values;
  std::vector<double> dfdp;
};

int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const auto* cb = static_cast<const Callbacks*>(data);
  double* rate = N_VGetArrayPointer(ydot);
  if (cb->actuator != nullptr) {
    const double* state = N_VGetArrayPointer(y);
    rate[0] = state[1];
    rate[1] = cb->actuator->Acceleration(cb->InputTime(t), state[0], state[1]);
    return std::isfinite(rate[1]) ? 0 : 1;
  }
  cb->system->RightHandSide(cb->InputTime(t), N_VGetArrayPointer(y), rate);
  // a non-finite value is a recoverable error: CVODE retries with a smaller step. A
  // position's rate is a velocity of the state itself; the accelerations (odd entries) and
  // the activation and integral rates after the nodes' states are computed
  const sunindextype n = N_VGetLength(ydot);
  const sunindextype node_states = cb->system->node_state_count();
  for (sunindextype i = 1; i < node_states; i += 2) {
    if (!std::isfinite(rate[i])) return 1;
  }
  for (sunindextype i = node_states; i < n; ++i) {
    if (!std::isfinite(rate[i])) return 1;
  }
  return 0;
}

int AnalyticJacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix jacobian, void* data,
                     N_Vector, N_Vector, N_Vector) {
  const auto* cb = static_cast<const Callbacks*>(data);
  if (cb->actuator != nullptr && cb->linear->dense()) {
    const double* state = N_VGetArrayPointer(y);
    const ActuatorSystem::JacobianRow row =
        cb->actuator->Jacobian(cb->InputTime(t), state[0], state[1]);
    SM_ELEMENT_D(jacobian, 0, 0) = 0.0;
    SM_ELEMENT_D(jacobian, 0, 1) = 1.0;
    SM_ELEMENT_D(jacobian, 1, 0) = row.by_length;
    SM_ELEMENT_D(jacobian, 1, 1) = row.by_rate;
    return 0;
  }
  std::vector<double>& values = cb->linear->values();
  cb->system->Jacobian(cb->InputTime(t), N_VGetArrayPointer(y), values.data());
  cb->linear->Fill(values.data(), jacobian);
  return 0;
}

// The sensitivities' right-hand sides s_i' = (df/dy) s_i + df/dp_i (docs/model.md 10), with
// df/dy the analytic Jacobian on its compressed-column pattern.
int SensitivityRightHandSide(int count, sunrealtype t, N_Vector y, N_Vector, N_Vector* s,
                             N_Vector* sdot, void* data, N_Vector, N_Vector) {
  auto* cb = static_cast<Callbacks*>(data);
  const NetworkSystem& system = *cb->system;
  const JacobianPattern& pattern = system.jacobian_pattern();
  const double at = cb->InputTime(t);
  const double* state = N_VGetArrayPointer(y);
  system.Jacobian(at, state, cb->jacobian_values.data());
  for (int i = 0; i < count; ++i) {
    const double* direction = N_VGetArrayPointer(s[i]);
    double* rate = N_VGetArrayPointer(sdot[i]);
    const ParameterDerivative& derivative =
        *(*cb->parameters)[static_cast<std::size_t>(i)].derivative;
    derivative.RightHandSide(at, state, rate);
    for (int column = 0; column < pattern.size; ++column) {
      const double along = direction[column];
      if (along == 0.0) continue;
      for (int k = pattern.column_starts[column]; k < pattern.column_starts[column + 1]; ++k) {
        rate[pattern.rows[k]] += cb->jacobian_values[k] * along;
      }
    }
    derivative.RefineRate(at, state, direction, rate);
    for (int k = 0; k < pattern.size; ++k) {
      if (!std::isfinite(rate[k])) return 1;  // recoverable: CVODES retries a smaller step
    }
  }
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
  N_Vector between = nullptr;  // a state interpolated within the last step
  std::unique_ptr<LinearSystem> linear;
  void* cvode = nullptr;
  IntegrationMethod method = IntegrationMethod::kBdf;
  Callbacks callbacks;
  NetworkSample sample;  // re-used by every record
  // forward sensitivities: at the last (re)start, and interpolated for a row
  N_Vector* sensitivities = nullptr;
  N_Vector* sensitivities_between = nullptr;
  int sensitivity_count = 0;
  int sensitivities_initialized = 0;  // the count CVodeSensInit1 was given; 0: none
  bool sensitivities_on = false;
  std::vector<double> sensitivity_scales;  // pbar: CVODES keeps the pointer
  // CVODE's counters since the last (re)initialisation already added to a run's stats: a
  // resumed run counts only what comes after them
  RunStats counted;
  // set when the last run completed without sensitivities: the system it integrated and its
  // end, where a resumed run may go on (Simulation::Integrate's `resume`)
  const NetworkSystem* resumable_system = nullptr;
  double resumable_time = 0.0;

  Workspace() {
    if (SUNContext_Create(nullptr, &context) != 0) {
      throw std::runtime_error("SUNContext_Create failed");
    }
  }
  ~Workspace() {
    if (cvode != nullptr) CVodeFree(&cvode);
    FreeSensitivities();
    linear.reset();
    if (between != nullptr) N_VDestroy(between);
    if (state != nullptr) N_VDestroy(state);
    if (context != nullptr) SUNContext_Free(&context);
  }

  void FreeSensitivities() {
    if (sensitivities != nullptr) N_VDestroyVectorArray(sensitivities, sensitivity_count);
    if (sensitivities_between != nullptr) {
      N_VDestroyVectorArray(sensitivities_between, sensitivity_count);
    }
    sensitivities = sensitivities_between = nullptr;
    sensitivity_count = 0;
  }

  // Vectors for `count` sensitivities like `state` (after Fit).
  void FitSensitivities(int count) {
    if (sensitivities != nullptr && sensitivity_count == count &&
        N_VGetLength(sensitivities[0]) == N_VGetLength(state)) {
      return;
    }
    FreeSensitivities();
    sensitivities = N_VCloneVectorArray(count, state);
    sensitivities_between = N_VCloneVectorArray(count, state);
    sensitivity_count = count;
    if (sensitivities == nullptr || sensitivities_between == nullptr) {
      throw std::runtime_error("allocating the sensitivity vectors failed");
    }
  }

  // Makes the state vector and linear system fit `system` with `kind`, keeping the CVODE
  // memory when they already do (a sweep's runs of one scenario).
  void Fit(const NetworkSystem& system, LinearSolverKind kind) {
    const JacobianPattern& pattern = system.jacobian_pattern();
    const bool small = kind == LinearSolverKind::kSmall;
    const bool same_size = state != nullptr && N_VGetLength(state) == pattern.size &&
                           IsSmallVector(state) == small;
    if (same_size && linear != nullptr && linear->Fits(kind, pattern)) return;
    if (cvode != nullptr) CVodeFree(&cvode);
    cvode = nullptr;
    linear.reset();
    if (!same_size) {
      FreeSensitivities();
      if (between != nullptr) N_VDestroy(between);
      if (state != nullptr) N_VDestroy(state);
      between = nullptr;
      state = small ? NewSmallVector(pattern.size, context) : N_VNew_Serial(pattern.size, context);
      // fused vector operations: fewer calls per step, which dominate on a small system
      if (state != nullptr && !small) N_VEnableFusedOps_Serial(state, SUNTRUE);
      if (state != nullptr) between = N_VClone(state);
      if (between == nullptr) throw std::runtime_error("allocating the CVODE state failed");
    }
    linear = std::make_unique<LinearSystem>(kind, pattern, state, context);
    callbacks.linear = linear.get();
  }

  // Creates the CVODE memory for `m`, or re-initialises the existing one at (t, state).
  void Start(IntegrationMethod m, double t) {
    counted = RunStats{};
    if (cvode != nullptr && method == m) {
      Check(CVodeReInit(cvode, t, state), "CVodeReInit");
      return;
    }
    if (cvode != nullptr) CVodeFree(&cvode);
    cvode = CVodeCreate(m == IntegrationMethod::kBdf ? CV_BDF : CV_ADAMS, context);
    if (cvode == nullptr) throw std::runtime_error("CVodeCreate failed");
    method = m;
    sensitivities_initialized = 0;
    sensitivities_on = false;
    Check(CVodeInit(cvode, RightHandSide, t, state), "CVodeInit");
    Check(CVodeSetLinearSolver(cvode, linear->solver(), linear->matrix()), "CVodeSetLinearSolver");
    Check(CVodeSetUserData(cvode, &callbacks), "CVodeSetUserData");
    Check(CVodeSetErrHandlerFn(cvode, KeepError, &callbacks), "CVodeSetErrHandlerFn");
  }

  void Check(int flag, const char* call) const {
    if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + FlagName(flag));
  }

  // Adds CVODE's counters since the last (re)initialisation, less those already counted, to
  // `stats`.
  void Accumulate(RunStats& stats) {
    const auto add = [&](auto get, long RunStats::*counter) {
      long value = 0;
      get(cvode, &value);
      stats.*counter += value - counted.*counter;
      counted.*counter = value;
    };
    add(CVodeGetNumSteps, &RunStats::steps);
    // a difference-quotient Jacobian's right-hand sides count with the steps' own
    long rhs = 0, linear_rhs = 0;
    CVodeGetNumRhsEvals(cvode, &rhs);
    CVodeGetNumLinRhsEvals(cvode, &linear_rhs);
    stats.rhs_evals += rhs + linear_rhs - counted.rhs_evals;
    counted.rhs_evals = rhs + linear_rhs;
    add(CVodeGetNumJacEvals, &RunStats::jac_evals);
    add(CVodeGetNumLinSolvSetups, &RunStats::linear_setups);
    add(CVodeGetNumNonlinSolvIters, &RunStats::newton_iters);
    add(CVodeGetNumNonlinSolvConvFails, &RunStats::newton_conv_fails);
    add(CVodeGetNumErrTestFails, &RunStats::error_test_fails);
    if (!sensitivities_on) return;
    add(CVodeGetSensNumRhsEvals, &RunStats::sensitivity_rhs_evals);
    add(CVodeGetSensNumNonlinSolvIters, &RunStats::sensitivity_newton_iters);
    add(CVodeGetSensNumNonlinSolvConvFails, &RunStats::sensitivity_newton_conv_fails);
    add(CVodeGetSensNumErrTestFails, &RunStats::sensitivity_error_test_fails);
  }

  // After Start: switches the sensitivities on at the values in `sensitivities` (the first
  // start of this CVODES memory: CVodeSensInit; later ones CVodeSensReInit), or off.
  void ConfigureSensitivities(int count) {
    if (count == 0) {
      if (sensitivities_on) Check(CVodeSensToggleOff(cvode), "CVodeSensToggleOff");
      sensitivities_on = false;
      return;
    }
    if (sensitivities_initialized == count) {
      Check(CVodeSensReInit(cvode, CV_STAGGERED, sensitivities), "CVodeSensReInit");
    } else {
      if (sensitivities_initialized != 0) CVodeSensFree(cvode);
      Check(CVodeSensInit(cvode, count, CV_STAGGERED, SensitivityRightHandSide, sensitivities),
            "CVodeSensInit");
      sensitivities_initialized = count;
    }
    sensitivities_on = true;
    // tolerances as the state's, the absolute one over |p| (pbar); the sensitivities in the
    // error test, without which they are known to be inaccurate
    Check(CVodeSetSensParams(cvode, nullptr, sensitivity_scales.data(), nullptr),
          "CVodeSetSensParams");
    Check(CVodeSensEEtolerances(cvode), "CVodeSensEEtolerances");
    Check(CVodeSetSensErrCon(cvode, SUNTRUE), "CVodeSetSensErrCon");
  }
};

Simulation::Simulation() : workspace_(std::make_unique<Workspace>()) {}
Simulation::~Simulation() = default;

namespace {

// Collects the points in a vector.
class VectorSink final : public TrajectorySink {
 public:
  explicit VectorSink(std::vector<TrajectoryPoint>& points) : points_(points) { points_.clear(); }
  void Record(const TrajectoryPoint& point) override { points_.push_back(point); }

 private:
  std::vector<TrajectoryPoint>& points_;
};

// The single actuator's view of its network's samples (element 0 the actuator, node 1 the tip).
class ActuatorView final : public NetworkSink {
 public:
  ActuatorView(const ActuatorSystem& system, TrajectorySink& out) : system_(system), out_(out) {}
  // the actuator's own Observe: what Record computes from the network, without the network
  bool RecordState(double t, const double* y) override {
    if (system_.excitation()) {
      out_.Record({t, system_.Observe(t, y[0], y[1], y[2])});  // y = (x, xdot, u)
    } else {
      out_.Record({t, system_.Observe(t, y[0], y[1])});
    }
    return true;
  }
  void Record(double t, const NetworkSample& s) override {
    const ElementSample& actuator = s.elements[0];
    ActuatorSample sample;
    sample.length = actuator.length;
    sample.shortening_velocity = 0.0 - actuator.lengthening_rate;  // +0 rather than -0 at rest
    sample.activation = actuator.activation;
    sample.excitation = actuator.excitation;
    sample.tension = actuator.parts;
    sample.load = s.load[1];
    out_.Record({t, sample});
  }

 private:
  const ActuatorSystem& system_;
  TrajectorySink& out_;
};

class NetworkVectorSink final : public NetworkSink {
 public:
  explicit NetworkVectorSink(NetworkRunResult& result) : result_(result) {}
  void Record(double t, const NetworkSample& sample) override {
    result_.times.push_back(t);
    result_.samples.push_back(sample);
  }

 private:
  NetworkRunResult& result_;
};

}  // namespace

NetworkRunRequest NetworkRequestOf(const ActuatorSystem& system, const RunRequest& request) {
  NetworkRunRequest network_request;
  network_request.t_start = request.t_start;
  network_request.t_end = request.t_end;
  network_request.output_interval = request.output_interval;
  if (request.min_length || request.max_length) {
    network_request.limits.push_back({"actuator", request.min_length, request.max_length});
  }
  network_request.initial_state = {request.length, request.lengthening_rate};
  if (system.excitation()) {
    const double u0 = system.excitation()->InitialActivation(request.t_start);
    network_request.initial_state.push_back(u0);
  }
  return network_request;
}

RunResult Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                          const RunRequest& request) {
  RunResult result;
  result.stats = Run(system, options, request, result.trajectory);
  return result;
}

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, std::vector<TrajectoryPoint>& trajectory) {
  VectorSink sink(trajectory);
  return Run(system, options, request, sink);
}

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, TrajectorySink& sink) {
  Validate(request);
  const NetworkRunRequest network_request = NetworkRequestOf(system, request);
  ActuatorView view(system, sink);
  // the actuator's own right-hand side knows no activation state
  workspace_->callbacks.actuator = system.excitation() ? nullptr : &system;
  try {
    const RunStats stats = Run(system.network(), options, network_request, view);
    workspace_->callbacks.actuator = nullptr;
    return stats;
  } catch (...) {
    workspace_->callbacks.actuator = nullptr;
    throw;
  }
}

NetworkRunResult Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                                 const NetworkRunRequest& request) {
  NetworkRunResult result;
  NetworkVectorSink sink(result);
  result.stats = Run(system, options, request, sink);
  return result;
}

RunStats Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                         const NetworkRunRequest& request, NetworkSink& sink) {
  return Integrate(system, options, request, &sink, nullptr, nullptr);
}

RunStats Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                         const NetworkRunRequest& request,
                         const std::vector<SensitivityParameter>& parameters,
                         SensitivitySink& sink) {
  return Integrate(system, options, request, nullptr, &parameters, &sink);
}

RunStats Simulation::Integrate(const NetworkSystem& system, const SolverOptions& options,
                               const NetworkRunRequest& request, NetworkSink* sink,
                               const std::vector<SensitivityParameter>* parameters,
                               SensitivitySink* sensitivity_sink, bool resume) {
  Validate(options);
  Validate(request);
  const auto wall_start = std::chrono::steady_clock::now();
  Workspace& ws = *workspace_;

  const int n = system.state_size();
  if (!request.initial_state.empty() && static_cast<int>(request.initial_state.size()) != n) {
    throw ParameterError("initial_state", std::to_string(request.initial_state.size()) + " values",
                         "must hold " + std::to_string(n) +
                             " values (x, xdot of every free node, then the activation of "
                             "every actuator with activation dynamics)");
  }
  std::vector<double> start(static_cast<std::size_t>(n));
  if (request.initial_state.empty()) {
    system.InitialState(request.t_start, start.data());
  } else {
    start = request.initial_state;
  }
  system.CheckLengths(request.t_start, start.data());
  Callbacks& cb = ws.callbacks;
  cb.roots = RootsOf(system, request, start.data());

  LinearSolverKind kind = options.linear_solver == LinearSolverKind::kAuto
                              ? ChooseLinearSolver(system.jacobian_pattern(), options.jacobian)
                              : options.linear_solver;
  if (kind == LinearSolverKind::kSmall && n > kSmallSystemMaxSize) {
    throw ParameterError("linear_solver", "small",
                         "serves at most " + std::to_string(kSmallSystemMaxSize) +
                             " states and this system has " + std::to_string(n) +
                             ": use auto, dense, band or sparse");
  }
  const int sensitivity_count = parameters == nullptr ? 0 : static_cast<int>(parameters->size());
  if (sensitivity_count > 0) {
    if (!system.controllers().empty()) {
      // df/dp and the activation rows' refinement assume inputs that no state feeds back into
      throw std::invalid_argument(
          "sensitivities of a network with controllers are not supported yet");
    }
    for (std::size_t i = 0; i < parameters->size(); ++i) {
      const SensitivityParameter& p = (*parameters)[i];
      if (p.derivative == nullptr || static_cast<int>(p.initial.size()) != n) {
        throw std::invalid_argument("sensitivity parameter " + std::to_string(i) +
                                    ": needs a derivative and " + std::to_string(n) +
                                    " initial values");
      }
    }
  }
  ws.Fit(system, kind);
  // CVODE's history is the last run's only while its memory lives on (Fit keeps it for the
  // same system) and that run ended where this one starts
  const bool resuming = resume && sensitivity_count == 0 && ws.cvode != nullptr &&
                        ws.resumable_system == &system && ws.resumable_time == request.t_start;
  ws.resumable_system = nullptr;  // until this run completes
  cb.system = &system;
  cb.last_error.clear();
  cb.parameters = parameters;
  std::vector<const double*> rows_sensitivities(static_cast<std::size_t>(sensitivity_count));
  if (sensitivity_count > 0) {
    ws.FitSensitivities(sensitivity_count);
    cb.jacobian_values.resize(static_cast<std::size_t>(system.jacobian_pattern().entries()));
    ws.sensitivity_scales.clear();
    for (int i = 0; i < sensitivity_count; ++i) {
      const SensitivityParameter& p = (*parameters)[static_cast<std::size_t>(i)];
      std::copy(p.initial.begin(), p.initial.end(), N_VGetArrayPointer(ws.sensitivities[i]));
      ws.sensitivity_scales.push_back(p.scale);
    }
  }

  double* y = N_VGetArrayPointer(ws.state);
  double* between = N_VGetArrayPointer(ws.between);
  std::copy(start.begin(), start.end(), y);
  const auto configure = [&](double t) {
    ws.Start(options.method, t);
    ws.Check(CVodeSStolerances(ws.cvode, options.rtol, options.atol), "CVodeSStolerances");
    ws.Check(CVodeSetJacFn(ws.cvode, options.jacobian == JacobianKind::kAnalytic
                                         ? AnalyticJacobian : nullptr),
             "CVodeSetJacFn");
    ws.Check(CVodeSetMaxStep(ws.cvode, options.max_step), "CVodeSetMaxStep");
    // A tighter Newton test (CVODE's default 0.1) and a fresher Jacobian (default every 51
    // steps): on this stiff, strongly nonlinear problem fewer steps fail, and each costs
    // little next to a step (README "Work-precision")
    ws.Check(CVodeSetNonlinConvCoef(ws.cvode, kNewtonConvergenceCoefficient),
             "CVodeSetNonlinConvCoef");
    ws.Check(CVodeSetJacEvalFrequency(ws.cvode, kJacobianEvaluationFrequency),
             "CVodeSetJacEvalFrequency");
    ws.ConfigureSensitivities(sensitivity_count);
  };

  RunStats stats;
  stats.linear_solver = kind;
  stats.sensitivities = sensitivity_count;
  bool fresh = !resuming;  // no step taken since the last (re)initialisation
  // the sensitivities at `at`: those the run (re)started with until a step is taken, then
  // the last step's interpolant's
  const auto sensitivities_at = [&](double at) {
    for (int i = 0; i < sensitivity_count; ++i) {
      rows_sensitivities[static_cast<std::size_t>(i)] =
          N_VGetArrayPointer(fresh ? ws.sensitivities[i] : ws.sensitivities_between[i]);
    }
    if (!fresh && sensitivity_count > 0) {
      ws.Check(CVodeGetSensDky(ws.cvode, at, 0, ws.sensitivities_between), "CVodeGetSensDky");
    }
    return rows_sensitivities.data();
  };
  // a row labelled `t` of the state `state` at time `state_time` (a rounding error from t)
  const auto record_at = [&](double t, const double* state, double state_time) {
    if (sensitivity_sink != nullptr) {
      sensitivity_sink->Record(t, state, sensitivities_at(state_time));
      return;
    }
    if (sink->RecordState(t, state)) return;
    system.Observe(t, state, ws.sample);
    sink->Record(t, ws.sample);
  };
  const auto record = [&](double t, const double* state) { record_at(t, state, t); };
  // the sensitivities at `t` become those the integrator restarts with
  const auto carry_sensitivities = [&](double t) {
    if (sensitivity_count == 0 || fresh) return;
    ws.Check(CVodeGetSensDky(ws.cvode, t, 0, ws.sensitivities), "CVodeGetSensDky");
  };
  const auto finish = [&](RunStatus status, double t, std::string message) {
    ws.Accumulate(stats);
    if (status == RunStatus::kCompleted && sensitivity_count == 0) {
      ws.resumable_system = &system;
      ws.resumable_time = t;
    }
    stats.status = status;
    stats.final_time = t;
    stats.message = std::move(message);
    stats.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return stats;
  };
  // the state at time `at` within the last step, from CVODE's interpolant
  const auto interpolate = [&](double at) {
    ws.Check(CVodeGetDky(ws.cvode, at, 0, ws.between), "CVodeGetDky");
    return between;
  };

  // Times a rounding error apart (a pulse edge computed as start + k period + width and an
  // output time k interval, say) are one time: CVODE refuses to step over less than a few
  // ulps (CV_TOO_CLOSE), so nothing closer than `merge` is integrated over.
  const double merge = 16.0 * std::numeric_limits<double>::epsilon() *
                       std::max(std::abs(request.t_start), std::abs(request.t_end));
  std::vector<double> stops;
  for (double b : system.Breakpoints(request.t_start, request.t_end)) {
    const double previous = stops.empty() ? request.t_start : stops.back();
    if (b - previous > merge && request.t_end - b > merge) stops.push_back(b);
  }
  stops.push_back(request.t_end);
  const std::vector<double>& listed = request.output_times;
  const bool explicit_times = !listed.empty();
  const bool every_step = !explicit_times && request.output_interval == 0.0;
  const bool row_at_start = !explicit_times || listed.front() == request.t_start;
  const double span = request.t_end - request.t_start;
  long outputs = every_step ? 0 : static_cast<long>(std::ceil(span / request.output_interval - 1e-9));
  // far from t = 0 the span itself carries rounding errors: a grid time within `merge` of
  // t_end is t_end, which the last output is anyway
  while (outputs > 1 &&
         request.t_start + (outputs - 1) * request.output_interval >= request.t_end - merge) {
    --outputs;
  }
  const long skipped = row_at_start && explicit_times ? 1 : 0;  // listed t_start: recorded first
  if (explicit_times) outputs = static_cast<long>(listed.size()) - skipped;
  long next_output = 1;  // output k is at t_start + k * interval, the last one at t_end
  const auto output_time = [&](long k) {
    if (explicit_times) return listed[static_cast<std::size_t>(k - 1 + skipped)];
    return k >= outputs ? request.t_end : request.t_start + k * request.output_interval;
  };
  // Records the grid outputs up to `until` within the last step; the state at `until` is
  // `at_until`. `through_until`: also an output at `until` or a rounding error past it,
  // labelled with its grid time; otherwise only those before it (the run ends there with a
  // row of its own).
  StepPolynomial polynomial;
  const auto record_outputs = [&](double until, const double* at_until, bool through_until) {
    if (every_step) return;
    // outputs strictly inside: more than the interpolant has terms (order + 1 derivatives to
    // fetch), and one polynomial serves them all; fewer, and CVodeGetDky per output costs less
    long inside = 0;
    while (next_output + inside <= outputs && output_time(next_output + inside) < until) ++inside;
    int order = 0;
    const bool by_polynomial = sensitivity_count == 0 &&
                               CVodeGetLastOrder(ws.cvode, &order) >= 0 && inside > order + 1 &&
                               polynomial.Fetch(ws.cvode, ws.between, n);
    while (next_output <= outputs) {
      const double out = output_time(next_output);
      if (through_until ? out - until > merge : out >= until - merge) break;
      if (out >= until) {
        record_at(out, at_until, until);
      } else if (by_polynomial) {
        polynomial.Evaluate(out, between);
        record(out, between);
      } else {
        record(out, interpolate(out));
      }
      ++next_output;
    }
  };

  // The roots are watched by their sign at the end of every step; only a sign change asks
  // for the crossing's time on the step's interpolant. A root exactly zero where the
  // integration (re)starts is inactive until it leaves zero, as in CVODE.
  const std::size_t root_count = cb.roots.size();
  std::vector<double> g_before(root_count), g_after(root_count);
  std::vector<char> active(root_count);
  const auto evaluate_roots = [&](double t, const double* state, std::vector<double>& g) {
    for (std::size_t i = 0; i < root_count; ++i) {
      g[i] = RootValue(system, cb.roots[i], cb.InputTime(t), state);
    }
  };
  const auto arm_roots = [&](double t) {
    evaluate_roots(t, y, g_before);
    for (std::size_t i = 0; i < root_count; ++i) active[i] = g_before[i] != 0.0;
  };
  // The earliest crossing over the last step (t_before, t_after], or -1.
  double crossing_time = 0.0;
  const auto find_crossing = [&](double t_before, double t_after, double step) -> int {
    int first = -1;
    for (std::size_t i = 0; i < root_count; ++i) {
      if (!active[i]) {
        if (g_after[i] != 0.0) active[i] = 1;  // left zero: watched from here on
        continue;
      }
      if (g_after[i] != 0.0 && (g_after[i] < 0.0) == (g_before[i] < 0.0)) continue;
      const Root& root = cb.roots[i];
      // CVODE's own location tolerance: 100 ulps of the time and the step
      const double tolerance =
          100.0 * std::numeric_limits<double>::epsilon() * (std::abs(t_after) + std::abs(step));
      const auto g = [&](double t) {
        return RootValue(system, root, cb.InputTime(t), interpolate(t));
      };
      const double at = LocateCrossing(g, t_before, g_before[i], t_after, g_after[i], tolerance);
      if (first < 0 || at < crossing_time) {
        first = static_cast<int>(i);
        crossing_time = at;
      }
    }
    return first;
  };

  double t = request.t_start;
  long calls = 0;     // CVode calls, one internal step each: the max_steps guard
  // resumed, CVODE goes on from its last step, with its order and step size, to the new stop
  // time (set below); its tolerances and settings are the last run's, the same options
  if (!resuming) configure(t);
  if (row_at_start) record(t, y);
  for (double stop : stops) {
    // the segment [t, stop]: its inputs read a few ulps inside it (Callbacks::InputTime)
    const double middle = 0.5 * (t + stop);
    cb.input_from = std::min(t + merge, middle);
    cb.input_to = std::max(stop - merge, middle);
    arm_roots(t);
    ws.Check(CVodeSetStopTime(ws.cvode, stop), "CVodeSetStopTime");
    while (t < stop) {
      if (fresh && stop - t <= merge) {
        // a rounding error past a restart, too close for CVODE's first step (CV_TOO_CLOSE):
        // the state there is the state here
        t = stop;
        record_outputs(t, y, true);
        break;
      }
      const double t_before = t;
      // CVODE bounds its first step by the distance to the time asked for: the next output,
      // as when it integrated output by output, so a restart starts as cautiously
      const double toward =
          fresh && !every_step && next_output <= outputs ? std::min(output_time(next_output), stop)
                                                          : stop;
      fresh = false;
      if (calls == options.max_steps) {
        // CVODE's own name for the condition, which the driver checks itself: one step per call
        return finish(RunStatus::kFailed, t,
                      "CVODE failed at t = " + FormatNumber(t) +
                          " s with CV_TOO_MUCH_WORK (more than max_steps = " +
                          std::to_string(options.max_steps) + " internal steps)");
      }
      ++calls;
      const int flag = CVode(ws.cvode, toward, ws.state, &t, CV_ONE_STEP);
      if (flag < 0) {
        return finish(RunStatus::kFailed, t,
                      "CVODE failed at t = " + FormatNumber(t) + " s with " + FlagName(flag) +
                          (cb.last_error.empty() ? "" : " (" + cb.last_error + ")"));
      }
      evaluate_roots(t, y, g_after);
      const int hit = find_crossing(t_before, t, t - t_before);
      if (hit < 0) {
        record_outputs(t, y, true);
        if (every_step) record(t, y);
        g_before.swap(g_after);
        continue;
      }
      // a crossing inside the step: the run goes on from there, on the interpolant's state
      t = crossing_time;
      const double* at_crossing = interpolate(t);
      std::copy(at_crossing, at_crossing + n, y);
      const Root& root = cb.roots[static_cast<std::size_t>(hit)];
      record_outputs(t, y, root.kind == Root::kKink);
      if (root.kind != Root::kKink) {
        const std::string& name = system.elements()[root.element].name;
        record(t, y);
        if (root.kind == Root::kZeroLength) {
          return finish(RunStatus::kFailed, t,
                        "the length of " + name + " reached zero at t = " + FormatNumber(t) +
                            " s: it collapsed");
        }
        return finish(RunStatus::kLimit, t,
                      std::string(root.kind == Root::kMinLength ? "min_length" : "max_length") +
                          " = " + FormatNumber(root.level) + " reached by " + name +
                          ": length " + FormatNumber(system.Length(root.element, t, y)) +
                          " m at t = " + FormatNumber(t) + " s");
      }
      // a kink: restart the integrator on its far side, the sensitivities carried over (the
      // right-hand side is continuous there: no jump, docs/model.md 10)
      carry_sensitivities(t);
      ws.Accumulate(stats);
      configure(t);
      fresh = true;
      ws.Check(CVodeSetStopTime(ws.cvode, stop), "CVodeSetStopTime");
      arm_roots(t);
      if (every_step) record(t, y);
    }
    if (stop < request.t_end) {
      // an input jumps at `stop`: restart with fresh history (a time that depends on no
      // parameter, so the sensitivities carry over unchanged)
      carry_sensitivities(t);
      ws.Accumulate(stats);
      configure(t);
      fresh = true;
    }
  }
  return finish(RunStatus::kCompleted, t, "");
}

}  // namespace musclesim
