// musclesim optimize PROBLEM.yaml [--quiet]
#include <chrono>
#include <csignal>
#include <iostream>

#include <unistd.h>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/optimize/optimum_files.h"
#include "musclesim/scenario/run.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim optimize PROBLEM.yaml [--quiet]

Finds the activations of the problem's controls, piecewise linear on a grid of `intervals`
over the base scenario's time span, with its free parameters and (if free) its final time,
that meet its final values and path bounds at the least weighted sum of effort (integral of
u^2 or |u|^3 per control), tracking (integral of (column - reference)^2), terminal
((column(T) - target)^2) and final-time terms, by direct multiple shooting with exact
derivatives (CVODES sensitivities) and IPOPT (docs/guide/optimize.md). Then re-simulates the
optimum as one run and writes, at the problem's `output` paths (by default in the working
directory, named after the problem file):
  scenario    the base scenario with the optimal activations as tables, the parameters and
              the final time at their optimal values: `musclesim run` it
  summary     JSON: IPOPT's status, the objective and its terms, iterations, the constraint
              violation, the gradient check, the grid, the controls, the parameters, and the
              re-simulation's deviation from the shooting states and its final values
  trajectory  the re-simulation's CSV, as `musclesim run` writes it (`musclesim plot` it)
  --quiet     no progress or report on standard error
SIGINT or SIGTERM stop IPOPT after its current iteration; the files are written with the
point reached.
An infeasible problem (final values or bounds the controls cannot meet) ends as IPOPT reports
it, or when the constraint violation stalls (no tenth less over 30 iterations): status
infeasibility_stalled, the constraint violated most named. optimizer.max_seconds bounds the
solve's wall time (status maximum_seconds_exceeded).
Exit codes: 0 solved (IPOPT's tolerance met), 3 not solved (IPOPT's status in the summary;
the files are written with the last point), 130 stopped by a signal (files written), 2 invalid
input, 1 anything else.
)";

volatile std::sig_atomic_t stop_signal = 0;

extern "C" void OnOptimizeStop(int) { stop_signal = 1; }

}  // namespace

int OptimizeCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {}, {"--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("optimize takes one PROBLEM.yaml");
  const auto start = std::chrono::steady_clock::now();
  ProblemFile file = LoadProblemFile(args.positional[0]);
  const bool quiet = args.Has("--quiet");
  stop_signal = 0;
  // installed until the command ends: a second signal must not cut the files' writing short
  std::signal(SIGINT, OnOptimizeStop);
  std::signal(SIGTERM, OnOptimizeStop);
  // on a terminal one line redrawn per iteration; into a file or a pipe a line every 25
  const bool terminal = isatty(STDERR_FILENO) != 0;
  file.options.progress = [quiet, terminal](const OptimizeProgress& p) {
    if (!quiet && (terminal || p.iteration % 25 == 0)) {
      std::cerr << (terminal ? "\r" : "") << "musclesim optimize: iteration " << p.iteration
                << ", objective " << p.objective << ", infeasibility " << p.infeasibility
                << (terminal ? "   " : "\n") << std::flush;
    }
    return stop_signal == 0;
  };
  const OptimalControlResult result = SolveOptimalControl(file.problem, file.options);
  if (!quiet && terminal) std::cerr << "\n";
  const std::string scenario_text = OptimumScenarioText(file, result);
  // the re-simulation reads the text about to be written, as `musclesim run` will read the
  // file: an optimum that does not read back fails here, before any file is replaced
  const RecordedRun run = RunScenario(
      ReadScenario(ParseDocument(file.outputs.scenario, scenario_text), file.outputs.scenario));
  const std::vector<FinalCheck> finals = CheckFinalValues(file, run);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  WriteOutput(file.outputs.scenario, scenario_text);
  WriteOutput(file.outputs.trajectory, FormatRunCsv(run));
  WriteOutput(file.outputs.summary, OptimumSummaryJson(file, result, run, finals, wall));
  if (!quiet) {
    std::cerr << "musclesim optimize: " << result.status << " after " << result.iterations
              << " iterations, objective " << result.objective << ", constraint violation "
              << result.constraint_violation
              << (result.solved || result.largest_violation.empty()
                      ? ""
                      : " (" + std::string(result.infeasible ? "infeasible: " : "largest: ") +
                            result.largest_violation + ")")
              << "; re-simulated (deviation " << result.resimulation_deviation << "): ";
    if (run.stats.status != RunStatus::kCompleted) {
      std::cerr << "the run ended early, at t = " << run.stats.final_time
                << " s (its CSV stops there): " << run.stats.message << " ";
    } else {
      for (const FinalCheck& f : finals) std::cerr << f.column << " = " << f.value << " ";
    }
    std::cerr << "-> " << file.outputs.scenario << ", " << file.outputs.summary << ", "
              << file.outputs.trajectory << std::endl;
  }
  if (stop_signal != 0) return kExitInterrupted;
  return result.solved ? kExitSuccess : kExitSolverFailure;
}

}  // namespace musclesim::cli
