#include "sweep/sweep_base.h"

#include <stdexcept>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "sweep/sweep_share.h"

namespace musclesim {

namespace {

// Passes on the metric element's samples as metric points and, when the trajectory is kept,
// every row to the recorder.
class Recorder final : public NetworkSink {
 public:
  Recorder(const Scenario& scenario, const NetworkSystem& system, int element,
           TrajectorySink& metrics, ColumnRecorder* trajectory)
      : actuator_form_(IsSingleActuator(scenario)),
        system_(system),
        element_(static_cast<std::size_t>(element)),
        metrics_(metrics),
        trajectory_(trajectory) {}

  // the metrics' one element straight from the state, unless the whole row is kept
  bool RecordState(double t, const double* y) override {
    if (trajectory_ != nullptr) return false;
    const int e = static_cast<int>(element_);
    system_.ObserveElement(e, t, y, element_sample_);
    if (!actuator_form_) {
      metrics_.Record(ElementPoint(t, element_sample_));
      return true;
    }
    metrics_.Record({t, ActuatorSampleOf(element_sample_, system_.LoadOn(kActuatorTipNode, t, y))});
    return true;
  }

  void Record(double t, const NetworkSample& sample) override {
    // the single actuator's points are its own view of the network (actuator_scenario.h)
    metrics_.Record(actuator_form_ ? TrajectoryPoint{t, ActuatorSampleOf(sample)}
                                   : ElementPoint(t, sample.elements[element_]));
    if (trajectory_ != nullptr) trajectory_->Record(t, sample);
  }

 private:
  bool actuator_form_;
  const NetworkSystem& system_;
  std::size_t element_;
  ElementSample element_sample_;
  TrajectorySink& metrics_;
  ColumnRecorder* trajectory_;  // null: the trajectory is not kept
};

// A metric window outside the run would leave its metric empty (NaN) at every point: refused
// as the file's error instead.
void RequireWindowWithin(const SweepSpec& spec, long index, const Scenario& scenario) {
  const MetricOptions& o = spec.metric_options;
  if (!o.window_start || !o.window_end) return;
  if (*o.window_start >= scenario.t_start && *o.window_end <= scenario.t_end) return;
  throw InputError(spec.source + ": metric_options.window = [" + FormatNumber(*o.window_start) +
                   ", " + FormatNumber(*o.window_end) + "]: must lie within the run's time [" +
                   FormatNumber(scenario.t_start) + ", " + FormatNumber(scenario.t_end) +
                   "] [s] (of point " + std::to_string(index) + ")");
}

}  // namespace

int MetricElementIndex(const Scenario& scenario, const std::string& element) {
  if (IsSingleActuator(scenario)) return kActuatorElement;
  if (element.empty()) return -1;
  std::string names;
  for (std::size_t e = 0; e < scenario.elements.size(); ++e) {
    if (scenario.elements[e].name == element) return static_cast<int>(e);
    names += (e ? ", " : "") + scenario.elements[e].name;
  }
  throw InputError("metric_options.element = " + element + ": the network of " + scenario.source +
                   " has no such element (its elements: " + names + ")");
}

MetricElements SweepBase::Validate(const SweepSpec& spec, long index, const std::string& element,
                                   SweepSpec* keep, long slot) const {
  Scenario scenario = points_->Make(spec, index).scenario;
  RequireWindowWithin(spec, index, scenario);
  MetricElements elements;
  MetricElementIndex(scenario, element);
  if (IsSingleActuator(scenario)) {
    elements = {{"actuator"}, {"actuator"}};
  } else {
    for (const Element& e : scenario.elements) {
      elements.all.push_back(e.name);
      if (e.kind == ElementKind::kActuator) elements.actuators.push_back(e.name);
    }
  }
  if (keep != nullptr) keep->scenarios[static_cast<std::size_t>(slot)] = std::move(scenario);
  return elements;
}

void SweepBase::Prepare(const SweepSpec& spec, long index) {
  made_.reset();
  const long slot = KeptSlot(spec, index);
  if (slot < 0) made_ = points_->Make(spec, index);
  scenario_ = made_ ? &made_->scenario : &spec.scenarios[static_cast<std::size_t>(slot)];
  element_ = MetricElementIndex(*scenario_, spec.metric_options.element);
  // the sweep's reader resolves the element before any point runs
  if (element_ < 0) throw std::logic_error("sweep: a network's point runs with no metric element");
  keep_ = spec.trajectories != TrajectoryPolicy::kNone;
}

RunStats SweepBase::Run(Simulation& simulation, TrajectorySink& metrics) {
  const Scenario& s = *scenario_;
  trajectory_.reset();
  // the system making the point built, else built now
  system_ =
      made_ && made_->system ? made_->system : std::make_shared<const NetworkSystem>(s.Build());
  if (keep_) trajectory_.emplace(s, *system_);
  Recorder recorder(s, *system_, element_, metrics, keep_ ? &*trajectory_ : nullptr);
  return simulation.Run(*system_, s.solver, s.Request(), recorder);
}

std::string SweepBase::TrajectoryCsv() const {
  if (!trajectory_) return "";
  RecordedRun run{trajectory_->layout(), {}, {}};
  for (std::size_t c = 0; c < trajectory_->layout().size(); ++c) {
    run.values.push_back(trajectory_->column(c));
  }
  return FormatRunCsv(run);
}

}  // namespace musclesim
