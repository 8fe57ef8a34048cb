// Work-precision of musclesim's CVODE configurations and of Boost.Odeint's rosenbrock4 on
// a canonical scenario: for rtol from 1e-3 to 1e-11, the achieved error against a reference
// run at rtol 1e-13 (itself checked against a second method) and the median wall time.
//   work_precision SCENARIO.yaml REFERENCE.csv > rows.csv
// writes the reference trajectory (t, length, tension on the output grid) to REFERENCE.csv
// for the Python peers, and CSV rows
//   scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals
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

#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
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
    e.length = std::max(e.length, std::abs(run.length[i] - reference.length[i]) / std::abs(reference.length[i]));
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
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

Grid Cvode(const ScenarioSpec& spec, const ActuatorSystem& system, Simulation& sim,
           const SolverOptions& options, long* rhs_evals) {
  std::vector<TrajectoryPoint> trajectory;
  const RunStats stats = sim.Run(system, options, spec.Request(), trajectory);
  if (rhs_evals != nullptr) *rhs_evals = stats.rhs_evals;
  Grid g;
  for (const TrajectoryPoint& p : trajectory) {
    g.t.push_back(p.t);
    g.length.push_back(p.sample.length);
    g.tension.push_back(p.sample.tension.total);
  }
  if (stats.status != RunStatus::kCompleted) g.t.clear();
  return g;
}

// Boost.Odeint: rosenbrock4 with its error controller and dense output, given the analytic
// Jacobian, integrated segment by segment between the inputs' breakpoints (restarting at
// each, as a careful user would) and observed on the same output grid.
Grid Odeint(const ScenarioSpec& spec, const ActuatorSystem& system, double rtol, double atol,
            long* rhs_evals) {
  long evaluations = 0;
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
      }};
  std::vector<double> stops = system.Breakpoints(spec.t_start, spec.t_end);
  stops.push_back(spec.t_end);
  const RunRequest request = spec.Request();
  const long outputs = static_cast<long>(std::ceil((spec.t_end - spec.t_start) / request.output_interval - 1e-9));
  std::vector<double> times;
  for (long k = 0; k <= outputs; ++k) times.push_back(k == outputs ? spec.t_end : spec.t_start + k * request.output_interval);

  Grid g;
  double y[2] = {spec.initial_length, spec.initial_lengthening_rate};
  double t0 = spec.t_start;
  std::size_t next = 0;
  for (double stop : stops) {
    // the output times in [t0, stop], and stop itself to carry the state across
    std::vector<double> segment;
    while (next < times.size() && times[next] <= stop) segment.push_back(times[next++]);
    const bool stop_is_output = !segment.empty() && segment.back() == stop;
    if (segment.empty() || segment.front() != t0) segment.insert(segment.begin(), t0);
    if (!stop_is_output) segment.push_back(stop);
    const bool first_is_output = !g.t.empty() ? g.t.back() != t0 : true;
    evaluations += OdeintSegment(problem, rtol, atol, y, segment, [&](double t, const double* s) {
      if (t == t0 && !first_is_output) return;   // already recorded
      if (t == stop && !stop_is_output) return;  // not an output time
      g.t.push_back(t);
      g.length.push_back(s[0]);
      g.tension.push_back(system.Observe(t, s[0], s[1]).tension.total);
    });
    t0 = stop;
  }
  if (rhs_evals != nullptr) *rhs_evals = evaluations;
  return g;
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
  const ScenarioSpec spec = LoadScenario(argv[1]);
  const std::string name = std::filesystem::path(argv[1]).stem().string();
  const ActuatorSystem system = BuildSystem(spec);
  Simulation sim;

  // the reference, and a second method to check it
  SolverOptions tight = spec.solver;
  tight.rtol = 1e-13;
  tight.atol = 1e-16;
  tight.jacobian = JacobianKind::kAnalytic;
  tight.method = IntegrationMethod::kBdf;
  const Grid reference = Cvode(spec, system, sim, tight, nullptr);
  tight.method = IntegrationMethod::kAdams;
  const Grid check = Cvode(spec, system, sim, tight, nullptr);
  const Errors agreement = Compare(check, reference);
  std::fprintf(stderr, "%s: reference (BDF, rtol 1e-13) against Adams at rtol 1e-13: length %.2g, tension %.2g\n",
               name.c_str(), agreement.length, agreement.tension);
  WriteReference(argv[2], reference);

  std::printf("scenario,tool,method,rtol,error,error_length,error_tension,wall_seconds,rhs_evals\n");
  const auto row = [&](const char* tool, const std::string& method, double rtol, const Grid& g,
                       double seconds, long steps) {
    const Errors e = Compare(g, reference);
    std::printf("%s,%s,%s,%.0e,%.6g,%.6g,%.6g,%.6g,%ld\n", name.c_str(), tool, method.c_str(), rtol,
                e.worst(), e.length, e.tension, seconds, steps);
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
        long steps = 0;
        const double seconds = MedianSeconds(7, [&] { g = Cvode(spec, system, sim, o, &steps); });
        row("musclesim", std::string(ToString(method)) + "-" +
                             (jacobian == JacobianKind::kAnalytic ? "analytic" : "dq"),
            rtol, g, seconds, steps);
      }
    }
    Grid g;
    long steps = 0;
    const double seconds = MedianSeconds(7, [&] { g = Odeint(spec, system, rtol, atol, &steps); });
    row("odeint", "rosenbrock4", rtol, g, seconds, steps);
  }
  return 0;
}
