// Step cost and stiffness of the canonical scenarios across configurations:
// {isometric, concentric, eccentric} x {BDF, Adams} x {analytic, difference-quotient
// Jacobian} x epsilon in {1e-2 ... 1e-6} x n in {1, 2, 3, 5}. Prints CSV:
//   scenario,method,jacobian,epsilon,n,status,steps,rhs_evals,jac_evals,newton_iters,
//   error_test_fails,wall_seconds,us_per_step,model_share,max_eigenvalue
// wall_seconds is the median of 5 runs. model_share estimates the time inside the model:
// (rhs_evals x one right-hand side + jac_evals x one Jacobian) / wall time, the two unit
// costs timed on the run's own states. max_eigenvalue is the largest |lambda| of the
// Jacobian over the recorded states: how stiff the run is.
//   step_cost SCENARIO_DIR
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/io/readers/scenario_yaml.h"

namespace {

using namespace musclesim;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// Average cost of one right-hand side and one Jacobian at the recorded states.
std::pair<double, double> UnitCosts(const ActuatorSystem& system,
                                    const std::vector<TrajectoryPoint>& trajectory) {
  volatile double sink = 0.0;
  const int rounds = std::max<int>(1, 200000 / static_cast<int>(trajectory.size()));
  auto start = Clock::now();
  for (int r = 0; r < rounds; ++r) {
    for (const TrajectoryPoint& p : trajectory) {
      sink = sink + system.Acceleration(p.t, p.sample.length, -p.sample.shortening_velocity);
    }
  }
  const double rhs = Seconds(start) / (rounds * trajectory.size());
  start = Clock::now();
  for (int r = 0; r < rounds; ++r) {
    for (const TrajectoryPoint& p : trajectory) {
      sink = sink + system.Jacobian(p.t, p.sample.length, -p.sample.shortening_velocity).by_rate;
    }
  }
  return {rhs, Seconds(start) / (rounds * trajectory.size())};
}

double LargestEigenvalue(const ActuatorSystem& system,
                         const std::vector<TrajectoryPoint>& trajectory) {
  double largest = 0.0;
  for (const TrajectoryPoint& p : trajectory) {
    // [[0, 1], [a, b]]: lambda^2 - b lambda - a = 0
    const ActuatorSystem::JacobianRow row =
        system.Jacobian(p.t, p.sample.length, -p.sample.shortening_velocity);
    const std::complex<double> root =
        std::sqrt(std::complex<double>(row.by_rate * row.by_rate + 4.0 * row.by_length));
    for (const std::complex<double> lambda :
         {(row.by_rate + root) / 2.0, (row.by_rate - root) / 2.0}) {
      largest = std::max(largest, std::abs(lambda));
    }
  }
  return largest;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: step_cost SCENARIO_DIR\n");
    return 2;
  }
  std::printf(
      "scenario,method,jacobian,epsilon,n,status,steps,rhs_evals,jac_evals,newton_iters,"
      "error_test_fails,wall_seconds,us_per_step,model_share,max_eigenvalue\n");
  Simulation sim;
  std::vector<TrajectoryPoint> trajectory;
  for (const char* name : {"isometric", "concentric", "eccentric"}) {
    for (double eps : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
      for (int n : {1, 2, 3, 5}) {
        const ActuatorScenarioSpec spec =
            LoadActuatorScenarioSpec(std::string(argv[1]) + "/" + name + ".yaml",
                                     {"model.velocity.epsilon=" + std::to_string(eps),
                                      "model.velocity.n=" + std::to_string(n)});
        const ActuatorSystem system = MakeActuatorSystem(spec);
        for (IntegrationMethod method : {IntegrationMethod::kBdf, IntegrationMethod::kAdams}) {
          for (JacobianKind jacobian :
               {JacobianKind::kAnalytic, JacobianKind::kDifferenceQuotient}) {
            SolverOptions options = spec.solver;
            options.method = method;
            options.jacobian = jacobian;
            std::vector<double> walls;
            RunStats stats;
            for (int r = 0; r < 5; ++r) {
              const auto start = Clock::now();
              stats = sim.Run(system, options, MakeActuatorRunRequest(spec), trajectory);
              walls.push_back(Seconds(start));
            }
            std::sort(walls.begin(), walls.end());
            const double wall = walls[2];
            const auto [rhs_cost, jac_cost] = UnitCosts(system, trajectory);
            const double share = (stats.rhs_evals * rhs_cost + stats.jac_evals * jac_cost) / wall;
            std::printf("%s,%s,%s,%g,%d,%s,%ld,%ld,%ld,%ld,%ld,%.6g,%.4g,%.3f,%.4g\n", name,
                        std::string(ToString(method)).c_str(),
                        jacobian == JacobianKind::kAnalytic ? "analytic" : "dq", eps, n,
                        std::string(ToString(stats.status)).c_str(), stats.steps, stats.rhs_evals,
                        stats.jac_evals, stats.newton_iters, stats.error_test_fails, wall,
                        1e6 * wall / std::max(1L, stats.steps), share,
                        LargestEigenvalue(system, trajectory));
          }
        }
      }
    }
  }
  return 0;
}
