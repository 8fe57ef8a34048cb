// Work-precision of musclesim's CVODE configurations and of Boost.Odeint's rosenbrock4 on
// a canonical scenario (two states (x, xdot), or three with activation dynamics): for rtol from
// 1e-3 to 1e-11, the achieved error against a reference run at rtol 1e-13 (itself checked against a
// second method) and the median wall time.
//   work_precision SCENARIO.yaml REFERENCE.csv > rows.csv
// writes the reference trajectory (t, length, tension on the output grid) to REFERENCE.csv
// for the Python peers, and CSV rows
//   scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals,steps
// rhs_evals: right-hand-side evaluations (musclesim's include those of a difference-quotient
// Jacobian); steps: accepted internal steps (CVODE's, rosenbrock4's).
// Errors: the largest relative error of the length over the output grid, and of the total
// tension relative to its largest value; `error` is the larger of the two.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "odeint_network.h"
#include "odeint_peer.h"

namespace {

using namespace musclesim;

struct Grid {
  std::vector<double> t, length, tension;
};

struct Errors {
  double length = 0.0, tension = 0.0;
  double worst() const { return std::max(length, tension); }
};

Errors Compare(const Grid& run, const Grid& reference) {
  Errors e;
  double scale = 0.0;
  for (double v : reference.tension) scale = std::max(scale, std::abs(v));
  const std::size_t n = std::min(run.t.size(), reference.t.size());
  if (run.t.size() != reference.t.size()) return {INFINITY, INFINITY};
  for (std::size_t i = 0; i < n; ++i) {
    e.length = std::max(
        e.length, std::abs(run.length[i] - reference.length[i]) / std::abs(reference.length[i]));
    e.tension = std::max(e.tension, std::abs(run.tension[i] - reference.tension[i]) / scale);
  }
  return e;
}

// The median wall time of `repeats` calls of `run`, which fills `grid`.
double MedianSeconds(int repeats, const std::function<void()>& run) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// One CVODE run on the output grid; `stats` gets its counters. A run that stops early (a
// limit, a failure) gives an empty grid, whose error is infinite.
// Records what the comparison reads straight into the grid, as the Odeint side does.
class GridSink final : public TrajectorySink {
 public:
  explicit GridSink(Grid& grid) : grid_(grid) {}
  void Record(const TrajectoryPoint& p) override {
    grid_.t.push_back(p.t);
    grid_.length.push_back(p.sample.length);
    grid_.tension.push_back(p.sample.tension.total);
  }

 private:
  Grid& grid_;
};

Grid Cvode(const ActuatorScenarioSpec& spec, const ActuatorSystem& system, Simulation& sim,
           const SolverOptions& options, RunStats* stats) {
  Grid g;
  GridSink sink(g);
  const RunStats run = sim.Run(system, options, MakeActuatorRunRequest(spec), sink);
  if (stats != nullptr) *stats = run;
  if (run.status != RunStatus::kCompleted) g.t.clear();
  return g;
}

// The output grid (t_start + k * output_interval, then t_end, as Simulation::Run records it)
// cut at the inputs' breakpoints: one list of times per segment, from its start to its stop,
// with the grid index each time records (-1: a segment's end that is no grid time). A grid
// time a rounding error from a stop is recorded there, as CVODE does; a segment shorter
// than that is skipped.
struct Segment {
  std::vector<double> times;
  std::vector<long> grid_index;
};

std::vector<Segment> Segments(const ActuatorScenarioSpec& spec, const ActuatorSystem& system,
                              std::vector<double>& grid) {
  const RunRequest request = MakeActuatorRunRequest(spec);
  const double span = spec.t_end - spec.t_start;
  const long outputs = static_cast<long>(std::ceil(span / request.output_interval - 1e-9));
  grid.clear();
  for (long k = 0; k <= outputs; ++k) {
    grid.push_back(k == outputs ? spec.t_end : spec.t_start + k * request.output_interval);
  }
  const double same = 1e-12 * span;  // closer than this is one time
  std::vector<double> stops;
  for (double b : system.Breakpoints(spec.t_start, spec.t_end)) {
    const double previous = stops.empty() ? spec.t_start : stops.back();
    if (b - previous > same && spec.t_end - b > same) stops.push_back(b);
  }
  stops.push_back(spec.t_end);

  std::vector<Segment> segments;
  double t0 = spec.t_start;
  long next = 0;  // the first grid time not yet given to a segment
  for (double stop : stops) {
    Segment s;
    s.times.push_back(t0);
    s.grid_index.push_back(next < static_cast<long>(grid.size()) && grid[next] - t0 <= same ? next++
                                                                                            : -1);
    while (next < static_cast<long>(grid.size()) && grid[next] < stop - same) {
      s.times.push_back(grid[next]);
      s.grid_index.push_back(next++);
    }
    s.times.push_back(stop);
    s.grid_index.push_back(
        next < static_cast<long>(grid.size()) && grid[next] - stop <= same ? next++ : -1);
    segments.push_back(std::move(s));
    t0 = stop;
  }
  return segments;
}

// Integrates segment by segment (restarting at each breakpoint, as a careful user would),
// `segment` integrating one from the state `y` through its times and calling `observe` at each;
// `tension` gives the total tension at (t, state). Returns the run on the output grid.
Grid OnGrid(
    const ActuatorScenarioSpec& spec, const ActuatorSystem& system, std::vector<double> y,
    const std::function<double(double t, const double* y)>& tension,
    const std::function<void(std::vector<double>& y, const std::vector<double>& times,
                             const std::function<void(double, const double*)>& observe)>& segment) {
  std::vector<double> grid;
  const std::vector<Segment> segments = Segments(spec, system, grid);
  Grid g;
  for (const Segment& s : segments) {
    std::size_t i = 0;  // integrate_times observes every time of the list once, in order
    segment(y, s.times, [&](double, const double* state) {
      const long k = s.grid_index[i++];
      if (k < 0 || (!g.t.empty() && g.t.back() == grid[k])) return;  // not a grid time, or recorded
      g.t.push_back(grid[k]);
      g.length.push_back(state[0]);
      g.tension.push_back(tension(grid[k], state));
    });
  }
  return g;
}

// Boost.Odeint: rosenbrock4 with its error controller and dense output, given the analytic
// Jacobian (and df/dt), on the two states (x, xdot).
Grid OdeintTwoState(const ActuatorScenarioSpec& spec, const ActuatorSystem& system, double rtol,
                    double atol, OdeintCounts& counts) {
  const TwoStateProblem problem{
      &system,
      [](const void* s, double t, double x, double v) {
        return static_cast<const ActuatorSystem*>(s)->Acceleration(t, x, v);
      },
      [](const void* s, double t, double x, double v, double* by_length, double* by_rate) {
        const ActuatorSystem::JacobianRow row =
            static_cast<const ActuatorSystem*>(s)->Jacobian(t, x, v);
        *by_length = row.by_length;
        *by_rate = row.by_rate;
      },
      [](const void* s, double t, double x, double v) {
        // d/dt of (F_load(t, x) - T(x, -v, u(t)) - ...) / m: the force waveforms' slopes
        // and the activation's through dT/du
        const ActuatorSystem& system = *static_cast<const ActuatorSystem*>(s);
        double load_slope = 0.0;
        for (const Load& load : system.loads().loads()) {
          if (load.kind == LoadKind::kForce) load_slope += load.force.Slope(t);
        }
        const Waveform& activation = system.activation();
        const TensionSample tension = system.model().Evaluate(x, -v, activation.Evaluate(t));
        return (load_slope - tension.d_activation * activation.Slope(t)) / system.effective_mass();
      }};
  return OnGrid(
      spec, system, {spec.initial_length, spec.initial_lengthening_rate},
      [&](double t, const double* y) { return system.Observe(t, y[0], y[1]).tension.total; },
      [&](std::vector<double>& y, const std::vector<double>& times, const auto& observe) {
        OdeintSegment(problem, rtol, atol, y.data(), times, observe, counts);
      });
}

bool PiecewiseConstant(const Waveform& w) {
  return w.kind == WaveformKind::kConstant || w.kind == WaveformKind::kStep ||
         w.kind == WaveformKind::kPulses;
}

// With activation dynamics the activation u is a third state: rosenbrock4 on the system's
// network (x, xdot, u), starting where Simulation::Run starts it. The N-state peer takes
// df/dt = 0, so the inputs must be constant between breakpoints.
Grid OdeintNetworkRun(const ActuatorScenarioSpec& spec, const ActuatorSystem& system, double rtol,
                      double atol, OdeintCounts& counts) {
  const NetworkSystem& network = system.network();
  OdeintNetwork context{&network, std::vector<double>(network.jacobian_pattern().entries())};
  const NStateProblem problem{network.state_size(), &context, &OdeintNetwork::Rhs,
                              &OdeintNetwork::DenseJacobian};
  return OnGrid(
      spec, system,
      {spec.initial_length, spec.initial_lengthening_rate,
       system.excitation()->InitialActivation(spec.t_start)},
      [&](double t, const double* y) { return system.Observe(t, y[0], y[1], y[2]).tension.total; },
      [&](std::vector<double>& y, const std::vector<double>& times, const auto& observe) {
        OdeintSegmentN(problem, rtol, atol, y.data(), times, observe, counts);
      });
}

Grid Odeint(const ActuatorScenarioSpec& spec, const ActuatorSystem& system, double rtol,
            double atol, OdeintCounts& counts) {
  return system.excitation() ? OdeintNetworkRun(spec, system, rtol, atol, counts)
                             : OdeintTwoState(spec, system, rtol, atol, counts);
}

void WriteReference(const std::string& path, const Grid& g) {
  std::ofstream out(path);
  out << "t,length,tension\n";
  char line[128];
  for (std::size_t i = 0; i < g.t.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", g.t[i], g.length[i], g.tension[i]);
    out << line;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: work_precision SCENARIO.yaml REFERENCE.csv\n");
    return 2;
  }
  const ActuatorScenarioSpec spec = LoadActuatorScenarioSpec(argv[1]);
  const std::string name = std::filesystem::path(argv[1]).stem().string();
  const ActuatorSystem system = MakeActuatorSystem(spec);
  if (system.excitation()) {
    bool constant = PiecewiseConstant(system.excitation()->signal);
    for (const Load& load : system.loads().loads()) {
      if (load.kind == LoadKind::kForce) constant = constant && PiecewiseConstant(load.force);
    }
    if (!constant) {
      std::fprintf(stderr,
                   "%s: excitation and force loads must be constant, step or pulses "
                   "(the N-state Odeint peer takes df/dt = 0 between breakpoints)\n",
                   argv[1]);
      return 2;
    }
  }
  Simulation sim;

  // the reference, and a second method to check it
  SolverOptions tight = spec.solver;
  tight.rtol = 1e-13;
  tight.atol = 1e-16;
  tight.jacobian = JacobianKind::kAnalytic;
  tight.method = IntegrationMethod::kBdf;
  RunStats reference_stats;
  const Grid reference = Cvode(spec, system, sim, tight, &reference_stats);
  if (reference.t.empty()) {
    std::fprintf(stderr, "%s: the reference run stopped early: %s\n", argv[1],
                 reference_stats.message.c_str());
    return 1;
  }
  tight.method = IntegrationMethod::kAdams;
  const Grid check = Cvode(spec, system, sim, tight, nullptr);
  const Errors agreement = Compare(check, reference);
  std::fprintf(
      stderr,
      "%s: reference (BDF, rtol 1e-13) against Adams at rtol 1e-13: length %.2g, tension %.2g\n",
      name.c_str(), agreement.length, agreement.tension);
  WriteReference(argv[2], reference);

  std::fprintf(stderr, "%s: Odeint (%s) restarts at %zu breakpoints\n", name.c_str(),
               system.excitation() ? "N-state, on the network (x, xdot, u)" : "two-state (x, xdot)",
               system.Breakpoints(spec.t_start, spec.t_end).size());
  const int repeats = 7;
  std::printf(
      "scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals,steps\n");
  const auto row = [&](const char* tool, const std::string& method, double rtol, const Grid& g,
                       double seconds, long rhs_evals, long steps) {
    const Errors e = Compare(g, reference);
    std::printf("%s,%s,%s,%.0e,%.6g,%.6g,%.6g,%.6g,%ld,%ld\n", name.c_str(), tool, method.c_str(),
                rtol, e.worst(), e.length, e.tension, seconds, rhs_evals, steps);
  };
  for (int k = 3; k <= 11; ++k) {
    const double rtol = std::pow(10.0, -k), atol = rtol * 1e-3;
    for (IntegrationMethod method : {IntegrationMethod::kBdf, IntegrationMethod::kAdams}) {
      for (JacobianKind jacobian : {JacobianKind::kAnalytic, JacobianKind::kDifferenceQuotient}) {
        SolverOptions o = spec.solver;
        o.method = method;
        o.jacobian = jacobian;
        o.rtol = rtol;
        o.atol = atol;
        Grid g;
        RunStats stats;
        const double seconds =
            MedianSeconds(repeats, [&] { g = Cvode(spec, system, sim, o, &stats); });
        row("musclesim",
            std::string(ToString(method)) + "-" +
                (jacobian == JacobianKind::kAnalytic ? "analytic" : "dq"),
            rtol, g, seconds, stats.rhs_evals, stats.steps);
      }
    }
    Grid g;
    OdeintCounts counts;
    const double seconds = MedianSeconds(repeats, [&] {
      counts = OdeintCounts();
      g = Odeint(spec, system, rtol, atol, counts);
    });
    row("odeint", "rosenbrock4", rtol, g, seconds, counts.rhs_evals, counts.steps);
  }
  return 0;
}
