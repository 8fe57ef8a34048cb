// The network form of a sweep's base: its points are NetworkScenarioSpecs, the metrics read
// the element metric_options.element names, and a kept trajectory is the network's CSV.
#include <optional>

#include "musclesim/errors.h"
#include "musclesim/io/network_csv.h"
#include "musclesim/io/network_scenario_template.h"
#include "musclesim/studies/metrics.h"
#include "studies/sweep_base.h"
#include "studies/sweep_share.h"

namespace musclesim {

namespace {

// The index of `element` among the scenario's elements; InputError if it has none of that
// name (an axis renamed it).
int ElementIndex(const NetworkScenarioSpec& scenario, const std::string& element) {
  std::string names;
  for (std::size_t e = 0; e < scenario.elements.size(); ++e) {
    if (scenario.elements[e].name == element) return static_cast<int>(e);
    names += (e ? ", " : "") + scenario.elements[e].name;
  }
  throw InputError("metric_options.element = " + element + ": the network of " +
                   scenario.source + " has no such element (its elements: " + names + ")");
}

// Passes on the metric element's samples as metric points and, when the trajectory is kept,
// a copy of every sample (the slots re-used from run to run, so that their memory is too).
class Recorder final : public NetworkSink {
 public:
  Recorder(int element, TrajectorySink& metrics, std::vector<double>* times,
           std::vector<NetworkSample>* samples)
      : element_(static_cast<std::size_t>(element)), metrics_(metrics), times_(times),
        samples_(samples) {}

  void Record(double t, const NetworkSample& sample) override {
    metrics_.Record(ElementPoint(t, sample.elements[element_]));
    if (times_ == nullptr) return;
    const std::size_t n = times_->size();
    times_->push_back(t);
    if (n < samples_->size()) (*samples_)[n] = sample;
    else samples_->push_back(sample);
  }

 private:
  std::size_t element_;
  TrajectorySink& metrics_;
  std::vector<double>* times_;            // null: the trajectory is not kept
  std::vector<NetworkSample>* samples_;   // slots of past runs, as many as their longest
};

class NetworkSweepBase final : public SweepBase {
 public:
  explicit NetworkSweepBase(std::unique_ptr<NetworkScenarioTemplate> base)
      : base_(std::move(base)) {}

  std::unique_ptr<SweepBase> Copy() const override {
    return std::make_unique<NetworkSweepBase>(base_->Copy());
  }

  MetricElements Validate(const std::vector<std::string>& overrides, const std::string& element,
                          SweepSpec* keep, long slot) const override {
    NetworkScenarioSpec scenario = base_->Instantiate(overrides);
    if (!element.empty()) ElementIndex(scenario, element);
    MetricElements elements;
    for (const Element& e : scenario.elements) {
      elements.all.push_back(e.name);
      if (e.kind == ElementKind::kActuator) elements.actuators.push_back(e.name);
    }
    if (keep != nullptr) {
      keep->network_scenarios[static_cast<std::size_t>(slot)] = std::move(scenario);
    }
    return elements;
  }

  void Prepare(const SweepSpec& spec, long index) override {
    built_.reset();
    const long slot = KeptSlot(spec, index);
    if (slot < 0) built_ = base_->Instantiate(PointOverrides(spec, index));
    scenario_ = built_ ? &*built_ : &spec.network_scenarios[static_cast<std::size_t>(slot)];
    element_ = ElementIndex(*scenario_, spec.metric_options.element);
    keep_ = spec.trajectories != TrajectoryPolicy::kNone;
  }

  RunStats Run(Simulation& simulation, TrajectorySink& metrics) override {
    times_.clear();
    const NetworkScenarioSpec& s = *scenario_;
    // built in place: a NetworkSystem holds pointers into its own parts
    system_.reset();
    system_.emplace(s.nodes, s.elements, s.loads, s.controllers);
    Recorder recorder(element_, metrics, keep_ ? &times_ : nullptr, &samples_);
    return simulation.Run(*system_, s.solver, s.Request(), recorder);
  }

  std::string TrajectoryCsv() const override {
    const NetworkCsvFormat format(*system_, scenario_->output.phase_tolerance);
    std::string csv = format.header() + "\n";
    for (std::size_t i = 0; i < times_.size(); ++i) format.AppendRow(csv, times_[i], samples_[i]);
    return csv;
  }

 private:
  std::unique_ptr<NetworkScenarioTemplate> base_;
  std::optional<NetworkScenarioSpec> built_;      // the point, when not kept in the spec
  const NetworkScenarioSpec* scenario_ = nullptr;  // the prepared point
  int element_ = 0;                               // the metric element's index
  bool keep_ = false;                             // the spec keeps trajectories
  std::optional<NetworkSystem> system_;           // of the last run
  std::vector<double> times_;                     // kept trajectory: its times [s]
  std::vector<NetworkSample> samples_;            // and samples (slots beyond times_.size() unused)
};

}  // namespace

std::unique_ptr<SweepBase> OpenNetworkSweepBase(const std::string& path) {
  return std::make_unique<NetworkSweepBase>(std::make_unique<NetworkScenarioTemplate>(path));
}

}  // namespace musclesim
