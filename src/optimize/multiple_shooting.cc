#include "musclesim/optimize/multiple_shooting.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "optimize/shooting_program.h"

namespace musclesim {

MultipleShooting::MultipleShooting(const OptimalControlProblem& problem,
                                   ShootingDerivatives derivatives)
    : impl_(std::make_unique<Impl>()) {
  Impl& p = *impl_;
  p.quotients = derivatives == ShootingDerivatives::kDifferenceQuotients;
  p.index = CheckProblem(problem);
  p.problem = problem;
  p.scenario = problem.scenario;
  p.intervals = problem.intervals;
  p.n = problem.scenario.Build().state_size();
  p.results.resize(static_cast<std::size_t>(p.intervals));
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  for (int w = 0; w < std::min(cores, p.intervals); ++w) {
    p.simulations.push_back(std::make_unique<Simulation>());
  }
}

MultipleShooting::~MultipleShooting() = default;

int MultipleShooting::variable_count() const { return impl_->variables(); }

int MultipleShooting::constraint_count() const {
  const Impl& p = *impl_;
  return (p.intervals - 1) * p.n + static_cast<int>(p.index.finals.size()) +
         static_cast<int>(p.index.paths.size()) * p.intervals;
}

void MultipleShooting::VariableBounds(double* lower, double* upper) const {
  impl_->VariableBounds(lower, upper);
}

void MultipleShooting::ConstraintBounds(double* lower, double* upper) const {
  const Impl& p = *impl_;
  int row = (p.intervals - 1) * p.n;
  std::fill(lower, lower + row, 0.0);
  std::fill(upper, upper + row, 0.0);
  for (const FinalValue& final : p.problem.final_values) {
    lower[row] = final.lower;
    upper[row++] = final.upper;
  }
  for (const PathBound& bound : p.problem.path_bounds) {
    for (int i = 0; i < p.intervals; ++i) {
      lower[row] = bound.lower;
      upper[row++] = bound.upper;
    }
  }
}

std::string MultipleShooting::ConstraintName(int row, const double* x) const {
  const Impl& p = *impl_;
  const std::vector<double> times = p.Grid(p.FinalTime(x));
  const auto at = [&](int i) {
    return " at t = " + FormatNumber(times[static_cast<std::size_t>(i)]) + " s";
  };
  const int continuity = (p.intervals - 1) * p.n;
  if (row < continuity) {
    return "continuity of state " + std::to_string(row % p.n) + at(row / p.n + 1);
  }
  row -= continuity;
  const int finals = static_cast<int>(p.problem.final_values.size());
  if (row < finals) {
    return "final_values[" + std::to_string(row) + "] " +
           p.problem.final_values[static_cast<std::size_t>(row)].column;
  }
  row -= finals;
  const int bound = row / p.intervals;
  return "path_bounds[" + std::to_string(bound) + "] " +
         p.problem.path_bounds[static_cast<std::size_t>(bound)].column + at(row % p.intervals + 1);
}

std::vector<double> MultipleShooting::StartingPoint() {
  Impl& p = *impl_;
  std::vector<double> x(static_cast<std::size_t>(p.variables()), 0.0);
  const Scenario& given = p.problem.scenario;
  if (p.free_time()) {
    x[static_cast<std::size_t>(p.TimeIndex())] =
        std::clamp(given.t_end, p.problem.final_time->lower, p.problem.final_time->upper);
  }
  const std::vector<double> times = p.Grid(p.FinalTime(x.data()));
  for (int j = 0; j < p.controls(); ++j) {
    const ControlSpec& control = p.problem.controls[static_cast<std::size_t>(j)];
    const Element& element =
        given.elements[static_cast<std::size_t>(p.index.elements[static_cast<std::size_t>(j)])];
    const Waveform& activation =
        element.excitation ? element.excitation->signal : element.activation;
    for (int i = 0; i <= p.intervals; ++i) {
      x[static_cast<std::size_t>(p.ControlIndex(j, i))] = std::clamp(
          activation.Evaluate(times[static_cast<std::size_t>(i)]), control.lower, control.upper);
    }
  }
  for (int q = 0; q < p.parameters(); ++q) {
    const FreeParameter& free = p.problem.parameters[static_cast<std::size_t>(q)];
    x[static_cast<std::size_t>(p.ParameterIndex(q))] = std::clamp(
        p.index.parameters[static_cast<std::size_t>(q)].Get(given), free.lower, free.upper);
  }
  // one run through the grid: each interval starts where the one before ended
  if (!p.Build(x.data())) return x;
  for (int i = 0; i + 1 < p.intervals; ++i) {
    try {
      if (!p.Integrate(i, x.data(), 0, p.results[static_cast<std::size_t>(i)])) {
        break;
      }
    } catch (const std::exception&) {
      break;  // IPOPT starts from what there is
    }
    const std::vector<double>& end = p.results[static_cast<std::size_t>(i)].state;
    std::copy(end.begin(), end.end(), x.begin() + p.StateIndex(i + 1, 0));
  }
  p.evaluated.clear();  // the results are of a partly filled point
  return x;
}

bool MultipleShooting::Terms(const double* x, ObjectiveTerms& terms) {
  Impl& p = *impl_;
  terms = {};
  const double T = p.FinalTime(x);
  const double h = (T - p.problem.scenario.t_start) / p.intervals;
  for (int j = 0; j < p.controls(); ++j) {
    const ControlSpec& control = p.problem.controls[static_cast<std::size_t>(j)];
    for (int i = 0; i < p.intervals; ++i) {
      terms.effort +=
          control.effort_weight * h *
          SegmentEffort(x[p.ControlIndex(j, i)], x[p.ControlIndex(j, i + 1)], control.effort_power)
              .value;
    }
  }
  if (p.free_time()) terms.final_time = p.problem.final_time->weight * T;
  if (p.problem.tracking.empty() && p.problem.terminal.empty()) return true;
  if (!p.Evaluate(x)) return false;
  for (const IntervalResult& r : p.results) terms.tracking += r.tracking;
  const IntervalResult& last = p.results.back();
  for (std::size_t k = 0; k < p.problem.terminal.size(); ++k) {
    const TerminalTerm& term = p.problem.terminal[k];
    const double miss = last.columns[static_cast<std::size_t>(p.index.terminals[k])] - term.target;
    terms.terminal += term.weight * miss * miss;
  }
  return true;
}

bool MultipleShooting::Objective(const double* x, double& value) {
  ObjectiveTerms terms;
  if (!Terms(x, terms)) return false;
  value = terms.effort + terms.tracking + terms.terminal + terms.final_time;
  return true;
}

bool MultipleShooting::ObjectiveGradient(const double* x, double* gradient) {
  Impl& p = *impl_;
  std::fill(gradient, gradient + p.variables(), 0.0);
  const double T = p.FinalTime(x);
  const double h = (T - p.problem.scenario.t_start) / p.intervals;
  for (int j = 0; j < p.controls(); ++j) {
    const ControlSpec& control = p.problem.controls[static_cast<std::size_t>(j)];
    for (int i = 0; i < p.intervals; ++i) {
      const Effort e =
          SegmentEffort(x[p.ControlIndex(j, i)], x[p.ControlIndex(j, i + 1)], control.effort_power);
      gradient[p.ControlIndex(j, i)] += control.effort_weight * h * e.by_start;
      gradient[p.ControlIndex(j, i + 1)] += control.effort_weight * h * e.by_end;
      if (p.free_time()) gradient[p.TimeIndex()] += control.effort_weight * e.value / p.intervals;
    }
  }
  if (p.free_time()) gradient[p.TimeIndex()] += p.problem.final_time->weight;
  if (p.problem.tracking.empty() && p.problem.terminal.empty()) return true;
  if (!p.Evaluate(x)) return false;
  const auto add = [&](int variable, double value) { gradient[variable] += value; };
  for (int i = 0; i < p.intervals; ++i) {
    const IntervalResult& r = p.results[static_cast<std::size_t>(i)];
    // tracking needs a fixed final time: no derivative in T
    p.VisitInterval(
        i, [&](int k) { return r.tracking_gradient[static_cast<std::size_t>(k)]; }, 0.0, add);
  }
  const IntervalResult& last = p.results.back();
  const std::size_t U = p.index.columns.size();
  for (std::size_t k = 0; k < p.problem.terminal.size(); ++k) {
    const TerminalTerm& term = p.problem.terminal[k];
    const auto u = static_cast<std::size_t>(p.index.terminals[k]);
    const double slope = 2.0 * term.weight * (last.columns[u] - term.target);
    p.VisitInterval(
        p.intervals - 1,
        [&](int q) { return slope * last.column_gradients[static_cast<std::size_t>(q) * U + u]; },
        p.free_time() ? slope * p.columns_by_time.back()[u] : 0.0, add);
  }
  return true;
}

bool MultipleShooting::Constraints(const double* x, double* g) {
  Impl& p = *impl_;
  if (!p.Evaluate(x)) return false;
  int row = 0;
  for (int i = 0; i + 1 < p.intervals; ++i) {
    for (int k = 0; k < p.n; ++k) {
      g[row++] = p.results[static_cast<std::size_t>(i)].state[static_cast<std::size_t>(k)] -
                 x[p.StateIndex(i + 1, k)];
    }
  }
  for (const int u : p.index.finals)
    g[row++] = p.results.back().columns[static_cast<std::size_t>(u)];
  for (const int u : p.index.paths) {
    for (const IntervalResult& r : p.results) g[row++] = r.columns[static_cast<std::size_t>(u)];
  }
  return true;
}

void MultipleShooting::JacobianStructure(int* rows, int* columns) const {
  int entry = 0;
  impl_->WalkJacobian(false, [&](int row, int column, double) {
    rows[entry] = row;
    columns[entry] = column;
    ++entry;
  });
}

int MultipleShooting::jacobian_nonzeros() const {
  int count = 0;
  impl_->WalkJacobian(false, [&](int, int, double) { ++count; });
  return count;
}

bool MultipleShooting::ConstraintJacobian(const double* x, double* values) {
  if (!impl_->Evaluate(x)) return false;
  int entry = 0;
  impl_->WalkJacobian(true, [&](int, int, double value) { values[entry++] = value; });
  return true;
}

std::vector<double> MultipleShooting::Times(const double* x) const {
  return impl_->Grid(impl_->FinalTime(x));
}

std::vector<double> MultipleShooting::ControlValues(const double* x, int j) const {
  std::vector<double> values;
  for (int i = 0; i <= impl_->intervals; ++i) values.push_back(x[impl_->ControlIndex(j, i)]);
  return values;
}

std::vector<double> MultipleShooting::ParameterValues(const double* x) const {
  return std::vector<double>(x + impl_->ParameterIndex(0),
                             x + impl_->ParameterIndex(impl_->parameters()));
}

std::vector<double> MultipleShooting::States(const double* x) {
  Impl& p = *impl_;
  if (!p.Evaluate(x)) return {};
  std::vector<double> states = p.built.initial;
  states.insert(states.end(), x + p.StateIndex(1, 0), x + p.StateIndex(p.intervals, 0));
  const std::vector<double>& last = p.results.back().state;
  states.insert(states.end(), last.begin(), last.end());
  return states;
}

int MultipleShooting::state_size() const { return impl_->n; }

double MultipleShooting::integration_seconds() const { return impl_->integration_seconds; }

Scenario MultipleShooting::ScenarioAt(const double* x) const {
  Scenario scenario = impl_->problem.scenario;
  impl_->Apply(x, scenario);
  return scenario;
}

}  // namespace musclesim
