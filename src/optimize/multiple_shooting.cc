#include "musclesim/optimize/multiple_shooting.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/solver/sensitivity.h"
#include "musclesim/solver/simulation.h"
#include "optimize/shooting_parts.h"

namespace musclesim {

struct MultipleShooting::Impl {
  Scenario scenario;  // its controls' activations rewritten per point
  std::vector<ControlSpec> controls;
  std::vector<int> elements;  // each control's actuator
  std::vector<FinalValue> finals;
  std::vector<int> final_states;  // each final value's state index
  std::vector<double> times;      // t_0 .. t_N
  std::vector<double> initial;    // s_0
  int n = 0;                      // the state's size
  int intervals = 0;
  // one CVODE memory per worker thread: the intervals are integrated in parallel
  std::vector<std::unique_ptr<Simulation>> simulations;

  // The last point integrated: its x, whether every interval completed, and per interval
  // Phi_i and dPhi_i/d(s_i, U_(j,i), U_(j,i+1)) (column-major, n rows).
  std::vector<double> evaluated;
  bool ok = false;
  std::vector<std::vector<double>> ends, sensitivities;

  int control_count() const { return static_cast<int>(controls.size()); }
  int ControlIndex(int j, int i) const { return j * (intervals + 1) + i; }
  int StateIndex(int i, int k) const {  // s_i, i >= 1
    return control_count() * (intervals + 1) + (i - 1) * n + k;
  }
  int variables() const { return control_count() * (intervals + 1) + (intervals - 1) * n; }
  int sensitivity_count() const { return n + 2 * control_count(); }

  NetworkSystem BuildAt(const double* x) {
    for (int j = 0; j < control_count(); ++j) {
      std::vector<TablePoint> points;
      for (int i = 0; i <= intervals; ++i) {
        // IPOPT keeps to the bounds; the clamp only guards the activation's range
        const double u = std::clamp(x[ControlIndex(j, i)], 0.0, 1.0);
        points.push_back({times[static_cast<std::size_t>(i)], u});
      }
      scenario.elements[static_cast<std::size_t>(elements[static_cast<std::size_t>(j)])]
          .activation = Waveform::Table(std::move(points));
    }
    return scenario.Build();
  }

  // Integrates interval i of `system` from s_i (read from x) with the sensitivities.
  bool Integrate(const NetworkSystem& system, int i, const double* x, Simulation& simulation) {
    const double t0 = times[static_cast<std::size_t>(i)];
    const double t1 = times[static_cast<std::size_t>(i) + 1];
    NetworkRunRequest request;
    request.t_start = t0;
    request.t_end = t1;
    request.output_times = {t1};
    request.initial_state =
        i == 0 ? initial : std::vector<double>(x + StateIndex(i, 0), x + StateIndex(i, 0) + n);
    std::vector<std::unique_ptr<ParameterDerivative>> derivatives;
    std::vector<SensitivityParameter> parameters;
    for (int k = 0; k < n; ++k) {
      derivatives.push_back(std::make_unique<InitialStateDerivative>(n));
      std::vector<double> unit(static_cast<std::size_t>(n), 0.0);
      unit[static_cast<std::size_t>(k)] = 1.0;
      parameters.push_back({derivatives.back().get(), std::move(unit), 1.0});
    }
    for (int j = 0; j < control_count(); ++j) {
      for (const bool at_end : {false, true}) {
        derivatives.push_back(std::make_unique<ControlValueDerivative>(
            system, elements[static_cast<std::size_t>(j)], t0, t1, at_end));
        parameters.push_back(
            {derivatives.back().get(), std::vector<double>(static_cast<std::size_t>(n), 0.0), 1.0});
      }
    }
    IntervalEnd sink(n, sensitivity_count());
    const RunStats stats = simulation.Run(system, scenario.solver, request, parameters, sink);
    if (stats.status != RunStatus::kCompleted || !sink.recorded()) return false;
    ends[static_cast<std::size_t>(i)] = sink.state();
    sensitivities[static_cast<std::size_t>(i)] = sink.sensitivities();
    return true;
  }

  bool Evaluate(const double* point) {
    const int count = variables();
    if (!evaluated.empty() && std::equal(point, point + count, evaluated.begin())) return ok;
    evaluated.assign(point, point + count);
    ok = false;
    const NetworkSystem system = BuildAt(point);  // immutable: shared by the workers
    const int workers = static_cast<int>(simulations.size());
    std::vector<char> completed(static_cast<std::size_t>(intervals), 0);
    const auto work = [&](int w) {
      // interval i to worker i mod workers: neighbouring intervals cost alike
      for (int i = w; i < intervals; i += workers) {
        try {
          completed[static_cast<std::size_t>(i)] =
              Integrate(system, i, point, *simulations[static_cast<std::size_t>(w)]) ? 1 : 0;
        } catch (const std::exception&) {
          // a trial point the run refuses (a state that collapses an element): IPOPT steps
          // back from a point it cannot evaluate
          completed[static_cast<std::size_t>(i)] = 0;
        }
      }
    };
    std::vector<std::thread> threads;
    for (int w = 1; w < workers; ++w) threads.emplace_back(work, w);
    work(0);
    for (std::thread& thread : threads) thread.join();
    ok = std::all_of(completed.begin(), completed.end(), [](char c) { return c != 0; });
    return ok;
  }

  // Visits the constraint Jacobian's nonzeros in one fixed order, visit(row, column, value),
  // the values from the intervals' sensitivities when `with_values` (else 0).
  template <typename Visit>
  void WalkJacobian(bool with_values, Visit visit) const {
    const auto s = [&](int i, int parameter, int k) {
      if (!with_values) return 0.0;
      return sensitivities[static_cast<std::size_t>(i)]
                          [static_cast<std::size_t>(parameter * n + k)];
    };
    // the row of Phi_i's component k: by s_i (i >= 1) and the interval's two control values
    const auto interval_row = [&](int i, int row, int k) {
      if (i >= 1) {
        for (int q = 0; q < n; ++q) visit(row, StateIndex(i, q), s(i, q, k));
      }
      for (int j = 0; j < control_count(); ++j) {
        visit(row, ControlIndex(j, i), s(i, n + 2 * j, k));
        visit(row, ControlIndex(j, i + 1), s(i, n + 2 * j + 1, k));
      }
    };
    int row = 0;
    for (int i = 0; i + 1 < intervals; ++i) {
      for (int k = 0; k < n; ++k, ++row) {
        interval_row(i, row, k);
        visit(row, StateIndex(i + 1, k), -1.0);
      }
    }
    for (const int state : final_states) interval_row(intervals - 1, row++, state);
  }
};

MultipleShooting::MultipleShooting(const OptimalControlProblem& problem)
    : impl_(std::make_unique<Impl>()) {
  Impl& p = *impl_;
  p.scenario = problem.scenario;
  p.controls = problem.controls;
  p.finals = problem.final_values;
  p.intervals = problem.intervals;
  const NetworkSystem system = CheckProblem(problem, p.elements, p.final_states);
  p.n = system.state_size();
  p.initial.resize(static_cast<std::size_t>(p.n));
  system.InitialState(problem.scenario.t_start, p.initial.data());
  const double span = problem.scenario.t_end - problem.scenario.t_start;
  for (int i = 0; i <= p.intervals; ++i) {
    // the last point exactly t_end
    p.times.push_back(i == p.intervals ? problem.scenario.t_end
                                       : problem.scenario.t_start + span * i / p.intervals);
  }
  p.ends.resize(static_cast<std::size_t>(p.intervals));
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  for (int w = 0; w < std::min(cores, p.intervals); ++w) {
    p.simulations.push_back(std::make_unique<Simulation>());
  }
  p.sensitivities.resize(static_cast<std::size_t>(p.intervals));
}

MultipleShooting::~MultipleShooting() = default;

int MultipleShooting::variable_count() const { return impl_->variables(); }

int MultipleShooting::constraint_count() const {
  return (impl_->intervals - 1) * impl_->n + static_cast<int>(impl_->finals.size());
}

void MultipleShooting::VariableBounds(double* lower, double* upper) const {
  const Impl& p = *impl_;
  std::fill(lower, lower + p.variables(), -kNoBound);
  std::fill(upper, upper + p.variables(), kNoBound);
  for (int j = 0; j < p.control_count(); ++j) {
    for (int i = 0; i <= p.intervals; ++i) {
      lower[p.ControlIndex(j, i)] = p.controls[static_cast<std::size_t>(j)].lower;
      upper[p.ControlIndex(j, i)] = p.controls[static_cast<std::size_t>(j)].upper;
    }
  }
}

void MultipleShooting::ConstraintBounds(double* lower, double* upper) const {
  const Impl& p = *impl_;
  const int continuity = (p.intervals - 1) * p.n;
  std::fill(lower, lower + continuity, 0.0);
  std::fill(upper, upper + continuity, 0.0);
  for (std::size_t r = 0; r < p.finals.size(); ++r) {
    lower[continuity + static_cast<int>(r)] = p.finals[r].lower;
    upper[continuity + static_cast<int>(r)] = p.finals[r].upper;
  }
}

std::vector<double> MultipleShooting::StartingPoint() {
  Impl& p = *impl_;
  std::vector<double> x(static_cast<std::size_t>(p.variables()), 0.0);
  for (int j = 0; j < p.control_count(); ++j) {
    const ControlSpec& control = p.controls[static_cast<std::size_t>(j)];
    const Waveform& given =
        p.scenario.elements[static_cast<std::size_t>(p.elements[static_cast<std::size_t>(j)])]
            .activation;
    for (int i = 0; i <= p.intervals; ++i) {
      x[static_cast<std::size_t>(p.ControlIndex(j, i))] = std::clamp(
          given.Evaluate(p.times[static_cast<std::size_t>(i)]), control.lower, control.upper);
    }
  }
  // one run through the grid: each interval starts where the one before ended
  const NetworkSystem system = p.BuildAt(x.data());
  for (int i = 0; i + 1 < p.intervals; ++i) {
    if (!p.Integrate(system, i, x.data(), *p.simulations.front()))
      break;  // IPOPT starts from what there is
    std::copy(p.ends[static_cast<std::size_t>(i)].begin(),
              p.ends[static_cast<std::size_t>(i)].end(), x.begin() + p.StateIndex(i + 1, 0));
  }
  return x;
}

double MultipleShooting::Objective(const double* x) const {
  const Impl& p = *impl_;
  double total = 0.0;
  for (int j = 0; j < p.control_count(); ++j) {
    const ControlSpec& control = p.controls[static_cast<std::size_t>(j)];
    for (int i = 0; i < p.intervals; ++i) {
      const double h =
          p.times[static_cast<std::size_t>(i) + 1] - p.times[static_cast<std::size_t>(i)];
      total +=
          control.effort_weight * h *
          SegmentEffort(x[p.ControlIndex(j, i)], x[p.ControlIndex(j, i + 1)], control.effort_power)
              .value;
    }
  }
  return total;
}

void MultipleShooting::ObjectiveGradient(const double* x, double* gradient) const {
  const Impl& p = *impl_;
  std::fill(gradient, gradient + p.variables(), 0.0);
  for (int j = 0; j < p.control_count(); ++j) {
    const ControlSpec& control = p.controls[static_cast<std::size_t>(j)];
    for (int i = 0; i < p.intervals; ++i) {
      const double h =
          p.times[static_cast<std::size_t>(i) + 1] - p.times[static_cast<std::size_t>(i)];
      const Effort e =
          SegmentEffort(x[p.ControlIndex(j, i)], x[p.ControlIndex(j, i + 1)], control.effort_power);
      gradient[p.ControlIndex(j, i)] += control.effort_weight * h * e.by_start;
      gradient[p.ControlIndex(j, i + 1)] += control.effort_weight * h * e.by_end;
    }
  }
}

bool MultipleShooting::Constraints(const double* x, double* g) {
  Impl& p = *impl_;
  if (!p.Evaluate(x)) return false;
  int row = 0;
  for (int i = 0; i + 1 < p.intervals; ++i) {
    for (int k = 0; k < p.n; ++k) {
      g[row++] = p.ends[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] -
                 x[p.StateIndex(i + 1, k)];
    }
  }
  const std::vector<double>& last = p.ends.back();
  for (const int state : p.final_states) g[row++] = last[static_cast<std::size_t>(state)];
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

const std::vector<double>& MultipleShooting::times() const { return impl_->times; }

std::vector<double> MultipleShooting::ControlValues(const double* x, int j) const {
  std::vector<double> values;
  for (int i = 0; i <= impl_->intervals; ++i) values.push_back(x[impl_->ControlIndex(j, i)]);
  return values;
}

}  // namespace musclesim
