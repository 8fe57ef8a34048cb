// musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--stats PATH] [--quiet]
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/errors.h"
#include "musclesim/io/output_file.h"
#include "musclesim/io/peak_speed.h"
#include "musclesim/io/trajectory_csv.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--stats PATH] [--quiet]

Integrates the scenario's actuator/load dynamics with CVODE and writes the trajectory CSV:
  t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,phase
  -o PATH          overrides output.file ("-" is standard output)
  --set KEY=VALUE  overrides one value by its dotted path, e.g. model.velocity.n=4 or
                   load[0].value=55; validated like the file (repeatable)
  --stats PATH     writes solver counters, wall time, final time and status as JSON
  --quiet          no summary line on standard error
The CSV is written atomically. If the solver fails, the rows computed so far go to
PATH.partial and PATH is left as it was.
Exit codes: 0 completed (or stopped at a length limit), 2 invalid input, 3 solver failure
(or the length reached zero), 1 anything else.
)";

}  // namespace

int RunCommand(int argc, char** argv) {
  const Arguments args =
      Parse(argc, argv, 2, {"-o", "--set", "--stats"}, {"--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one scenario file (see --help)");
  const auto sets = args.values.find("--set");
  const ScenarioSpec spec = LoadScenario(
      args.positional[0], sets == args.values.end() ? std::vector<std::string>{} : sets->second);
  const std::string output = args.Value("-o", spec.output.file);
  if (output.empty()) {
    throw InputError(spec.source + ": no output file: set output.file or pass -o PATH");
  }

  // rows stream to PATH.partial as they are recorded; PATH is replaced only on success
  StreamedOutput csv(output);
  TrajectoryCsvWriter writer(csv, spec.PhaseTolerance());
  struct Watch final : TrajectorySink {
    TrajectorySink* next;
    PeakSpeed peak;
    void Record(const TrajectoryPoint& point) override {
      peak.Observe(point);
      next->Record(point);
    }
  } watch;
  watch.next = &writer;
  watch.peak.v_max = spec.model.params.velocity.v_max;
  Simulation simulation;
  const RunStats stats = simulation.Run(BuildSystem(spec), spec.solver, spec.Request(), watch);
  writer.Flush();
  if (args.Has("--stats")) WriteOutput(args.Value("--stats"), FormatStatsJson(stats));

  const bool quiet = args.Has("--quiet");
  const std::string label = spec.name.empty() ? spec.source : spec.name;
  if (stats.status == RunStatus::kFailed) {
    const std::string& partial = csv.written_path();
    std::cerr << "musclesim run: " << label << ": solver failure: " << stats.message << "\n"
              << "musclesim run: the " << writer.rows() << " rows computed so far are in "
              << (partial == "-" ? std::string("standard output") : partial)
              << (csv.in_place() ? "" : "; " + output + " was left as it was") << "\n";
    return kExitSolverFailure;
  }
  csv.Commit();

  if (!quiet) {
    const PeakSpeed& peak = watch.peak;
    if (peak.beyond_v_max()) {
      std::cerr << "musclesim run: note: |shortening velocity| reached "
                << FormatNumber(peak.speed) << " m/s, beyond v_max = " << FormatNumber(peak.v_max)
                << " m/s, where g(v) is the paper's power law extrapolated\n";
    }
    if (stats.status == RunStatus::kLimit) std::cerr << "musclesim run: " << stats.message << "\n";
    std::cerr << "musclesim run: " << label << ": " << ToString(stats.status) << " at t = "
              << FormatNumber(stats.final_time) << " s: " << stats.steps << " steps, "
              << stats.rhs_evals << " RHS evaluations, " << stats.wall_seconds * 1e3
              << " ms, final length " << FormatNumber(writer.last().sample.length) << " m -> "
              << output << "\n";
  }
  return kExitSuccess;
}

}  // namespace musclesim::cli
