#include "cvode_workspace.h"

#include <cvodes/cvodes_ls.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "small_vector.h"

namespace musclesim {

namespace {

constexpr double kNewtonConvergenceCoefficient = 0.03;
constexpr long kJacobianEvaluationFrequency = 10;  // steps

int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  auto* cb = static_cast<Callbacks*>(data);
  double* rate = N_VGetArrayPointer(ydot);
  cb->system->RightHandSide(cb->InputTime(t), N_VGetArrayPointer(y), rate, cb->scratch);
  // a non-finite value is a recoverable error: CVODE retries with a smaller step. Every rate is
  // checked: a massless junction's position rate is its balance's root, computed like the
  // accelerations and the activation and integral rates (a pass over a few numbers)
  const sunindextype n = N_VGetLength(ydot);
  bool finite = true;
  for (sunindextype i = 0; i < n; ++i) finite = finite && std::isfinite(rate[i]);
  if (finite) return 0;
  cb->NoteNonFinite(cb->InputTime(t), N_VGetArrayPointer(y), static_cast<std::size_t>(n));
  return 1;
}

int AnalyticJacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix jacobian, void* data, N_Vector,
                     N_Vector, N_Vector) {
  auto* cb = static_cast<Callbacks*>(data);
  std::vector<double>& values = cb->linear->values();
  cb->system->Jacobian(cb->InputTime(t), N_VGetArrayPointer(y), values.data(), cb->scratch);
  cb->linear->Fill(values.data(), jacobian);
  return 0;
}

// With the sparse solver and `jacobian: difference_quotient`: the coloured quotient on the
// system's structure (CVODE's own is for dense and band matrices only).
int SparseDifferenceQuotientJacobian(sunrealtype t, N_Vector y, N_Vector rate, SUNMatrix jacobian,
                                     void* data, N_Vector perturbed, N_Vector perturbed_rate,
                                     N_Vector weights) {
  auto* cb = static_cast<Callbacks*>(data);
  if (CVodeGetErrWeights(cb->cvode, weights) < 0) return -1;
  N_VScale(1.0, y, perturbed);
  const double at = cb->InputTime(t);
  const ColouredDifferenceQuotient& quotient = cb->linear->quotient();
  std::vector<double>& values = cb->linear->values();
  double step = 0.0;
  if (CVodeGetCurrentStep(cb->cvode, &step) < 0) return -1;
  quotient.Evaluate([&](const double* state,
                        double* out) { cb->system->RightHandSide(at, state, out, cb->scratch); },
                    N_VGetArrayPointer(perturbed), N_VGetArrayPointer(rate),
                    N_VGetArrayPointer(weights), step, N_VGetArrayPointer(perturbed_rate),
                    values.data());
  cb->quotient_rhs_evals += quotient.groups();
  for (double value : values) {
    if (!std::isfinite(value)) return 1;  // recoverable: CVODE retries a smaller step
  }
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
  system.Jacobian(at, state, cb->jacobian_values.data(), cb->scratch);
  for (int i = 0; i < count; ++i) {
    const double* direction = N_VGetArrayPointer(s[i]);
    double* rate = N_VGetArrayPointer(sdot[i]);
    const ParameterDerivative& derivative =
        *(*cb->parameters)[static_cast<std::size_t>(i)].derivative;
    derivative.RightHandSide(at, state, rate, cb->scratch);
    for (int column = 0; column < pattern.size; ++column) {
      const double along = direction[column];
      if (along == 0.0) continue;
      for (int k = pattern.column_starts[column]; k < pattern.column_starts[column + 1]; ++k) {
        rate[pattern.rows[k]] += cb->jacobian_values[k] * along;
      }
    }
    derivative.RefineRate(at, state, direction, rate, cb->scratch);
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

}  // namespace

std::string FlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // allocated by SUNDIALS
  std::string text = name != nullptr ? name : std::to_string(flag);
  std::free(name);
  return text;
}

CvodeWorkspace::CvodeWorkspace() {
  if (SUNContext_Create(nullptr, &context_) != 0) {
    throw std::runtime_error("SUNContext_Create failed");
  }
}

CvodeWorkspace::~CvodeWorkspace() {
  if (cvode_ != nullptr) CVodeFree(&cvode_);
  FreeSensitivities();
  linear_.reset();
  if (between_ != nullptr) N_VDestroy(between_);
  if (state_ != nullptr) N_VDestroy(state_);
  if (context_ != nullptr) SUNContext_Free(&context_);
}

void CvodeWorkspace::FreeSensitivities() {
  if (sensitivities_ != nullptr) N_VDestroyVectorArray(sensitivities_, sensitivity_count_);
  if (sensitivities_between_ != nullptr) {
    N_VDestroyVectorArray(sensitivities_between_, sensitivity_count_);
  }
  sensitivities_ = sensitivities_between_ = nullptr;
  sensitivity_count_ = 0;
}

void CvodeWorkspace::FitSensitivities(int count) {
  if (sensitivities_ != nullptr && sensitivity_count_ == count &&
      N_VGetLength(sensitivities_[0]) == N_VGetLength(state_)) {
    return;
  }
  FreeSensitivities();
  sensitivities_ = N_VCloneVectorArray(count, state_);
  sensitivities_between_ = N_VCloneVectorArray(count, state_);
  sensitivity_count_ = count;
  if (sensitivities_ == nullptr || sensitivities_between_ == nullptr) {
    throw std::runtime_error("allocating the sensitivity vectors failed");
  }
}

void CvodeWorkspace::Fit(const NetworkSystem& system, LinearSolverKind kind) {
  const JacobianPattern& pattern = system.jacobian_pattern();
  const bool small = kind == LinearSolverKind::kSmall;
  const bool same_size =
      state_ != nullptr && N_VGetLength(state_) == pattern.size && IsSmallVector(state_) == small;
  if (same_size && linear_ != nullptr && linear_->Fits(kind, pattern)) return;
  if (cvode_ != nullptr) CVodeFree(&cvode_);
  cvode_ = nullptr;
  linear_.reset();
  if (!same_size) {
    FreeSensitivities();
    if (between_ != nullptr) N_VDestroy(between_);
    if (state_ != nullptr) N_VDestroy(state_);
    between_ = nullptr;
    state_ = small ? NewSmallVector(pattern.size, context_) : N_VNew_Serial(pattern.size, context_);
    // fused vector operations: fewer calls per step, which dominate on a small system
    if (state_ != nullptr && !small) N_VEnableFusedOps_Serial(state_, SUNTRUE);
    if (state_ != nullptr) between_ = N_VClone(state_);
    if (between_ == nullptr) throw std::runtime_error("allocating the CVODE state failed");
  }
  linear_ = std::make_unique<LinearSystem>(kind, pattern, state_, context_);
  callbacks_.linear = linear_.get();
}

void CvodeWorkspace::Start(IntegrationMethod method, double t) {
  counted_ = RunStats{};
  callbacks_.quotient_rhs_evals = 0;
  if (cvode_ != nullptr && method_ == method) {
    Check(CVodeReInit(cvode_, t, state_), "CVodeReInit");
    return;
  }
  if (cvode_ != nullptr) CVodeFree(&cvode_);
  cvode_ = CVodeCreate(method == IntegrationMethod::kBdf ? CV_BDF : CV_ADAMS, context_);
  if (cvode_ == nullptr) throw std::runtime_error("CVodeCreate failed");
  method_ = method;
  sensitivities_initialized_ = 0;
  sensitivities_on_ = false;
  Check(CVodeInit(cvode_, RightHandSide, t, state_), "CVodeInit");
  Check(CVodeSetLinearSolver(cvode_, linear_->solver(), linear_->matrix()), "CVodeSetLinearSolver");
  Check(CVodeSetUserData(cvode_, &callbacks_), "CVodeSetUserData");
  callbacks_.cvode = cvode_;
  Check(CVodeSetErrHandlerFn(cvode_, KeepError, &callbacks_), "CVodeSetErrHandlerFn");
}

void CvodeWorkspace::Configure(const SolverOptions& options, double t, int count) {
  Start(options.method, t);
  Check(CVodeSStolerances(cvode_, options.rtol, options.atol), "CVodeSStolerances");
  CVLsJacFn jacobian = AnalyticJacobian;
  if (options.jacobian == JacobianKind::kDifferenceQuotient) {
    jacobian =
        linear_->kind() == LinearSolverKind::kSparse ? SparseDifferenceQuotientJacobian : nullptr;
  }
  Check(CVodeSetJacFn(cvode_, jacobian), "CVodeSetJacFn");
  Check(CVodeSetMaxStep(cvode_, options.max_step), "CVodeSetMaxStep");
  // A tighter Newton test (CVODE's default 0.1) and a fresher Jacobian (default every 51
  // steps): on this stiff, strongly nonlinear problem fewer steps fail, and each costs
  // little next to a step (docs/performance.md)
  Check(CVodeSetNonlinConvCoef(cvode_, kNewtonConvergenceCoefficient), "CVodeSetNonlinConvCoef");
  Check(CVodeSetJacEvalFrequency(cvode_, kJacobianEvaluationFrequency), "CVodeSetJacEvalFrequency");
  ConfigureSensitivities(count);
}

void CvodeWorkspace::Check(int flag, const char* call) const {
  if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + FlagName(flag));
}

void CvodeWorkspace::Accumulate(RunStats& stats) {
  const auto add = [&](auto get, long RunStats::*counter) {
    long value = 0;
    get(cvode_, &value);
    stats.*counter += value - counted_.*counter;
    counted_.*counter = value;
  };
  add(CVodeGetNumSteps, &RunStats::steps);
  // a difference-quotient Jacobian's right-hand sides count with the steps' own
  long rhs = 0, linear_rhs = 0;
  CVodeGetNumRhsEvals(cvode_, &rhs);
  CVodeGetNumLinRhsEvals(cvode_, &linear_rhs);
  rhs += linear_rhs + callbacks_.quotient_rhs_evals;
  stats.rhs_evals += rhs - counted_.rhs_evals;
  counted_.rhs_evals = rhs;
  add(CVodeGetNumJacEvals, &RunStats::jac_evals);
  add(CVodeGetNumLinSolvSetups, &RunStats::linear_setups);
  add(CVodeGetNumNonlinSolvIters, &RunStats::newton_iters);
  add(CVodeGetNumNonlinSolvConvFails, &RunStats::newton_conv_fails);
  add(CVodeGetNumErrTestFails, &RunStats::error_test_fails);
  if (!sensitivities_on_) return;
  add(CVodeGetSensNumRhsEvals, &RunStats::sensitivity_rhs_evals);
  add(CVodeGetSensNumNonlinSolvIters, &RunStats::sensitivity_newton_iters);
  add(CVodeGetSensNumNonlinSolvConvFails, &RunStats::sensitivity_newton_conv_fails);
  add(CVodeGetSensNumErrTestFails, &RunStats::sensitivity_error_test_fails);
}

// After Start: switches the sensitivities on at the values in sensitivities_ (the first start
// of this CVODES memory: CVodeSensInit; later ones CVodeSensReInit), or off.
void CvodeWorkspace::ConfigureSensitivities(int count) {
  if (count == 0) {
    if (sensitivities_on_) Check(CVodeSensToggleOff(cvode_), "CVodeSensToggleOff");
    sensitivities_on_ = false;
    return;
  }
  if (sensitivities_initialized_ == count) {
    Check(CVodeSensReInit(cvode_, CV_STAGGERED, sensitivities_), "CVodeSensReInit");
  } else {
    if (sensitivities_initialized_ != 0) CVodeSensFree(cvode_);
    Check(CVodeSensInit(cvode_, count, CV_STAGGERED, SensitivityRightHandSide, sensitivities_),
          "CVodeSensInit");
    sensitivities_initialized_ = count;
  }
  sensitivities_on_ = true;
  // tolerances as the state's, the absolute one over |p| (pbar); the sensitivities in the
  // error test, without which they are known to be inaccurate
  Check(CVodeSetSensParams(cvode_, nullptr, sensitivity_scales_.data(), nullptr),
        "CVodeSetSensParams");
  Check(CVodeSensEEtolerances(cvode_), "CVodeSensEEtolerances");
  Check(CVodeSetSensErrCon(cvode_, SUNTRUE), "CVodeSetSensErrCon");
}

}  // namespace musclesim
