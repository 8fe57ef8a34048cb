// musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--sensitivity PATH ...]
//               [--stats PATH] [--quiet]
#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/run_report.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/sensitivity_run.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim run SCENARIO.yaml [-o PATH] [--set KEY=VALUE ...] [--sensitivity PATH ...]
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
                   tension (docs/guide/sensitivities.md); repeatable, before the scenario's own
                   `sensitivities:` list
  --stats PATH     writes solver counters, wall time, final time and status as JSON (with
                   sensitivities: their counters and how each df/dp is computed)
  --quiet          no summary line on standard error
The CSV is written atomically. If the solver fails, the rows computed so far go to
PATH.partial and PATH is left as it was.
Exit codes: 0 completed (or stopped at a length limit), 2 invalid input, 3 solver failure
(or a length reached zero), 1 anything else.
)";

// Passes every row on to the CSV writer, keeping each actuator's fastest shortening or
// lengthening, read from the row's shortening-velocity columns: beyond its model's v_max,
// g(v) is the paper's power law extrapolated (the paper's family only).
class PeakSpeeds final : public NetworkSink {
 public:
  PeakSpeeds(RunCsvWriter& next, const Scenario& scenario, const NetworkSystem& system)
      : next_(next), scenario_(scenario), system_(system) {
    const std::vector<std::string>& names = next.columns().names();
    for (std::size_t e = 0; e < system.elements().size(); ++e) {
      const Element& element = system.elements()[e];
      if (element.kind != ElementKind::kActuator) continue;
      // the other families define their curves at every speed (docs/model.md 14.1)
      if (element.model->params().family != CurveFamily::kPaper) continue;
      const std::string column = ElementColumn(scenario, element.name, "shortening_velocity");
      const auto at = std::find(names.begin(), names.end(), column);
      watched_.push_back({static_cast<int>(e), static_cast<std::size_t>(at - names.begin()), 0.0});
    }
  }

  bool RecordState(double t, const double* y) override {
    if (!next_.RecordState(t, y)) return false;
    Update();
    return true;
  }

  void Record(double t, const NetworkSample& sample) override {
    next_.Record(t, sample);
    Update();
  }

  std::vector<std::string> Notes() const {
    std::vector<std::string> notes;
    for (const Watched& w : watched_) {
      const Element& element = system_.elements()[static_cast<std::size_t>(w.element)];
      const double v_max = element.model->params().velocity.v_max;
      if (!(w.speed > v_max)) continue;
      const std::string who = OfElement(scenario_, element.name);
      notes.push_back("note: |shortening velocity|" + who + " reached " + FormatNumber(w.speed) +
                      " m/s, beyond v_max = " + FormatNumber(v_max) +
                      " m/s, where g(v) is the paper's power law extrapolated");
    }
    return notes;
  }

 private:
  struct Watched {
    int element;
    std::size_t column;  // its shortening velocity in the writer's rows
    double speed;        // the fastest so far [m/s]
  };
  void Update() {
    for (Watched& w : watched_) w.speed = std::max(w.speed, std::abs(next_.last()[w.column]));
  }

  RunCsvWriter& next_;
  const Scenario& scenario_;
  const NetworkSystem& system_;
  std::vector<Watched> watched_;
};

std::string Label(const Scenario& scenario) {
  return scenario.name.empty() ? scenario.source : scenario.name;
}

int RunPlain(const Arguments& args, const LoadedScenario& loaded) {
  const Scenario& scenario = loaded.scenario;
  const NetworkSystem& system = *loaded.system;
  const std::string output = RunOutputPath(args, scenario.output.file, scenario.source);
  // rows stream to PATH.partial as they are recorded; PATH is replaced only on success
  StreamedOutput csv(output);
  RunCsvWriter writer(csv, scenario, system);
  PeakSpeeds watch(writer, scenario, system);
  Simulation simulation;
  const RunStats stats = RunScenario(scenario, system, simulation, watch);
  writer.Flush();

  RunOutcome outcome;
  outcome.label = Label(scenario);
  outcome.output = output;
  outcome.rows = writer.rows();
  if (!IsSingleActuator(scenario)) {
    outcome.result = std::to_string(writer.rows()) + " rows";
  } else if (writer.rows() > 0) {
    outcome.result = "final length " + FormatNumber(writer.last()[1]) + " m";  // column length
  }
  outcome.notes = watch.Notes();
  return FinishRun(args, csv, stats, outcome);
}

// A run with sensitivities: the same CSV with the derivative columns after it.
int RunSensitivities(const Arguments& args, const LoadedScenario& loaded,
                     const std::vector<std::string>& parameters) {
  const Scenario& scenario = loaded.scenario;
  std::vector<SensitivityRequest> requests;
  for (const std::string& path : parameters) requests.push_back({path, "--sensitivity"});
  const SensitivityRun run(scenario, requests, loaded.system);
  const std::string output = RunOutputPath(args, scenario.output.file, args.positional[0]);
  StreamedOutput csv(output);
  SensitivityCsvWriter writer(csv, run);
  Simulation simulation;
  const RunStats stats = run.Run(simulation, writer);
  writer.Flush();
  RunOutcome outcome;
  outcome.label = scenario.name.empty() ? args.positional[0] : scenario.name;
  outcome.output = output;
  outcome.rows = writer.rows();
  int quotients = 0;
  for (std::size_t i = 0; i < run.paths().size(); ++i) {
    outcome.sensitivities.push_back({run.paths()[i], std::string(ToString(run.sources()[i]))});
    if (run.sources()[i] == DerivativeSource::kDifferenceQuotient) ++quotients;
  }
  outcome.result = std::to_string(run.paths().size()) + " sensitivities (" +
                   std::to_string(run.paths().size() - static_cast<std::size_t>(quotients)) +
                   " analytic, " + std::to_string(quotients) + " by difference quotient)";
  return FinishRun(args, csv, stats, outcome);
}

}  // namespace

int RunCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {"-o", "--set", "--stats", "--sensitivity"},
                               {"--quiet", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one scenario file (see --help)");
  const std::string& path = args.positional[0];
  const LoadedScenario loaded =
      LoadBuiltScenario(path, Overrides(args.List("--set"), "--set"), path);
  // a scenario's own `sensitivities:` asks for them too
  const std::vector<std::string> parameters = args.List("--sensitivity");
  if (!parameters.empty() || !loaded.scenario.sensitivities.empty()) {
    return RunSensitivities(args, loaded, parameters);
  }
  return RunPlain(args, loaded);
}

}  // namespace musclesim::cli
