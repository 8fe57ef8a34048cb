// SolveOptimalControl: the multiple-shooting program handed to IPOPT (its C++ interface,
// Ipopt::TNLP) with exact first derivatives and IPOPT's limited-memory Hessian.
#include <IpIpoptApplication.hpp>
#include <IpIpoptData.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/optimize/multiple_shooting.h"
#include "musclesim/solver/simulation.h"
#include "optimize/shooting_parts.h"

namespace musclesim {

namespace {

using Ipopt::Index;
using Ipopt::Number;

std::string StatusName(Ipopt::SolverReturn status) {
  switch (status) {
    case Ipopt::SUCCESS: return "success";
    case Ipopt::MAXITER_EXCEEDED: return "maximum_iterations_exceeded";
    case Ipopt::CPUTIME_EXCEEDED: return "maximum_cpu_time_exceeded";
    case Ipopt::STOP_AT_TINY_STEP: return "search_direction_becomes_too_small";
    case Ipopt::STOP_AT_ACCEPTABLE_POINT: return "solved_to_acceptable_level";
    case Ipopt::LOCAL_INFEASIBILITY: return "infeasible_problem_detected";
    case Ipopt::USER_REQUESTED_STOP: return "user_requested_stop";
    case Ipopt::DIVERGING_ITERATES: return "diverging_iterates";
    case Ipopt::RESTORATION_FAILURE: return "restoration_failed";
    case Ipopt::ERROR_IN_STEP_COMPUTATION: return "error_in_step_computation";
    case Ipopt::INVALID_NUMBER_DETECTED: return "invalid_number_detected";
    case Ipopt::TOO_FEW_DEGREES_OF_FREEDOM: return "not_enough_degrees_of_freedom";
    default: return "internal_error";
  }
}

// Why the program stopped IPOPT itself, when it did.
enum class OwnStop { kNone, kStalled, kOutOfTime };

// The stall rule of optimal_control.h: over the last kStallIterations iterations neither the
// least violation fell by kStallReduction nor the least objective by a tenth of that, 1 %,
// below their least over the kStallIterations before them, the violation staying above
// kStallViolation (an infeasible problem's iterates trade the one for the other, making
// progress in neither).
class StallWatch {
 public:
  bool Stalled(double objective, double violation) {
    objectives_.push_back(objective);
    violations_.push_back(violation);
    constexpr auto window = static_cast<std::ptrdiff_t>(kStallIterations);
    if (static_cast<std::ptrdiff_t>(violations_.size()) < 2 * window) return false;
    const auto least = [](const std::vector<double>& v, std::ptrdiff_t back) {
      const auto end = v.end() - back * window;
      return *std::min_element(end - window, end);
    };
    const double violation_now = least(violations_, 0), violation_then = least(violations_, 1);
    const double objective_now = least(objectives_, 0), objective_then = least(objectives_, 1);
    const double objective_step = 0.1 * kStallReduction * std::abs(objective_then);
    return violation_now > kStallViolation &&
           violation_now > (1.0 - kStallReduction) * violation_then &&
           objective_now > objective_then - objective_step;
  }

 private:
  std::vector<double> objectives_, violations_;
};

class ShootingProgram final : public Ipopt::TNLP {
 public:
  ShootingProgram(MultipleShooting& shooting, OptimalControlResult& result,
                  const OptimizeOptions& options)
      : shooting_(shooting),
        result_(result),
        progress_(options.progress),
        max_seconds_(options.max_seconds),
        start_(shooting.StartingPoint()),
        started_(std::chrono::steady_clock::now()) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = shooting_.variable_count();
    m = shooting_.constraint_count();
    nnz_jac_g = shooting_.jacobian_nonzeros();
    nnz_h_lag = 0;  // limited-memory Hessian
    index_style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Index, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    shooting_.VariableBounds(x_l, x_u);
    shooting_.ConstraintBounds(g_l, g_u);
    return true;
  }
  bool get_starting_point(Index n, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    std::copy(start_.begin(), start_.begin() + n, x);
    return true;
  }
  bool eval_f(Index, const Number* x, bool, Number& objective) override {
    return shooting_.Objective(x, objective);
  }
  bool eval_grad_f(Index, const Number* x, bool, Number* gradient) override {
    return shooting_.ObjectiveGradient(x, gradient);
  }
  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    return shooting_.Constraints(x, g);
  }
  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* columns,
                  Number* values) override {
    if (values == nullptr) {
      shooting_.JacobianStructure(rows, columns);
      return true;
    }
    return shooting_.ConstraintJacobian(x, values);
  }
  bool intermediate_callback(Ipopt::AlgorithmMode, Index iteration, Number objective,
                             Number infeasibility, Number dual_infeasibility, Number, Number,
                             Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    result_.dual_infeasibility = dual_infeasibility;
    if (stall_.Stalled(objective, infeasibility)) {
      stop_ = OwnStop::kStalled;
      return false;
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (elapsed > max_seconds_) {
      stop_ = OwnStop::kOutOfTime;
      return false;
    }
    if (!progress_) return true;
    return progress_({iteration, objective, infeasibility, dual_infeasibility});
  }
  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index m, const Number* g, const Number*, Number objective,
                         const Ipopt::IpoptData* data, Ipopt::IpoptCalculatedQuantities*) override {
    result_.status = stop_ == OwnStop::kStalled     ? "infeasibility_stalled"
                     : stop_ == OwnStop::kOutOfTime ? "maximum_seconds_exceeded"
                                                    : StatusName(status);
    result_.solved = status == Ipopt::SUCCESS;
    result_.infeasible = stop_ == OwnStop::kStalled || status == Ipopt::LOCAL_INFEASIBILITY ||
                         status == Ipopt::RESTORATION_FAILURE;
    result_.objective = objective;
    result_.iterations = data != nullptr ? data->iter_count() : 0;
    std::vector<double> lower(static_cast<std::size_t>(m)), upper(static_cast<std::size_t>(m));
    shooting_.ConstraintBounds(lower.data(), upper.data());
    double violation = 0.0;
    Index worst = -1;
    for (Index r = 0; r < m; ++r) {
      const auto i = static_cast<std::size_t>(r);
      const double by = std::max(lower[i] - g[r], g[r] - upper[i]);
      if (by > violation) {
        violation = by;
        worst = r;
      }
    }
    result_.constraint_violation = violation;
    if (worst >= 0) {
      const auto i = static_cast<std::size_t>(worst);
      const auto shown = [](double v) { return FormatSignificant(v, 4); };
      result_.largest_violation =
          shooting_.ConstraintName(worst, x) + ": " + shown(g[worst]) + " where " +
          (lower[i] == upper[i] ? shown(lower[i])
                                : "[" + shown(lower[i]) + ", " + shown(upper[i]) + "]") +
          " is asked";
    }
    solution_.assign(x, x + n);
  }
  const std::vector<double>& solution() const { return solution_; }

 private:
  MultipleShooting& shooting_;
  OptimalControlResult& result_;
  std::function<bool(const OptimizeProgress&)> progress_;
  double max_seconds_;
  std::vector<double> start_;
  std::chrono::steady_clock::time_point started_;
  StallWatch stall_;
  OwnStop stop_ = OwnStop::kNone;
  std::vector<double> solution_;
};

// The objective's derivative at x along a pseudo-random direction (variables within a step of
// a bound left out: the controls are clamped there) by central differences, against the
// gradient's: their relative difference (0 when the direction is empty).
double GradientCheck(MultipleShooting& shooting, const std::vector<double>& x) {
  const auto count = x.size();
  std::vector<double> lower(count), upper(count), gradient(count), direction(count, 0.0);
  shooting.VariableBounds(lower.data(), upper.data());
  const double none = std::numeric_limits<double>::quiet_NaN();  // null in the summary
  if (!shooting.ObjectiveGradient(x.data(), gradient.data())) return none;
  std::mt19937 random(20261128);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  constexpr double kStep = 1e-6;
  double exact = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double step = kStep * std::max(1.0, std::abs(x[k]));
    if (x[k] - 2.0 * step < lower[k] || x[k] + 2.0 * step > upper[k]) continue;
    direction[k] = step * unit(random);
    exact += gradient[k] * direction[k];
  }
  std::vector<double> plus(x), minus(x);
  for (std::size_t k = 0; k < count; ++k) {
    plus[k] += direction[k];
    minus[k] -= direction[k];
  }
  double above = 0.0, below = 0.0;
  if (!shooting.Objective(plus.data(), above) || !shooting.Objective(minus.data(), below)) {
    return none;
  }
  const double differenced = 0.5 * (above - below);
  const double scale = std::max(std::abs(exact), std::abs(differenced));
  return scale > 0.0 ? std::abs(differenced - exact) / scale : 0.0;
}

// Keeps every row's state.
class StateRows final : public NetworkSink {
 public:
  void Record(double, const NetworkSample&) override {}
  bool RecordState(double, const double* y) override {
    rows.emplace_back(y, y + size);
    return true;
  }
  std::size_t size = 0;
  std::vector<std::vector<double>> rows;
};

// The optimum's scenario run once from s_0 with rows at the grid's points, against the
// shooting states; infinity when the run does not complete.
double ResimulationDeviation(const OptimalControlResult& result) {
  if (result.states.empty()) return std::numeric_limits<double>::infinity();
  const NetworkSystem system = result.scenario.Build();
  NetworkRunRequest request;
  request.t_start = result.times.front();
  request.t_end = result.times.back();
  request.output_times.assign(result.times.begin() + 1, result.times.end());
  StateRows rows;
  rows.size = static_cast<std::size_t>(result.state_size);
  Simulation simulation;
  const RunStats stats = simulation.Run(system, result.scenario.solver, request, rows);
  if (stats.status != RunStatus::kCompleted || rows.rows.size() + 1 != result.times.size()) {
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    for (std::size_t k = 0; k < rows.size; ++k) {
      worst = std::max(worst, std::abs(rows.rows[i][k] - result.states[(i + 1) * rows.size + k]));
    }
  }
  return worst;
}

// IPOPT's linear solver in Debian's build, MUMPS (sequential), keeps state of its own between
// calls: two solves at once in one process crash inside it (a SIGSEGV, or Fortran's "Attempt
// to DEALLOCATE unallocated"). Solves are therefore taken one at a time; each integrates its
// intervals on every core.
std::mutex& IpoptMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

OptimalControlResult SolveOptimalControl(const OptimalControlProblem& problem,
                                         const OptimizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MultipleShooting shooting(problem, options.derivatives);
  OptimalControlResult result;
  result.status = "not_run";
  Ipopt::SmartPtr<ShootingProgram> program = new ShootingProgram(shooting, result, options);
  const std::lock_guard<std::mutex> one_at_a_time(IpoptMutex());
  Ipopt::SmartPtr<Ipopt::IpoptApplication> ipopt = IpoptApplicationFactory();
  ipopt->Options()->SetNumericValue("tol", options.tolerance);
  ipopt->Options()->SetIntegerValue("max_iter", options.max_iterations);
  ipopt->Options()->SetIntegerValue("print_level", options.print_level);
  ipopt->Options()->SetStringValue("hessian_approximation", "limited-memory");
  ipopt->Options()->SetStringValue("sb", "yes");  // no banner
  // the controls are activations: IPOPT must not step outside [0, 1]
  ipopt->Options()->SetNumericValue("bound_relax_factor", 0.0);
  if (ipopt->Initialize() != Ipopt::Solve_Succeeded) {
    throw InputError("IPOPT could not be initialised");
  }
  ipopt->OptimizeTNLP(program);
  const std::vector<double>& x = program->solution();
  result.scenario = problem.scenario;
  if (x.empty()) return result;  // IPOPT stopped before its first point
  result.times = shooting.Times(x.data());
  result.final_time = result.times.back();
  for (std::size_t j = 0; j < problem.controls.size(); ++j) {
    result.controls.push_back(shooting.ControlValues(x.data(), static_cast<int>(j)));
  }
  result.parameter_values = shooting.ParameterValues(x.data());
  result.scenario = shooting.ScenarioAt(x.data());
  shooting.Terms(x.data(), result.terms);
  result.states = shooting.States(x.data());
  result.state_size = shooting.state_size();
  result.gradient_check = GradientCheck(shooting, x);
  result.resimulation_deviation = ResimulationDeviation(result);
  result.integration_seconds = shooting.integration_seconds();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace musclesim
