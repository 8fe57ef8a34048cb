// musclesim sweep SWEEP.yaml [-o PATH] [--jobs N] [--resume] [--quiet]
#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/progress_report.h"
#include "cli/sweep_mpi_session.h"
#include "musclesim/core/errors.h"
#include "musclesim/sweep/sweep_file.h"
#include "musclesim/sweep/sweep_mpi.h"
#include "musclesim/sweep/sweep_runner.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim sweep SWEEP.yaml [-o PATH] [--jobs N] [--resume] [--quiet]

Runs every point of the sweep (a base scenario with values overridden at dotted paths) and
writes one summary CSV: index, one column per swept path, status (ok, failed, or invalid),
the metrics, steps, rhs_evals, wall_seconds, message; rows sorted by index. The base may be
a network scenario: its metrics read the element metric_options.element names (by default
its only actuator), and its kept trajectories are network CSVs.
  -o PATH     overrides the sweep file's `output`
  --jobs N    worker threads (default: every core); points are handed out dynamically
  --resume    skip the points already in PATH.partial (left by an interrupted run of the
              same sweep; malformed rows in it are dropped and run again)
  --quiet     no progress on standard error
Sweeps of up to 10,000 points are validated point by point before anything runs; larger
ones validate a sample up front (for a grid, every value of every axis) and the rest as
they run, an invalid point giving an `invalid` row. A sweep has at most 1e9 points.
Finished rows are flushed to PATH.partial as they complete, which a running sweep locks;
PATH appears atomically at the end. SIGINT or SIGTERM stop the sweep after the running
points, keeping PATH.partial.
Under mpirun (built with -DMUSCLESIM_WITH_MPI=ON) the points are spread over the ranks and
rank 0 writes the summary.
Exit codes: 0 every point ok, 3 some points failed, 2 invalid input (or some points were
not valid scenarios: the summary is written), 130 interrupted (resume with --resume),
1 anything else.
)";

// set by SIGINT or SIGTERM; the sweep polls it through the observer below
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void OnStopSignal(int) { stop_signal = 1; }

// The command's view of a sweep: progress on standard error, a stop on SIGINT or SIGTERM,
// and under MPI a rank's error printed before the job ends with its exit code.
class CommandObserver final : public SweepObserver {
 public:
  explicit CommandObserver(bool quiet) : progress_(quiet) {}
  void OnProgress(long done, long total) override { progress_.Update(done, total); }
  void OnNotice(const std::string& message) override {
    std::cerr << "musclesim sweep: " << message << std::endl;
  }
  bool StopRequested() override { return stop_signal != 0; }
  int OnRankError(int rank, const std::exception& error) override {
    std::cerr << "musclesim sweep: rank " << rank << ": " << error.what() << std::endl;
    return dynamic_cast<const InputError*>(&error) != nullptr ? kExitInvalidInput : kExitFailure;
  }
  void Finish() { progress_.Finish(); }

 private:
  ProgressReport progress_;
};

// Worker threads when --jobs is not given: every core, shared among the MPI ranks that
// mpirun started on this host.
int DefaultJobs() {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const char* local_ranks = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int ranks = local_ranks != nullptr ? std::max(1, std::atoi(local_ranks)) : 1;
  return std::max(1, cores / ranks);
}

// The sweep on the threads, or over the ranks when launched by mpirun; the library's refusal
// of a leftover PATH.partial worded with this program's flag.
SweepOutcome RunSweepCommand(const MpiSession& mpi, const SweepPlan& plan,
                             const SweepRunOptions& options) {
  try {
    return mpi.active() ? RunSweepMpi(plan, options) : RunSweep(plan, options);
  } catch (const InterruptedSweepError& e) {
    throw InputError(e.partial_path() +
                     " exists: an earlier sweep was interrupted. Pass "
                     "--resume to continue it, or delete the file to start again");
  }
}

}  // namespace

int SweepCommand(int argc, char** argv) {
  const Arguments args =
      Parse(argc, argv, 2, {"-o", "--jobs"}, {"--resume", "--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one sweep file (see --help)");
  SweepRunOptions options;
  options.jobs = DefaultJobs();
  if (args.Has("--jobs")) {
    const std::string text = args.Value("--jobs");
    char* end = nullptr;
    const long jobs = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || jobs < 1 || jobs > 4096) {
      throw UsageError("--jobs " + text + ": must be an integer from 1 to 4096");
    }
    options.jobs = static_cast<int>(jobs);
  }
  options.resume = args.Has("--resume");
  const bool quiet = args.Has("--quiet");
  CommandObserver observer(quiet);
  options.observer = &observer;

  MpiSession mpi(argc, argv);  // MPI_Init only when launched by mpirun
  // validation runs on the threads asked for (by default every core, shared by the ranks)
  const SweepPlan plan = LoadSweep(args.positional[0], args.Has("--jobs") ? options.jobs : 0);
  const SweepSpec& spec = plan.spec;
  options.output = args.Value("-o", spec.output);
  if (options.output.empty()) {
    throw InputError(spec.source + ": no output file: set output or pass -o PATH");
  }
  CheckSummaryPath(spec, options.output);
  std::signal(SIGINT, OnStopSignal);
  std::signal(SIGTERM, OnStopSignal);
  const SweepOutcome outcome = RunSweepCommand(mpi, plan, options);
  if (!mpi.is_root()) return kExitSuccess;
  observer.Finish();

  if (outcome.interrupted) {
    std::cerr << "musclesim sweep: interrupted: " << outcome.resumed + outcome.ran << " of "
              << outcome.points << " points are in " << options.output
              << ".partial; run again with --resume to finish\n";
    return kExitInterrupted;
  }
  if (!quiet) {
    std::cerr << "musclesim sweep: " << outcome.points << " points (" << outcome.ran << " run now, "
              << outcome.resumed << " resumed), " << outcome.failed << " failed";
    if (outcome.invalid > 0) std::cerr << ", " << outcome.invalid << " invalid";
    std::cerr << " -> " << options.output << "\n";
  }
  // an invalid point is invalid input, found late: it outranks a solver failure
  if (outcome.invalid > 0) {
    std::cerr << "musclesim sweep: " << outcome.invalid << " of " << outcome.points
              << " points are not valid scenarios (status invalid in " << options.output
              << ", the reason in their message)\n";
    return kExitInvalidInput;
  }
  return outcome.failed > 0 ? kExitSolverFailure : kExitSuccess;
}

}  // namespace musclesim::cli
