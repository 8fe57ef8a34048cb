// Cost of a chain of N soft actuators in series (docs/model.md section 7) against N, per linear
// solver of the Newton iteration (dense, band, KLU sparse, and musclesim's own `small` where the
// chain has at most kSmallSystemMaxSize states): how a run's cost grows with the network. Node 0
// is fixed; segment i is an actuator of scenarios/isometric.yaml's model in parallel with a
// light damper between nodes i - 1 and i; every free node carries 1 g; a constant load of f_iso
// pulls the free end. The chain starts at rest where the passive tension holds the load; the
// activation steps from 0 to 1 at t = 0.05 s (the scenario's) and every segment shortens a few
// millimetres, staying above its passive slack length (so no segment crosses its kink and
// restarts the integrator: the steps stay comparable across N). Runs to 0.5 s at the scenario's
// rtol 1e-6, atol 1e-10. Counters per run: steps, RHS and Jacobian evaluations, linear setups
// (factorisations), the wall time per internal step, and `error`: the final state's largest
// relative difference from a reference run at rtol 1e-10 (see MaxRelativeDifference). A run over
// kBudgetSeconds is stopped and the case skipped with a message saying so (dense at N = 1000 on
// a small machine).
//
// With Boost (BM_ChainOdeint), the same chain through Boost.Odeint's rosenbrock4 with dense
// ublas matrices, as a careful Odeint user would write it: make_dense_output at the same rtol
// and atol, integrate_times over the same output grid, segment by segment between the inputs'
// breakpoints, the analytic Jacobian scattered into a dense matrix, df/dt = 0 (the inputs are
// constant between breakpoints). Its counters are the same (steps: accepted steps; jac and
// setups: attempted steps, each with its Jacobian and LU) and `vs_cvode`, the final state's
// largest relative difference from CVODE's at the same tolerances.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#ifdef MUSCLESIM_WITH_ODEINT
#include "work_precision/odeint_network.h"
#include "work_precision/odeint_peer.h"
#endif

namespace musclesim {
namespace {

constexpr double kNodeMass = 1e-3;  // [kg] a small lumped mass per free node
// [N s/m] light: about 1.6% of one segment's critical damping 2 sqrt(k m) at the start, where
// the passive stiffness is k = alpha (T_p + k_p) = 1.01e4 N/m
constexpr double kDamping = 0.1;
constexpr double kBudgetSeconds = 20.0;   // a run longer than this is stopped and reported
constexpr double kRecordInterval = 0.01;  // [s] records are cheap next to the integration

const LinearSolverKind kSolvers[] = {LinearSolverKind::kDense, LinearSolverKind::kBand,
                                     LinearSolverKind::kSparse, LinearSolverKind::kSmall};
constexpr int kSmallSolverIndex = 3;
const int kSegments[] = {1, 10, 100, 1000};
// the reference for `error`: 1e4 times tighter than the runs measured, so its own error is
// negligible next to theirs
constexpr double kReferenceRtol = 1e-10;
constexpr double kReferenceAtol = 1e-14;

// The chain's parts, built from scenarios/isometric.yaml's model, activation and solver.
struct Chain {
  NetworkSystem system;
  SolverOptions options;
  NetworkRunRequest request;
};

// "n3", "actuator3": appended rather than concatenated, which GCC 12 misreads (-Wrestrict)
std::string Numbered(const char* prefix, int i) {
  std::string name(prefix);
  name += std::to_string(i);
  return name;
}

Chain MakeChain(int segments) {
  const ActuatorScenarioSpec spec =
      LoadActuatorScenarioSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/isometric.yaml");
  const auto model = std::make_shared<const TensionModel>(spec.model.params);
  const PassiveParams& passive = spec.model.params.passive;
  const double load = spec.model.params.f_iso;  // [N]
  // at rest with u = 0 every segment carries the load on its passive element alone (MODEL.md
  // section 2): k_p (exp(alpha (l - x0)) - 1) = load
  const double length = passive.slack_length + std::log1p(load / passive.k_p) / passive.alpha;

  std::vector<Node> nodes = {Node::Fixed("n0", 0.0)};
  std::vector<Element> elements;
  for (int i = 1; i <= segments; ++i) {
    const std::string node = Numbered("n", i), previous = Numbered("n", i - 1);
    nodes.push_back(Node::Free(node, kNodeMass, i * length));
    elements.push_back(
        Element::Actuator(Numbered("actuator", i), previous, node, model, spec.activation));
    elements.push_back(Element::Damper(Numbered("damper", i), previous, node, kDamping));
  }
  std::vector<NodeLoad> loads = {{nodes.back().name, Load::Constant(load)}};

  NetworkRunRequest request;
  request.t_start = spec.t_start;
  request.t_end = spec.t_end;
  request.output_interval = kRecordInterval;
  return {NetworkSystem(std::move(nodes), std::move(elements), std::move(loads)), spec.solver,
          request};
}

// Thrown by BudgetSink when a run has taken longer than its budget.
struct OverBudget : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Keeps the free end's position (the run's result) and stops a run that is over budget.
class BudgetSink final : public NetworkSink {
 public:
  BudgetSink() : start_(std::chrono::steady_clock::now()) {}
  void Record(double t, const NetworkSample& sample) override {
    end_position = sample.position.back();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (seconds > kBudgetSeconds) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "skipped: one run takes over %g s (stopped at t = %g s of the run)",
                    kBudgetSeconds, t);
      throw OverBudget(message);
    }
  }
  double end_position = 0.0;  // [m]

 private:
  std::chrono::steady_clock::time_point start_;
};

// Keeps the state at the last output time (the run's end).
class FinalStateSink final : public NetworkSink {
 public:
  explicit FinalStateSink(int size) : size_(size) {}
  void Record(double, const NetworkSample&) override {}
  bool RecordState(double /*t*/, const double* y) override {
    state.assign(y, y + size_);
    return true;
  }
  std::vector<double> state;

 private:
  int size_;
};

// The final state of one CVODE run of the chain with `options`.
std::vector<double> FinalState(const Chain& chain, const SolverOptions& options) {
  Simulation simulation;
  FinalStateSink sink(chain.system.state_size());
  const RunStats stats = simulation.Run(chain.system, options, chain.request, sink);
  if (stats.status != RunStatus::kCompleted) throw std::runtime_error(stats.message);
  return sink.state;
}

// The final state of a run at kReferenceRtol (band: banded at every N), once per N.
const std::vector<double>& ReferenceState(const Chain& chain, int segments) {
  static std::map<int, std::vector<double>> references;
  auto found = references.find(segments);
  if (found == references.end()) {
    SolverOptions tight = chain.options;
    tight.rtol = kReferenceRtol;
    tight.atol = kReferenceAtol;
    tight.linear_solver = LinearSolverKind::kBand;
    found = references.emplace(segments, FinalState(chain, tight)).first;
  }
  return found->second;
}

// max_i |a_i - b_i| / max(|b_i|, atol / rtol): the relative difference, where a state is below
// atol / rtol (a velocity near rest) measured against that floor, where the error control stops
// being relative. Comparable with rtol.
double MaxRelativeDifference(const std::vector<double>& a, const std::vector<double>& b,
                             const SolverOptions& options) {
  if (a.size() != b.size()) return INFINITY;
  const double floor = options.atol / options.rtol;
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), floor));
  }
  return worst;
}

// Counters that BM_ChainRun and BM_ChainOdeint share.
void SetRunCounters(benchmark::State& state, int states, long steps, long rhs, long jac,
                    long setups) {
  const double runs = static_cast<double>(state.iterations());
  state.counters["states"] = states;
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["rhs"] = static_cast<double>(rhs);
  state.counters["jac"] = static_cast<double>(jac);
  state.counters["setups"] = static_cast<double>(setups);
  // seconds of wall time per internal step (printed with an SI prefix: 1.2u is 1.2 us)
  state.counters["time_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * runs, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(steps * state.iterations());
}

// args: segments N, linear solver (0 dense, 1 band, 2 sparse, 3 small)
void BM_ChainRun(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  Chain chain = MakeChain(segments);
  chain.options.linear_solver = kSolvers[state.range(1)];
  state.SetLabel("N=" + std::to_string(segments) + " " +
                 std::string(ToString(chain.options.linear_solver)));
  Simulation simulation;
  RunStats stats;
  try {
    // one untimed run allocates the CVODE memory and the linear solver
    BudgetSink warm_up;
    stats = simulation.Run(chain.system, chain.options, chain.request, warm_up);
  } catch (const OverBudget& e) {
    state.SkipWithError(e.what());  // the timed loop then runs no iteration
    return;
  }
  for (auto _ : state) {
    BudgetSink sink;
    stats = simulation.Run(chain.system, chain.options, chain.request, sink);
    benchmark::DoNotOptimize(sink.end_position);
  }
  if (stats.status != RunStatus::kCompleted) {
    state.SkipWithError(stats.message.c_str());
    return;
  }
  SetRunCounters(state, chain.system.state_size(), stats.steps, stats.rhs_evals, stats.jac_evals,
                 stats.linear_setups);
  state.counters["error"] = MaxRelativeDifference(FinalState(chain, chain.options),
                                                  ReferenceState(chain, segments), chain.options);
}
// every N with every solver but small, which only where it applies (2N states)
void ChainCases(benchmark::internal::Benchmark* b) {
  for (int segments : kSegments) {
    for (int solver = 0; solver <= kSmallSolverIndex; ++solver) {
      if (solver == kSmallSolverIndex && 2 * segments > kSmallSystemMaxSize) continue;
      b->Args({segments, solver});
    }
  }
}
BENCHMARK(BM_ChainRun)
    ->Apply(ChainCases)
    ->ArgNames({"N", "solver"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

#ifdef MUSCLESIM_WITH_ODEINT

// One Odeint run of the chain at the chain's rtol and atol, on the CVODE runs' output grid
// (t_start + k * output_interval, then t_end), restarting at every breakpoint of the inputs.
// Returns the final state; throws OverBudget past kBudgetSeconds.
std::vector<double> RunOdeint(const Chain& chain, OdeintCounts& counts) {
  const auto start = std::chrono::steady_clock::now();
  const NetworkSystem& system = chain.system;
  const NetworkRunRequest& request = chain.request;
  OdeintNetwork context{&system, std::vector<double>(system.jacobian_pattern().entries())};
  const NStateProblem problem{system.state_size(), &context, &OdeintNetwork::Rhs,
                              &OdeintNetwork::DenseJacobian};
  std::vector<double> y(system.state_size());
  system.InitialState(request.t_start, y.data());

  const double span = request.t_end - request.t_start;
  const long outputs = static_cast<long>(std::ceil(span / request.output_interval - 1e-9));
  std::vector<double> grid;
  for (long k = 1; k < outputs; ++k) grid.push_back(request.t_start + k * request.output_interval);
  std::vector<double> stops = system.Breakpoints(request.t_start, request.t_end);
  stops.push_back(request.t_end);
  const double same = 1e-12 * span;  // a grid time this close to a stop is the stop
  const auto observe = [&](double t, const double*) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        kBudgetSeconds) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "skipped: one run takes over %g s (stopped at t = %g s of the run)",
                    kBudgetSeconds, t);
      throw OverBudget(message);
    }
  };
  double t0 = request.t_start;
  for (double stop : stops) {
    std::vector<double> times = {t0};
    for (double t : grid) {
      if (t > t0 + same && t < stop - same) times.push_back(t);
    }
    times.push_back(stop);
    OdeintSegmentN(problem, chain.options.rtol, chain.options.atol, y.data(), times, observe,
                   counts);
    t0 = stop;
  }
  return y;
}

// args: segments N
void BM_ChainOdeint(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const Chain chain = MakeChain(segments);
  state.SetLabel("N=" + std::to_string(segments) + " rosenbrock4-dense");
  OdeintCounts counts;
  std::vector<double> final_state;
  try {
    final_state = RunOdeint(chain, counts);  // untimed, as BM_ChainRun's first run
  } catch (const OverBudget& e) {
    state.SkipWithError(e.what());
    return;
  }
  for (auto _ : state) {
    counts = OdeintCounts();
    final_state = RunOdeint(chain, counts);
    benchmark::DoNotOptimize(final_state.data());
  }
  SetRunCounters(state, chain.system.state_size(), counts.steps, counts.rhs_evals, counts.jac_evals,
                 counts.jac_evals);
  state.counters["error"] =
      MaxRelativeDifference(final_state, ReferenceState(chain, segments), chain.options);
  state.counters["vs_cvode"] =
      MaxRelativeDifference(final_state, FinalState(chain, chain.options), chain.options);
}
// dense LU on 2N states every attempted step: N = 1000 would take minutes per run
BENCHMARK(BM_ChainOdeint)
    ->ArgsProduct({{1, 10, 100}})
    ->ArgNames({"N"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace musclesim
