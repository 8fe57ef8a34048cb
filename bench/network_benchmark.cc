// What a single actuator costs through its network (docs/model.md 7.4) against the direct
// ActuatorSystem path, per callback CVODE makes: the right-hand side, the Jacobian and the
// observation recorded at every output. Each pair evaluates the same system at the same states,
// so the difference is the network's bookkeeping. The "bare" network is the same system without
// the damper and spring elements the canonical scenarios leave at zero: what dropping them would
// save. Whole runs then split the single actuator's cost between the ActuatorSystem wrapper and
// the network's elements.
//   args: scenario (0 isometric, 1 concentric, 2 eccentric)
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/io/readers/scenario_yaml.h"

namespace musclesim {
namespace {

const char* const kScenarios[] = {"isometric", "concentric", "eccentric"};

ActuatorScenarioSpec Spec(const benchmark::State& state) {
  return LoadActuatorScenarioSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" +
                                  kScenarios[state.range(0)] + ".yaml");
}

ActuatorSystem Canonical(const benchmark::State& state) {
  const ActuatorScenarioSpec s = Spec(state);
  return MakeActuatorSystem(s);
}

// The single actuator's network without its damper and spring (zero in the canonical
// scenarios), as ActuatorSystem::network() lays it out otherwise.
NetworkSystem Bare(const ActuatorScenarioSpec& s) {
  std::vector<NodeLoad> loads;
  for (const Load& load : s.loads) loads.push_back({"tip", load});
  return NetworkSystem(
      {Node::Fixed("ground", 0.0), Node::Free("tip", s.actuator.mass, 0.0)},
      {Element::Actuator("actuator", "ground", "tip",
                         std::make_shared<const TensionModel>(s.model.params), s.activation)},
      std::move(loads));
}

// Active, near the initial length, shortening slowly: a state of the runs' second phase. The
// length creeps and the velocity flips sign so no evaluation repeats the last one.
struct State {
  double t = 0.2, x = 0.1, xdot = -0.01;
  void Next() {
    x += 1e-9;
    xdot = -xdot;
  }
};

void BM_ActuatorAcceleration(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  State s;
  for (auto _ : state) {
    benchmark::DoNotOptimize(system.Acceleration(s.t, s.x, s.xdot));
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ActuatorAcceleration)->DenseRange(0, 2);

void BM_NetworkRightHandSide(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  const NetworkSystem& network = system.network();
  State s;
  double y[2], ydot[2];
  for (auto _ : state) {
    y[0] = s.x;
    y[1] = s.xdot;
    network.RightHandSide(s.t, y, ydot);
    benchmark::DoNotOptimize(ydot);
    benchmark::ClobberMemory();
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NetworkRightHandSide)->DenseRange(0, 2);

void BM_BareNetworkRightHandSide(benchmark::State& state) {
  const NetworkSystem network = Bare(Spec(state));
  State s;
  double y[2], ydot[2];
  for (auto _ : state) {
    y[0] = s.x;
    y[1] = s.xdot;
    network.RightHandSide(s.t, y, ydot);
    benchmark::DoNotOptimize(ydot);
    benchmark::ClobberMemory();
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BareNetworkRightHandSide)->DenseRange(0, 2);

void BM_ActuatorJacobian(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  State s;
  for (auto _ : state) {
    benchmark::DoNotOptimize(system.Jacobian(s.t, s.x, s.xdot));
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ActuatorJacobian)->DenseRange(0, 2);

void BM_NetworkJacobian(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  const NetworkSystem& network = system.network();
  std::vector<double> values(static_cast<std::size_t>(network.jacobian_pattern().entries()));
  State s;
  double y[2];
  for (auto _ : state) {
    y[0] = s.x;
    y[1] = s.xdot;
    network.Jacobian(s.t, y, values.data());
    benchmark::DoNotOptimize(values.data());
    benchmark::ClobberMemory();
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NetworkJacobian)->DenseRange(0, 2);

// What the direct path recorded per output point.
void BM_ActuatorObserve(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  State s;
  for (auto _ : state) {
    benchmark::DoNotOptimize(system.Observe(s.t, s.x, s.xdot));
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ActuatorObserve)->DenseRange(0, 2);

// What the network path records per output point before the single actuator's view of it
// (simulation.cc re-uses one sample, as here).
void BM_NetworkObserve(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  const NetworkSystem& network = system.network();
  NetworkSample sample;
  State s;
  double y[2];
  for (auto _ : state) {
    y[0] = s.x;
    y[1] = s.xdot;
    network.Observe(s.t, y, sample);
    benchmark::DoNotOptimize(sample.elements.data());
    benchmark::ClobberMemory();
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NetworkObserve)->DenseRange(0, 2);

// A root function's value: the direct path computed x - level.
void BM_NetworkLength(benchmark::State& state) {
  const ActuatorSystem system = Canonical(state);
  const NetworkSystem& network = system.network();
  State s;
  double y[2];
  for (auto _ : state) {
    y[0] = s.x;
    y[1] = s.xdot;
    benchmark::DoNotOptimize(network.Length(0, s.t, y));
    s.Next();
  }
  state.SetLabel(kScenarios[state.range(0)]);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NetworkLength)->DenseRange(0, 2);

// The single actuator's view of a network sample, kept in a vector as Simulation::Run does for
// an ActuatorSystem (element 0 the actuator, node 1 the tip).
class ViewSink final : public NetworkSink {
 public:
  explicit ViewSink(std::vector<TrajectoryPoint>& points) : points_(points) { points_.clear(); }
  void Record(double t, const NetworkSample& s) override {
    ActuatorSample sample;
    sample.length = s.elements[0].length;
    sample.shortening_velocity = 0.0 - s.elements[0].lengthening_rate;
    sample.activation = s.elements[0].activation;
    sample.tension = s.elements[0].parts;
    sample.load = s.load[1];
    points_.push_back({t, sample});
  }

 private:
  std::vector<TrajectoryPoint>& points_;
};

NetworkRunRequest AsNetworkRequest(const RunRequest& r) {
  NetworkRunRequest request;
  request.t_start = r.t_start;
  request.t_end = r.t_end;
  request.output_interval = r.output_interval;
  if (r.min_length || r.max_length)
    request.limits.push_back({"actuator", r.min_length, r.max_length});
  request.initial_state = {r.length, r.lengthening_rate};
  return request;
}

// args: scenario, path (0 Simulation::Run of the ActuatorSystem; 1 its network run directly;
// 2 the bare network run directly)
void BM_SingleActuatorRun(benchmark::State& state) {
  const ActuatorScenarioSpec spec = Spec(state);
  const ActuatorSystem system = MakeActuatorSystem(spec);
  const NetworkSystem bare = Bare(spec);
  const NetworkRunRequest request = AsNetworkRequest(MakeActuatorRunRequest(spec));
  Simulation simulation;
  std::vector<TrajectoryPoint> trajectory;
  const auto run = [&] {
    if (state.range(1) == 0)
      return simulation.Run(system, spec.solver, MakeActuatorRunRequest(spec), trajectory);
    ViewSink sink(trajectory);
    return simulation.Run(state.range(1) == 1 ? system.network() : bare, spec.solver, request,
                          sink);
  };
  RunStats stats = run();  // allocates the CVODE memory and the trajectory's storage
  for (auto _ : state) {
    stats = run();
    benchmark::DoNotOptimize(trajectory.data());
  }
  const char* const paths[] = {"actuator", "network", "bare network"};
  state.SetLabel(std::string(kScenarios[state.range(0)]) + " " + paths[state.range(1)]);
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["rhs"] = static_cast<double>(stats.rhs_evals);
  state.SetItemsProcessed(stats.steps * state.iterations());
}
BENCHMARK(BM_SingleActuatorRun)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}})
    ->ArgNames({"scenario", "path"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace musclesim
