// Cost of spatial networks against their size (docs/model.md section 12): an N x N lattice of
// point masses in the plane and a chain of N nodes in space, integrated for a fixed simulated
// time with the sparse (KLU) linear solver and, for comparison, the band solver: how the cost
// per internal step and per simulated second grows with the number of nodes.
//
// The lattice: nodes (i, j), i, j = 0 .. N-1, spaced h = 0.1 m (the actuators' optimal length,
// so that they work on their force-length curve), 10 g each, the bottom row j = 0 fixed,
// gravity -9.81 m/s^2 along y. Vertical links and both diagonals of every cell are springs of
// 1e3 N/m at rest at their initial length (each row is held by the row below: the lattice is
// rigid); every horizontal link is an actuator of scenarios/isometric.yaml's model scaled to
// f_iso = 1 N, its activation 0.5 + 0.5 sin(2 pi 5 t). The lattice sags under gravity and
// its rows squeeze and relax with the activation.
// The chain: N nodes along x, spaced 0.1 m on a small helix (so that it is not planar), both
// ends fixed; springs of 1e3 N/m at 90% of their initial length (taut), each with a 0.05 N s/m
// damper beside it, gravity -9.81 m/s^2 along z: it sags and swings.
//
// Both run 0.05 s (the lattice's sag under gravity and a quarter period of its activation) at
// rtol 1e-6, atol 1e-9, analytic Jacobian, with a record every 0.01 s (taken straight from the
// state: cheap). A run of the largest lattice takes about a minute on a small machine, so each
// case runs once, without an untimed first run (CVODE's allocations are negligible next to
// such runs). Counters: nodes, states, steps, RHS and Jacobian evaluations, linear setups
// (factorisations), and the time per step, per simulated second and per step and node. A run
// over kBudgetSeconds is stopped and the case skipped; band at N = 60 is not run (14160 states
// of bandwidth 493: its LU takes about a second per factorisation).
// BM_LatticeEvaluation times one right-hand side and one Jacobian of the lattice alone.
//   args: N, network (0 lattice, 1 chain), linear solver (0 sparse, 1 band)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#ifdef MUSCLESIM_WITH_KLU
#include <klu.h>
#endif

namespace musclesim {
namespace {

constexpr double kSpacing = 0.1;        // [m]
constexpr double kNodeMass = 0.01;      // [kg]
constexpr double kStiffness = 1e3;      // [N/m]
constexpr double kChainDamping = 0.05;  // [N s/m]
constexpr double kGravity = -9.81;      // [m/s^2]
constexpr double kSimulated = 0.05;     // [s] simulated per run
constexpr double kBudgetSeconds = 120.0;
const LinearSolverKind kSolvers[] = {LinearSolverKind::kSparse, LinearSolverKind::kBand};
const char* const kNetworks[] = {"lattice2d", "chain3d"};

// "n3_4": appended rather than concatenated, which GCC 12 misreads (-Wrestrict)
std::string Name(const char* prefix, int i, int j = -1) {
  std::string name(prefix);
  name.append(std::to_string(i));
  if (j >= 0) name.append("_").append(std::to_string(j));
  return name;
}

double Distance(const Coordinates& a, const Coordinates& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// isometric.yaml's model with f_iso = 1 N: a tension of the springs' order
std::shared_ptr<const TensionModel> ActuatorModel() {
  ModelParams params =
      LoadActuatorScenarioSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/isometric.yaml")
          .model.params;
  params.f_iso = 1.0;
  return std::make_shared<const TensionModel>(params);
}

NetworkSystem Lattice(int n) {
  const auto model = ActuatorModel();
  std::vector<Node> nodes;
  std::vector<Coordinates> at;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Coordinates p{i * kSpacing, j * kSpacing, 0.0};
      nodes.push_back(j == 0 ? Node::Fixed(Name("n", i, j), p)
                             : Node::Free(Name("n", i, j), kNodeMass, p));
      at.push_back(p);
    }
  }
  const auto index = [n](int i, int j) { return static_cast<std::size_t>(j * n + i); };
  std::vector<Element> elements;
  const auto spring = [&](const char* kind, int i0, int j0, int i1, int j1) {
    const std::size_t a = index(i0, j0), b = index(i1, j1);
    elements.push_back(Element::Spring(Name(kind, static_cast<int>(elements.size())), nodes[a].name,
                                       nodes[b].name, kStiffness, Distance(at[a], at[b])));
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n && j > 0) {  // the bottom row is fixed: no element between fixed nodes
        elements.push_back(Element::Actuator(Name("a", i, j), nodes[index(i, j)].name,
                                             nodes[index(i + 1, j)].name, model,
                                             Waveform::Sine(0.5, 0.5, 5.0)));
      }
      if (j + 1 < n) {
        spring("v", i, j, i, j + 1);
        if (i + 1 < n) {
          spring("d", i, j, i + 1, j + 1);
          spring("e", i + 1, j, i, j + 1);
        }
      }
    }
  }
  return NetworkSystem(std::move(nodes), std::move(elements), {}, {},
                       Space{2, {0.0, kGravity, 0.0}});
}

NetworkSystem Chain(int n) {
  std::vector<Node> nodes;
  std::vector<Coordinates> at;
  for (int i = 0; i < n; ++i) {
    const Coordinates p{i * kSpacing, 0.01 * std::cos(0.5 * i), 0.01 * std::sin(0.5 * i)};
    nodes.push_back(i == 0 || i + 1 == n ? Node::Fixed(Name("n", i), p)
                                         : Node::Free(Name("n", i), kNodeMass, p));
    at.push_back(p);
  }
  std::vector<Element> elements;
  for (int i = 0; i + 1 < n; ++i) {
    const double length =
        Distance(at[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(i + 1)]);
    elements.push_back(Element::Spring(Name("s", i), nodes[static_cast<std::size_t>(i)].name,
                                       nodes[static_cast<std::size_t>(i + 1)].name, kStiffness,
                                       0.9 * length));
    elements.push_back(Element::Damper(Name("c", i), nodes[static_cast<std::size_t>(i)].name,
                                       nodes[static_cast<std::size_t>(i + 1)].name, kChainDamping));
  }
  return NetworkSystem(std::move(nodes), std::move(elements), {}, {},
                       Space{3, {0.0, 0.0, kGravity}});
}

struct OverBudget : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Records nothing (straight from the state, so no sample is observed) and stops a run over
// its budget.
class BudgetSink final : public NetworkSink {
 public:
  BudgetSink() : start_(std::chrono::steady_clock::now()) {}
  void Record(double, const NetworkSample&) override {}
  bool RecordState(double t, const double* y) override {
    benchmark::DoNotOptimize(y[0]);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (seconds > kBudgetSeconds) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "skipped: one run takes over %g s (stopped at t = %g s of the run)",
                    kBudgetSeconds, t);
      throw OverBudget(message);
    }
    return true;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

void BM_SpatialRun(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int network = static_cast<int>(state.range(1));
  const NetworkSystem system = network == 0 ? Lattice(n) : Chain(n);
  SolverOptions options;
  options.rtol = 1e-6;
  options.atol = 1e-9;
  options.linear_solver = kSolvers[state.range(2)];
  NetworkRunRequest request;
  request.t_start = 0.0;
  request.t_end = kSimulated;
  request.output_interval = 0.01;
  const int nodes = static_cast<int>(system.nodes().size());
  state.SetLabel(std::string(kNetworks[network]) + " N=" + std::to_string(n) + " nodes=" +
                 std::to_string(nodes) + " " + std::string(ToString(options.linear_solver)));
  Simulation simulation;
  RunStats stats;
  for (auto _ : state) {
    try {
      BudgetSink sink;
      stats = simulation.Run(system, options, request, sink);
    } catch (const OverBudget& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  if (stats.status != RunStatus::kCompleted) {
    state.SkipWithError(stats.message.c_str());
    return;
  }
  const double runs = static_cast<double>(state.iterations());
  const double steps = static_cast<double>(stats.steps);
  state.counters["nodes"] = nodes;
  state.counters["states"] = system.state_size();
  state.counters["steps"] = steps;
  state.counters["rhs"] = static_cast<double>(stats.rhs_evals);
  state.counters["jac"] = static_cast<double>(stats.jac_evals);
  state.counters["setups"] = static_cast<double>(stats.linear_setups);
  // seconds of wall time per step, per simulated second and per step and node (kInvert of a
  // rate: printed with an SI prefix, 1.2u is 1.2 us)
  const auto per = [&](double count) {
    return benchmark::Counter(count * runs,
                              benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  };
  state.counters["time_per_step"] = per(steps);
  state.counters["time_per_simulated_s"] = per(kSimulated);
  state.counters["time_per_step_node"] = per(steps * nodes);
}
void Cases(benchmark::internal::Benchmark* b) {
  for (int network : {0, 1}) {
    for (int n : {5, 10, 20, 30, 40, 60}) {
      for (int solver : {0, 1}) {
        if (network == 0 && n == 60 && solver == 1) continue;  // see the top
        b->Args({n, network, solver});
      }
    }
  }
}
BENCHMARK(BM_SpatialRun)
    ->Apply(Cases)
    ->ArgNames({"N", "network", "solver"})
    ->UseRealTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// One right-hand side (0) or one analytic Jacobian (1) of the lattice at its initial state:
// the model's share of a step, apart from the linear algebra, per node. Also the Jacobian's
// structural entries and bandwidths (what the linear solvers factor).
//   args: N, evaluation
void BM_LatticeEvaluation(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const NetworkSystem system = Lattice(n);
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  std::vector<double> out(
      static_cast<std::size_t>(std::max(system.state_size(), system.jacobian_pattern().entries())));
  system.InitialState(0.0, y.data());
  const bool jacobian = state.range(1) == 1;
  state.SetLabel(std::string(jacobian ? "jacobian" : "rhs") + " N=" + std::to_string(n));
  double t = 0.01;
  for (auto _ : state) {
    if (jacobian) {
      system.Jacobian(t, y.data(), out.data());
    } else {
      system.RightHandSide(t, y.data(), out.data());
    }
    benchmark::DoNotOptimize(out.data());
    t += 1e-9;
  }
  const double nodes = static_cast<double>(system.nodes().size());
  const JacobianPattern& pattern = system.jacobian_pattern();
  state.counters["nodes"] = nodes;
  state.counters["states"] = pattern.size;
  state.counters["entries"] = pattern.entries();
  state.counters["bandwidth"] = pattern.lower_bandwidth + pattern.upper_bandwidth + 1;
  state.counters["time_per_node"] =
      benchmark::Counter(nodes * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_LatticeEvaluation)
    ->ArgsProduct({{5, 10, 20, 30, 40, 60}, {0, 1}})
    ->ArgNames({"N", "evaluation"})
    ->Unit(benchmark::kMicrosecond);

#ifdef MUSCLESIM_WITH_KLU
// What KLU makes of the lattice's Newton matrix M = I - gamma J (gamma = 1e-4 s, J at the
// initial state, the pattern CVODE's sparse solver is given) with KLU's orderings: the time of
// one klu_factor after klu_analyze, the entries of L + U (fill) and KLU's flop count. SUNDIALS'
// KLU wrapper orders with COLAMD (sunlinsol_klu.h: SUNKLU_ORDERING_DEFAULT 1) unless told
// otherwise (SUNLinSol_KLUSetOrdering).
//   args: N, ordering (0 AMD, 1 COLAMD)
void BM_LatticeKluFactor(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const NetworkSystem system = Lattice(n);
  const JacobianPattern& pattern = system.jacobian_pattern();
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  std::vector<double> values(static_cast<std::size_t>(pattern.entries()));
  system.InitialState(0.0, y.data());
  system.Jacobian(0.01, y.data(), values.data());
  const double gamma = 1e-4;
  std::vector<int> starts(pattern.column_starts.begin(), pattern.column_starts.end());
  std::vector<int> rows(pattern.rows.begin(), pattern.rows.end());
  for (double& v : values) v *= -gamma;
  for (int c = 0; c < pattern.size; ++c) {
    for (int k = starts[static_cast<std::size_t>(c)]; k < starts[static_cast<std::size_t>(c) + 1];
         ++k) {
      if (rows[static_cast<std::size_t>(k)] == c) values[static_cast<std::size_t>(k)] += 1.0;
    }
  }
  klu_common common;
  klu_defaults(&common);
  common.ordering = static_cast<int>(state.range(1));
  state.SetLabel(std::string(common.ordering == 0 ? "amd" : "colamd") + " N=" + std::to_string(n));
  klu_symbolic* symbolic = klu_analyze(pattern.size, starts.data(), rows.data(), &common);
  klu_numeric* numeric = nullptr;
  for (auto _ : state) {
    if (numeric != nullptr) klu_free_numeric(&numeric, &common);
    numeric = klu_factor(starts.data(), rows.data(), values.data(), symbolic, &common);
  }
  if (numeric == nullptr) {
    state.SkipWithError("klu_factor failed");
  } else {
    klu_flops(symbolic, numeric, &common);
    state.counters["nodes"] = static_cast<double>(system.nodes().size());
    state.counters["entries"] = pattern.entries();
    state.counters["lu_entries"] = static_cast<double>(numeric->lnz + numeric->unz);
    state.counters["flops"] = common.flops;
    klu_free_numeric(&numeric, &common);
  }
  klu_free_symbolic(&symbolic, &common);
}
BENCHMARK(BM_LatticeKluFactor)
    ->ArgsProduct({{5, 10, 20, 30, 40, 60}, {0, 1}})
    ->ArgNames({"N", "ordering"})
    ->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace musclesim
