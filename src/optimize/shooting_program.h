// Private to optimize/: the state of one multiple-shooting program (MultipleShooting::Impl):
// the problem with its index of variables and constraints, the grid, each worker's
// simulation, the last point's interval results, and the walk of the constraint Jacobian's
// entries. multiple_shooting.cc is the program's face to IPOPT over it.
#pragma once

#include "musclesim/optimize/multiple_shooting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/solver/sensitivity.h"
#include "musclesim/solver/simulation.h"
#include "optimize/interval_recorder.h"
#include "optimize/problem_checks.h"
#include "optimize/shooting_parts.h"
#include "scenario/sensitivity_derivatives.h"

namespace musclesim {

struct MultipleShooting::Impl {
  OptimalControlProblem problem;
  ProblemIndex index;
  Scenario scenario;  // the problem's, set to the point being evaluated
  int n = 0;          // the state's size
  int intervals = 0;
  // one CVODE memory per worker thread: the intervals are integrated in parallel
  std::vector<std::unique_ptr<Simulation>> simulations;

  // The point last built: its system, initial state, resolved parameters and grid.
  struct Built {
    std::shared_ptr<const NetworkSystem> system;
    std::vector<double> initial;                             // s_0
    std::vector<std::vector<ResolvedParameter>> parameters;  // per worker
    std::vector<double> times;
    std::vector<IntervalPlan> plans;
  } built;

  // The last point integrated: its x, whether every interval completed, and per interval its
  // results and, with a free final time, the derivatives of Phi_i and of the columns in T.
  std::vector<double> evaluated;
  bool ok = false;
  std::vector<IntervalResult> results;
  std::vector<std::vector<double>> state_by_time, columns_by_time;
  bool quotients = false;            // difference quotients instead of sensitivities
  double integration_seconds = 0.0;  // wall time in the intervals' integrations

  int controls() const { return static_cast<int>(problem.controls.size()); }
  int parameters() const { return static_cast<int>(problem.parameters.size()); }
  bool free_time() const { return problem.final_time.has_value(); }
  int ControlIndex(int j, int i) const { return j * (intervals + 1) + i; }
  int StateIndex(int i, int k) const {  // s_i, i >= 1
    return controls() * (intervals + 1) + (i - 1) * n + k;
  }
  int ParameterIndex(int q) const { return controls() * (intervals + 1) + (intervals - 1) * n + q; }
  int TimeIndex() const { return ParameterIndex(parameters()); }
  int variables() const { return TimeIndex() + (free_time() ? 1 : 0); }
  // K: an interval's sensitivity parameters, s_i's components, its control values (start,
  // end per control), the free parameters
  int sensitivity_count() const { return n + 2 * controls() + parameters(); }
  // The variable interval i's sensitivity parameter k is, or -1 (s_0 is no variable).
  int VariableOf(int i, int k) const {
    if (k < n) return i >= 1 ? StateIndex(i, k) : -1;
    if (k < n + 2 * controls()) return ControlIndex((k - n) / 2, i + (k - n) % 2);
    return ParameterIndex(k - n - 2 * controls());
  }

  double FinalTime(const double* x) const {
    return free_time() ? x[TimeIndex()] : problem.scenario.t_end;
  }
  std::vector<double> Grid(double end) const {
    const double start = problem.scenario.t_start;
    std::vector<double> times;
    for (int i = 0; i <= intervals; ++i) {
      times.push_back(i == intervals ? end : start + (end - start) * i / intervals);
    }
    return times;
  }

  // `target` with x's controls as tables, its parameters and its final time (ParameterError
  // for parameters the scenario refuses).
  void Apply(const double* x, Scenario& target) const {
    const std::vector<double> times = Grid(FinalTime(x));
    if (parameters() > 0) {
      SetParameters(target, index.parameters,
                    std::vector<double>(x + ParameterIndex(0), x + ParameterIndex(parameters())));
    }
    target.t_end = times.back();
    for (int j = 0; j < controls(); ++j) {
      std::vector<TablePoint> points;
      for (int i = 0; i <= intervals; ++i) {
        // IPOPT keeps to the bounds; the clamp only guards the activation's range
        points.push_back(
            {times[static_cast<std::size_t>(i)], std::clamp(x[ControlIndex(j, i)], 0.0, 1.0)});
      }
      Element& element =
          target.elements[static_cast<std::size_t>(index.elements[static_cast<std::size_t>(j)])];
      if (element.excitation) {
        element.excitation->signal = Waveform::Table(std::move(points));
      } else {
        element.activation = Waveform::Table(std::move(points));
      }
    }
  }

  // The system at x, its initial state, its parameters resolved, its grid. False for a point
  // the scenario refuses.
  bool Build(const double* x) {
    try {
      Apply(x, scenario);
      BuiltScenario made = BuildScenario(scenario);
      built.system = made.system;
      built.initial = made.initial;
      // one resolution per worker: a difference quotient's derivative keeps scratch space
      // (a run is single-threaded), so workers must not share one
      built.parameters.clear();
      built.parameters.resize(simulations.size());
      for (std::vector<ResolvedParameter>& resolved : built.parameters) {
        for (int q = 0; q < parameters(); ++q) {
          resolved.push_back(ResolveParameter(scenario, made,
                                              index.parameters[static_cast<std::size_t>(q)],
                                              "parameters[" + std::to_string(q) + "].path"));
        }
      }
    } catch (const std::invalid_argument&) {  // ParameterError, InputError
      return false;
    }
    std::vector<double> times = Grid(FinalTime(x));
    if (times != built.times || built.plans.empty()) {
      built.plans = PlanIntervals(times, problem.tracking);
      built.times = std::move(times);
    }
    return true;
  }

  // Integrates interval i from s_i (read from x) into `out`, with the sensitivities unless
  // the derivatives are difference quotients.
  bool Integrate(int i, const double* x, int worker, IntervalResult& out) {
    Simulation& simulation = *simulations[static_cast<std::size_t>(worker)];
    const NetworkSystem& system = *built.system;
    const double t0 = built.times[static_cast<std::size_t>(i)];
    const double t1 = built.times[static_cast<std::size_t>(i) + 1];
    NetworkRunRequest request;
    request.t_start = t0;
    request.t_end = t1;
    request.output_times = built.plans[static_cast<std::size_t>(i)].times;
    request.initial_state =
        i == 0 ? built.initial
               : std::vector<double>(x + StateIndex(i, 0), x + StateIndex(i, 0) + n);
    std::vector<std::unique_ptr<ParameterDerivative>> derivatives;
    std::vector<SensitivityParameter> sensitivity;
    const std::vector<double> zero(static_cast<std::size_t>(n), 0.0);
    for (int k = 0; k < (quotients ? 0 : n); ++k) {
      derivatives.push_back(std::make_unique<InitialStateDerivative>(n));
      std::vector<double> unit = zero;
      unit[static_cast<std::size_t>(k)] = 1.0;
      sensitivity.push_back({derivatives.back().get(), std::move(unit), 1.0});
    }
    for (int j = 0; j < (quotients ? 0 : controls()); ++j) {
      const auto sj = static_cast<std::size_t>(j);
      const int element = index.elements[sj];
      for (const bool at_end : {false, true}) {
        std::vector<double> initial = zero;
        if (index.activation_states[sj] >= 0) {
          derivatives.push_back(
              std::make_unique<ExcitationValueDerivative>(system, element, t0, t1, at_end));
          if (i == 0 && !at_end && index.moves_start[sj] != 0) {
            initial[static_cast<std::size_t>(index.activation_states[sj])] = 1.0;
          }
        } else {
          derivatives.push_back(
              std::make_unique<ControlValueDerivative>(system, element, t0, t1, at_end));
        }
        sensitivity.push_back({derivatives.back().get(), std::move(initial), 1.0});
      }
    }
    for (const ResolvedParameter& p : built.parameters[static_cast<std::size_t>(worker)]) {
      if (quotients) break;
      // the parameter moves s_0 (a node's start, say), not a later s_i: that is a variable
      sensitivity.push_back({p.derivative.get(), i == 0 ? p.initial : zero,
                             p.value != 0.0 ? std::abs(p.value) : 1.0});
    }
    SensitivityColumns columns(problem.scenario.form, system, sensitivity);
    IntervalRecorder recorder(built.plans[static_cast<std::size_t>(i)], columns, index, n,
                              static_cast<int>(sensitivity.size()), out);
    const RunStats stats = simulation.Run(system, scenario.solver, request, sensitivity, recorder);
    return stats.status == RunStatus::kCompleted && recorder.complete();
  }

  // d Phi_i / dT and the columns' by the grid's stretch (docs/model.md 13.2): the end moves
  // by (i + 1) / N, the start by i / N, and the controls' kinks with them.
  void TimeDerivatives(const double* x) {
    const NetworkSystem& system = *built.system;
    const double T = built.times.back();
    const double h = (T - built.times.front()) / intervals;
    const auto sn = static_cast<std::size_t>(n);
    std::vector<double> f_end(sn), f_start(sn);
    state_by_time.assign(static_cast<std::size_t>(intervals), std::vector<double>(sn, 0.0));
    columns_by_time.assign(static_cast<std::size_t>(intervals),
                           std::vector<double>(index.columns.size(), 0.0));
    NetworkScratch scratch;
    for (int i = 0; i < intervals; ++i) {
      const IntervalResult& r = results[static_cast<std::size_t>(i)];
      const double a = static_cast<double>(i) / intervals,
                   b = static_cast<double>(i + 1) / intervals;
      system.RightHandSide(built.times[static_cast<std::size_t>(i) + 1], r.state.data(),
                           f_end.data(), scratch);
      if (i >= 1)
        system.RightHandSide(built.times[static_cast<std::size_t>(i)], x + StateIndex(i, 0),
                             f_start.data(), scratch);
      const auto S = [&](int parameter, int k) {
        return r.sensitivities[static_cast<std::size_t>(parameter * n + k)];
      };
      std::vector<double>& d = state_by_time[static_cast<std::size_t>(i)];
      for (int k = 0; k < n; ++k) {
        double value = b * f_end[static_cast<std::size_t>(k)];
        if (i >= 1) {
          for (int q = 0; q < n; ++q) value -= a * S(q, k) * f_start[static_cast<std::size_t>(q)];
        }
        for (int j = 0; j < controls(); ++j) {
          const double slope = (x[ControlIndex(j, i + 1)] - x[ControlIndex(j, i)]) / h;
          value -= slope * (a * S(n + 2 * j, k) + b * S(n + 2 * j + 1, k));
        }
        d[static_cast<std::size_t>(k)] = value;
      }
      for (std::size_t u = 0; u < index.columns.size(); ++u) {
        columns_by_time[static_cast<std::size_t>(i)][u] =
            index.column_signs[u] * d[static_cast<std::size_t>(index.column_states[u])];
      }
    }
  }

  void VariableBounds(double* lower, double* upper) const {
    const Impl& p = *this;
    std::fill(lower, lower + p.variables(), -kNoBound);
    std::fill(upper, upper + p.variables(), kNoBound);
    for (int j = 0; j < p.controls(); ++j) {
      for (int i = 0; i <= p.intervals; ++i) {
        lower[p.ControlIndex(j, i)] = p.problem.controls[static_cast<std::size_t>(j)].lower;
        upper[p.ControlIndex(j, i)] = p.problem.controls[static_cast<std::size_t>(j)].upper;
      }
    }
    for (int q = 0; q < p.parameters(); ++q) {
      lower[p.ParameterIndex(q)] = p.problem.parameters[static_cast<std::size_t>(q)].lower;
      upper[p.ParameterIndex(q)] = p.problem.parameters[static_cast<std::size_t>(q)].upper;
    }
    if (p.free_time()) {
      lower[p.TimeIndex()] = p.problem.final_time->lower;
      upper[p.TimeIndex()] = p.problem.final_time->upper;
    }
  }

  // Every interval at `point` (built) into `out`, on all the workers. False if one fails.
  bool IntegrateAll(const double* point, std::vector<IntervalResult>& out) {
    const auto start = std::chrono::steady_clock::now();
    const int workers = static_cast<int>(simulations.size());
    std::vector<char> completed(static_cast<std::size_t>(intervals), 0);
    const auto work = [&](int w) {
      // interval i to worker i mod workers: neighbouring intervals cost alike
      for (int i = w; i < intervals; i += workers) {
        try {
          completed[static_cast<std::size_t>(i)] =
              Integrate(i, point, w, out[static_cast<std::size_t>(i)]) ? 1 : 0;
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
    integration_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::all_of(completed.begin(), completed.end(), [](char c) { return c != 0; });
  }

  bool Evaluate(const double* point) {
    const int count = variables();
    if (!evaluated.empty() && std::equal(point, point + count, evaluated.begin())) return ok;
    evaluated.assign(point, point + count);
    ok = false;
    if (!Build(point)) return false;
    ok = IntegrateAll(point, results);
    if (ok && quotients) ok = DifferenceQuotients(point);
    if (ok && free_time() && !quotients) TimeDerivatives(point);
    return ok;
  }

  // The colour of interval i's sensitivity parameter k: variables of one colour move no
  // interval twice, so one evaluation per colour differences them all (K colours, and T).
  int ColourOf(int i, int k) const {
    if (k < n || k >= n + 2 * controls()) return k;
    const int j = (k - n) / 2, end = (k - n) % 2;
    return n + 2 * j + (i + end) % 2;
  }

  // The derivatives as forward differences, one evaluation per colour (what a user without
  // sensitivities would do, exploiting the structure): the comparison of docs/performance.md.
  bool DifferenceQuotients(const double* point) {
    const int K = sensitivity_count();
    const auto sn = static_cast<std::size_t>(n);
    const std::size_t U = index.columns.size();
    for (IntervalResult& r : results) {
      r.sensitivities.assign(static_cast<std::size_t>(K) * sn, 0.0);
      r.column_gradients.assign(static_cast<std::size_t>(K) * U, 0.0);
      r.tracking_gradient.assign(static_cast<std::size_t>(K), 0.0);
    }
    std::vector<double> lower(static_cast<std::size_t>(variables())),
        upper(static_cast<std::size_t>(variables()));
    VariableBounds(lower.data(), upper.data());
    // a step of sqrt(rtol): the integration's error over the step stays below the difference's
    const double relative = std::sqrt(std::max(scenario.solver.rtol, 1e-16));
    std::vector<double> moved(point, point + variables()), steps(moved.size(), 0.0);
    std::vector<IntervalResult> shifted(results.size());
    if (free_time()) {
      state_by_time.assign(static_cast<std::size_t>(intervals), {});
      columns_by_time.assign(static_cast<std::size_t>(intervals), {});
    }
    const int colours = K + (free_time() ? 1 : 0);
    for (int c = 0; c < colours; ++c) {
      std::copy(point, point + variables(), moved.begin());
      std::fill(steps.begin(), steps.end(), 0.0);
      const auto step = [&](int v) {
        const auto sv = static_cast<std::size_t>(v);
        double h = relative * std::max(1.0, std::abs(point[v]));
        if (point[v] + h > upper[sv]) h = -h;  // inward from an upper bound
        steps[sv] = h;
        moved[sv] = point[v] + h;
      };
      for (int i = 0; i < intervals; ++i) {
        for (int k = 0; k < K; ++k) {
          const int v = VariableOf(i, k);
          if (v >= 0 && ColourOf(i, k) == c) step(v);
        }
      }
      if (c == K) step(TimeIndex());
      if (!Build(moved.data()) || !IntegrateAll(moved.data(), shifted)) return false;
      for (int i = 0; i < intervals; ++i) {
        const auto si = static_cast<std::size_t>(i);
        IntervalResult& r = results[si];
        const IntervalResult& s = shifted[si];
        const auto difference = [&](double h, auto&& store) {
          for (std::size_t q = 0; q < sn; ++q) store.state(q, (s.state[q] - r.state[q]) / h);
          for (std::size_t u = 0; u < U; ++u) store.column(u, (s.columns[u] - r.columns[u]) / h);
          store.tracking((s.tracking - r.tracking) / h);
        };
        if (c == K) {
          struct {
            IntervalResult& r;
            std::vector<double>& states;
            std::vector<double>& columns;
            void state(std::size_t q, double d) { states[q] = d; }
            void column(std::size_t u, double d) { columns[u] = d; }
            void tracking(double) {}
          } by_time{r, state_by_time[si], columns_by_time[si]};
          by_time.states.assign(sn, 0.0);
          by_time.columns.assign(U, 0.0);
          difference(steps[static_cast<std::size_t>(TimeIndex())], by_time);
          continue;
        }
        for (int k = 0; k < K; ++k) {
          const int v = VariableOf(i, k);
          if (v < 0 || ColourOf(i, k) != c) continue;
          const auto sk = static_cast<std::size_t>(k);
          struct {
            IntervalResult& r;
            std::size_t k, n, U;
            void state(std::size_t q, double d) { r.sensitivities[k * n + q] = d; }
            void column(std::size_t u, double d) { r.column_gradients[k * U + u] = d; }
            void tracking(double d) { r.tracking_gradient[k] = d; }
          } by_parameter{r, sk, sn, U};
          difference(steps[static_cast<std::size_t>(v)], by_parameter);
        }
      }
    }
    return Build(point);  // the point's own system and grid again
  }

  // Visits interval i's derivatives of one quantity: visit(variable, value) for each of its
  // sensitivity parameters that is a variable, `of(k)` the derivative by parameter k, and
  // `by_time` the one by T (with a free final time).
  template <typename Of, typename Visit>
  void VisitInterval(int i, Of of, double by_time, Visit visit) const {
    for (int k = 0; k < sensitivity_count(); ++k) {
      const int variable = VariableOf(i, k);
      if (variable >= 0) visit(variable, of(k));
    }
    if (free_time()) visit(TimeIndex(), by_time);
  }

  // Visits the constraint Jacobian's nonzeros in one fixed order, visit(row, column, value),
  // the values from the intervals' sensitivities when `with_values` (else 0).
  template <typename Visit>
  void WalkJacobian(bool with_values, Visit visit) const {
    const auto U = index.columns.size();
    const auto column_row = [&](int i, int row, int u) {
      const IntervalResult* r = with_values ? &results[static_cast<std::size_t>(i)] : nullptr;
      const auto su = static_cast<std::size_t>(u);
      VisitInterval(
          i,
          [&](int k) {
            return r != nullptr ? r->column_gradients[static_cast<std::size_t>(k) * U + su] : 0.0;
          },
          with_values && free_time() ? columns_by_time[static_cast<std::size_t>(i)][su] : 0.0,
          [&](int column, double value) { visit(row, column, value); });
    };
    int row = 0;
    for (int i = 0; i + 1 < intervals; ++i) {
      const IntervalResult* r = with_values ? &results[static_cast<std::size_t>(i)] : nullptr;
      for (int k = 0; k < n; ++k, ++row) {
        VisitInterval(
            i,
            [&](int q) {
              return r != nullptr ? r->sensitivities[static_cast<std::size_t>(q * n + k)] : 0.0;
            },
            with_values && free_time()
                ? state_by_time[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)]
                : 0.0,
            [&](int column, double value) { visit(row, column, value); });
        visit(row, StateIndex(i + 1, k), -1.0);
      }
    }
    for (const int u : index.finals) column_row(intervals - 1, row++, u);
    for (const int u : index.paths) {
      for (int i = 0; i < intervals; ++i) column_row(i, row++, u);
    }
  }
};

}  // namespace musclesim
