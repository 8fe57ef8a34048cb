// musclesim optimize PROBLEM.yaml [--quiet]
#include <chrono>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/io/output_file.h"
#include "musclesim/io/run_csv.h"
#include "musclesim/io/scenario_yaml.h"
#include "musclesim/optimize/optimum_files.h"
#include "musclesim/scenario/run.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim optimize PROBLEM.yaml [--quiet]

Finds the activations of the problem's controls, piecewise linear on a grid of `intervals`
over the base scenario's time span, that reach its final values with the least effort
(integral of u^2 or |u|^3 per control), by direct multiple shooting with exact derivatives
(CVODES sensitivities) and IPOPT (docs/guide/optimize.md). Then re-simulates the optimum as
one run and writes, at the problem's `output` paths (by default next to the working
directory, named after the problem file):
  scenario    the base scenario with the optimal activations as tables: `musclesim run` it
  summary     JSON: IPOPT's status, the objective, iterations, the constraint violation,
              the grid, the controls, and the re-simulation's final values against their bounds
  trajectory  the re-simulation's CSV, as `musclesim run` writes it
  --quiet     no report on standard error
Exit codes: 0 solved (IPOPT's tolerance met), 3 not solved (IPOPT's status in the summary;
the files are written with the last point), 2 invalid input, 1 anything else.
)";

}  // namespace

int OptimizeCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {}, {"--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("optimize takes one PROBLEM.yaml");
  const auto start = std::chrono::steady_clock::now();
  const ProblemFile file = LoadProblemFile(args.positional[0]);
  const OptimalControlResult result = SolveOptimalControl(file.problem, file.options);
  const std::string scenario_text = OptimumScenarioText(file, result);
  WriteOutput(file.outputs.scenario, scenario_text);
  // the re-simulation runs the file just written, as `musclesim run` would
  const RecordedRun run = RunScenario(LoadScenario(file.outputs.scenario));
  WriteOutput(file.outputs.trajectory, FormatRunCsv(run));
  const std::vector<FinalCheck> finals = CheckFinalValues(file, run);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteOutput(file.outputs.summary, OptimumSummaryJson(file, result, run, finals, wall));
  if (!args.Has("--quiet")) {
    std::cerr << "musclesim optimize: " << result.status << " after " << result.iterations
              << " iterations, objective " << result.objective << ", constraint violation "
              << result.constraint_violation << "; re-simulated: ";
    for (const FinalCheck& f : finals) std::cerr << f.column << " = " << f.value << " ";
    std::cerr << "-> " << file.outputs.scenario << ", " << file.outputs.summary << ", "
              << file.outputs.trajectory << std::endl;
  }
  return result.solved ? kExitSuccess : kExitSolverFailure;
}

}  // namespace musclesim::cli
