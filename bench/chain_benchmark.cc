// Cost of a chain of N soft actuators in series (docs/model.md section 7) against N, per linear
// solver of the Newton iteration (dense, band, KLU sparse): how a run's cost grows with the
// network. Node 0 is fixed; segment i is an actuator of scenarios/isometric.yaml's model in
// parallel with a light damper between nodes i - 1 and i; every free node carries 1 g; a constant
// load of f_iso pulls the free end. The chain starts at rest where the passive tension holds the
// load; the activation steps from 0 to 1 at t = 0.05 s (the scenario's) and every segment
// shortens a few millimetres, staying above its passive slack length (so no segment crosses its
// kink and restarts the integrator: the steps stay comparable across N). Runs to 0.5 s at
// rtol 1e-6 (the scenario's solver). Counters per run: steps, RHS and Jacobian evaluations,
// linear setups (factorisations), and the wall time per internal step. A run over kBudgetSeconds
// is stopped and the case skipped with a message saying so (dense at N = 1000 on a small machine).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/io/scenario.h"

namespace musclesim {
namespace {

constexpr double kNodeMass = 1e-3;  // [kg] a small lumped mass per free node
// [N s/m] light: about 1.6% of one segment's critical damping 2 sqrt(k m) at the start, where
// the passive stiffness is k = alpha (T_p + k_p) = 1.01e4 N/m
constexpr double kDamping = 0.1;
constexpr double kBudgetSeconds = 20.0;  // a run longer than this is stopped and reported
constexpr double kRecordInterval = 0.01;  // [s] records are cheap next to the integration

const LinearSolverKind kSolvers[] = {LinearSolverKind::kDense, LinearSolverKind::kBand,
                                     LinearSolverKind::kSparse};

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
  const ScenarioSpec spec =
      LoadScenario(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/isometric.yaml");
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

// args: segments N, linear solver (0 dense, 1 band, 2 sparse)
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
  if (stats.status != RunStatus::kCompleted) state.SkipWithError(stats.message.c_str());
  const double runs = static_cast<double>(state.iterations());
  state.counters["states"] = chain.system.state_size();
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["rhs"] = static_cast<double>(stats.rhs_evals);
  state.counters["jac"] = static_cast<double>(stats.jac_evals);
  state.counters["setups"] = static_cast<double>(stats.linear_setups);
  // seconds of wall time per internal step (printed with an SI prefix: 1.2u is 1.2 us)
  state.counters["time_per_step"] = benchmark::Counter(
      static_cast<double>(stats.steps) * runs, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(stats.steps * state.iterations());
}
BENCHMARK(BM_ChainRun)
    ->ArgsProduct({{1, 10, 100, 1000}, {0, 1, 2}})
    ->ArgNames({"N", "solver"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace musclesim
