// What exact derivatives buy an optimal control solve (docs/performance.md): the antagonist
// pair's rest-to-rest problem (scenarios/antagonist_move_problem.yaml, 2 states, 2 controls)
// on N = 25, 50, 100 and 200 intervals and the suspended-mass move
// (scenarios/suspended_mass_move_problem.yaml, 4 states, 3 controls) on N = 25, 50 and 100,
// their derivatives by CVODES sensitivities and by forward difference quotients (one
// evaluation of every interval per colour of variables that move no interval twice: the
// structure exploited, as a careful user would), each solved by IPOPT from the same start.
// Prints a Markdown table: the problem, N, derivatives, IPOPT's status and iterations, the
// objective, the wall time, the time per iteration, the share of it spent integrating and the
// largest deviation of the re-simulation from the shooting states.
//   optimize_scaling [N ...]   (the same grids for both problems when given)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/optimize/optimal_control.h"
#include "musclesim/optimize/problem_file.h"

int main(int argc, char** argv) {
  using namespace musclesim;
  std::vector<int> grids = {25, 50, 100, 200};
  if (argc > 1) {
    grids.clear();
    for (int i = 1; i < argc; ++i) grids.push_back(std::atoi(argv[i]));
  }
  std::printf(
      "| problem | N | derivatives | status | iterations | objective | wall [s] | "
      "per iteration [ms] | integrating | largest state deviation of the re-simulation |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  const std::vector<std::pair<std::string, std::vector<int>>> problems = {
      {"antagonist_move_problem", grids},
      {"suspended_mass_move_problem", argc > 1 ? grids : std::vector<int>{25, 50, 100}}};
  for (const auto& [name, sizes] : problems) {
    const ProblemFile file =
        LoadProblemFile(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml");
    for (const int n : sizes) {
      for (const ShootingDerivatives method :
           {ShootingDerivatives::kSensitivities, ShootingDerivatives::kDifferenceQuotients}) {
        OptimalControlProblem problem = file.problem;
        problem.intervals = n;
        OptimizeOptions options = file.options;
        options.derivatives = method;
        const OptimalControlResult r = SolveOptimalControl(problem, options);
        const bool exact = method == ShootingDerivatives::kSensitivities;
        std::printf("| %s | %d | %s | %s | %d | %.10g | %.3f | %.1f | %.0f%% | %.1e |\n",
                    name.c_str(), n, exact ? "sensitivities" : "difference quotients",
                    r.status.c_str(), r.iterations, r.objective, r.wall_seconds,
                    1e3 * r.wall_seconds / std::max(1, r.iterations),
                    100.0 * r.integration_seconds / r.wall_seconds, r.resimulation_deviation);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
