// SolveOptimalControl: the multiple-shooting program handed to IPOPT (its C++ interface,
// Ipopt::TNLP) with exact first derivatives and IPOPT's limited-memory Hessian.
#include <IpIpoptApplication.hpp>
#include <IpIpoptData.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/optimize/multiple_shooting.h"
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

class ShootingProgram final : public Ipopt::TNLP {
 public:
  ShootingProgram(MultipleShooting& shooting, OptimalControlResult& result)
      : shooting_(shooting), result_(result), start_(shooting.StartingPoint()) {}

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
    objective = shooting_.Objective(x);
    return true;
  }
  bool eval_grad_f(Index, const Number* x, bool, Number* gradient) override {
    shooting_.ObjectiveGradient(x, gradient);
    return true;
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
  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index m, const Number* g, const Number*, Number objective,
                         const Ipopt::IpoptData* data, Ipopt::IpoptCalculatedQuantities*) override {
    result_.status = StatusName(status);
    result_.solved = status == Ipopt::SUCCESS;
    result_.objective = objective;
    result_.iterations = data != nullptr ? data->iter_count() : 0;
    std::vector<double> lower(static_cast<std::size_t>(m)), upper(static_cast<std::size_t>(m));
    shooting_.ConstraintBounds(lower.data(), upper.data());
    double violation = 0.0;
    for (Index r = 0; r < m; ++r) {
      const auto i = static_cast<std::size_t>(r);
      violation = std::max({violation, lower[i] - g[r], g[r] - upper[i]});
    }
    result_.constraint_violation = violation;
    solution_.assign(x, x + n);
  }
  const std::vector<double>& solution() const { return solution_; }

 private:
  MultipleShooting& shooting_;
  OptimalControlResult& result_;
  std::vector<double> start_;
  std::vector<double> solution_;
};

}  // namespace

OptimalControlResult SolveOptimalControl(const OptimalControlProblem& problem,
                                         const OptimizeOptions& options) {
  MultipleShooting shooting(problem);
  OptimalControlResult result;
  result.status = "not_run";
  Ipopt::SmartPtr<ShootingProgram> program = new ShootingProgram(shooting, result);
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
  result.times = shooting.times();
  result.scenario = problem.scenario;
  const std::vector<double>& x = program->solution();
  if (!x.empty()) {
    for (std::size_t j = 0; j < problem.controls.size(); ++j) {
      result.controls.push_back(shooting.ControlValues(x.data(), static_cast<int>(j)));
      std::vector<TablePoint> points;
      for (std::size_t i = 0; i < result.times.size(); ++i) {
        points.push_back({result.times[i], std::clamp(result.controls.back()[i], 0.0, 1.0)});
      }
      const int e = result.scenario.Build().FindElement(problem.controls[j].actuator);
      result.scenario.elements[static_cast<std::size_t>(e)].activation =
          Waveform::Table(std::move(points));
    }
  }
  return result;
}

}  // namespace musclesim
