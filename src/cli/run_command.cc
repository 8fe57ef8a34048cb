// musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--sensitivity PATH ...]
//               [--stats PATH] [--quiet]
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/run_network.h"
#include "cli/run_report.h"
#include "musclesim/errors.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/output_file.h"
#include "musclesim/io/peak_speed.h"
#include "musclesim/io/trajectory_csv.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/sensitivity_run.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--sensitivity PATH ...]
                     [--stats PATH] [--quiet]

Integrates the scenario's dynamics with CVODE and writes the trajectory CSV. A single
actuator's CSV has the columns
  t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,phase
with `excitation` after `activation` when the scenario gives an excitation (activation
dynamics). A network's (a file with a top-level `nodes:` key) has t; NODE.position,
NODE.velocity of every node; ELEMENT.length, ELEMENT.tension of every element, an actuator
adding .shortening_velocity, .activation (.excitation with activation dynamics),
.tension_passive, .tension_active and .phase; and NODE.load of every free node.
  -o PATH          overrides output.file ("-" is standard output)
  --set KEY=VALUE  overrides one value by its dotted path, e.g. model.velocity.n=4,
                   load[0].value=55 or elements[1].activation.after=0.5; validated like
                   the file (repeatable)
  --sensitivity PATH
                   adds the forward sensitivities (CVODES) to the parameter at PATH, a
                   numeric dotted path as --set takes it (model.f_iso, actuator.mass,
                   load[0].value, initial.length, nodes[1].mass, models.NAME.velocity.v_max):
                   after the CSV's columns, d_COLUMN/d_PATH for every state column and
                   tension (README "Sensitivities"); repeatable, before the scenario's own
                   `sensitivities:` list
  --stats PATH     writes solver counters, wall time, final time and status as JSON (with
                   sensitivities: their counters and how each df/dp is computed)
  --quiet          no summary line on standard error
The CSV is written atomically. If the solver fails, the rows computed so far go to
PATH.partial and PATH is left as it was.
Exit codes: 0 completed (or stopped at a length limit), 2 invalid input, 3 solver failure
(or a length reached zero), 1 anything else.
)";

int RunActuator(const Arguments& args, const std::vector<std::string>& sets) {
  const ScenarioSpec spec = LoadScenario(args.positional[0], sets);
  const std::string output = RunOutputPath(args, spec.output.file, spec.source);

  // rows stream to PATH.partial as they are recorded; PATH is replaced only on success
  StreamedOutput csv(output);
  TrajectoryCsvWriter writer(csv, spec.PhaseTolerance(), spec.excitation.has_value());
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

  RunOutcome outcome;
  outcome.label = spec.name.empty() ? spec.source : spec.name;
  outcome.output = output;
  outcome.rows = writer.rows();
  if (writer.rows() > 0) {
    outcome.result = "final length " + FormatNumber(writer.last().sample.length) + " m";
  }
  const PeakSpeed& peak = watch.peak;
  if (peak.beyond_v_max()) {
    outcome.notes.push_back("note: |shortening velocity| reached " + FormatNumber(peak.speed) +
                            " m/s, beyond v_max = " + FormatNumber(peak.v_max) +
                            " m/s, where g(v) is the paper's power law extrapolated");
  }
  return FinishRun(args, csv, stats, outcome);
}

// A run with sensitivities: the same CSV with the derivative columns after it.
int RunSensitivities(const Arguments& args, const std::vector<std::string>& sets,
                     const std::vector<std::string>& parameters) {
  SensitivityCsvRun run(args.positional[0], sets, parameters);
  const std::string output = RunOutputPath(args, run.output_file(), args.positional[0]);
  StreamedOutput csv(output);
  const RunStats stats = run.Run(csv);
  RunOutcome outcome;
  outcome.label = run.name().empty() ? args.positional[0] : run.name();
  outcome.output = output;
  outcome.rows = run.rows();
  int quotients = 0;
  for (std::size_t i = 0; i < run.parameters().size(); ++i) {
    const std::string derivative(ToString(run.sources()[i]));
    outcome.sensitivities.push_back({run.parameters()[i], derivative});
    if (run.sources()[i] == DerivativeSource::kDifferenceQuotient) ++quotients;
  }
  outcome.result = std::to_string(run.parameters().size()) + " sensitivities (" +
                   std::to_string(run.parameters().size() - static_cast<std::size_t>(quotients)) +
                   " analytic, " + std::to_string(quotients) + " by difference quotient)";
  return FinishRun(args, csv, stats, outcome);
}

}  // namespace

int RunCommand(int argc, char** argv) {
  const Arguments args =
      Parse(argc, argv, 2, {"-o", "--set", "--stats", "--sensitivity"}, {"--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one scenario file (see --help)");
  const auto sets = args.values.find("--set");
  const std::vector<std::string> overrides =
      sets == args.values.end() ? std::vector<std::string>{} : sets->second;
  const auto listed = args.values.find("--sensitivity");
  const std::vector<std::string> parameters =
      listed == args.values.end() ? std::vector<std::string>{} : listed->second;
  // a scenario's own `sensitivities:` asks for them too
  if (!parameters.empty() || HasSensitivities(args.positional[0])) {
    return RunSensitivities(args, overrides, parameters);
  }
  if (IsNetworkScenario(args.positional[0])) return RunNetwork(args, overrides);
  return RunActuator(args, overrides);
}

}  // namespace musclesim::cli
