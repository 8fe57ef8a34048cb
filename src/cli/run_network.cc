#include "cli/run_network.h"

#include <algorithm>
#include <cmath>

#include "cli/run_report.h"
#include "musclesim/io/network_csv.h"
#include "musclesim/io/network_scenario.h"

namespace musclesim::cli {

namespace {

// Passes every point on to the CSV, keeping each actuator's fastest shortening or
// lengthening: beyond its model's v_max, g(v) is the paper's power law extrapolated.
class PeakSpeeds final : public NetworkSink {
 public:
  PeakSpeeds(NetworkSink& next, const NetworkSystem& system)
      : next_(next), system_(system), speed_(system.elements().size(), 0.0) {}

  void Record(double t, const NetworkSample& sample) override {
    for (std::size_t e = 0; e < speed_.size(); ++e) {
      speed_[e] = std::max(speed_[e], std::abs(sample.elements[e].lengthening_rate));
    }
    next_.Record(t, sample);
  }

  std::vector<std::string> Notes() const {
    std::vector<std::string> notes;
    for (std::size_t e = 0; e < speed_.size(); ++e) {
      const Element& element = system_.elements()[e];
      if (element.kind != ElementKind::kActuator) continue;
      const double v_max = element.model->params().velocity.v_max;
      if (speed_[e] > v_max) {
        notes.push_back("note: |shortening velocity| of " + element.name + " reached " +
                        FormatNumber(speed_[e]) + " m/s, beyond v_max = " +
                        FormatNumber(v_max) +
                        " m/s, where g(v) is the paper's power law extrapolated");
      }
    }
    return notes;
  }

 private:
  NetworkSink& next_;
  const NetworkSystem& system_;
  std::vector<double> speed_;  // per element [m/s]
};

}  // namespace

int RunNetwork(const Arguments& args, const std::vector<std::string>& overrides) {
  const NetworkScenarioSpec spec = LoadNetworkScenario(args.positional[0], overrides);
  const std::string output = RunOutputPath(args, spec.output.file, spec.source);
  const NetworkSystem system = spec.Build();

  // rows stream to PATH.partial as they are recorded; PATH is replaced only on success
  StreamedOutput csv(output);
  NetworkCsvWriter writer(csv, system, spec.output.phase_tolerance);
  PeakSpeeds watch(writer, system);
  Simulation simulation;
  const RunStats stats = simulation.Run(system, spec.solver, spec.Request(), watch);
  writer.Flush();

  RunOutcome outcome;
  outcome.label = spec.name.empty() ? spec.source : spec.name;
  outcome.output = output;
  outcome.rows = writer.rows();
  outcome.result = std::to_string(writer.rows()) + " rows";
  outcome.notes = watch.Notes();
  return FinishRun(args, csv, stats, outcome);
}

}  // namespace musclesim::cli
