// The single-actuator form of a sweep's base: its points are ScenarioSpecs, its one element
// the actuator, whose samples are the run's own trajectory.
#include <optional>

#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/trajectory_csv.h"
#include "studies/sweep_base.h"
#include "studies/sweep_share.h"

namespace musclesim {

namespace {

// Hands each point to the metrics and keeps a copy for the trajectory CSV.
class KeepingSink final : public TrajectorySink {
 public:
  KeepingSink(TrajectorySink& metrics, std::vector<TrajectoryPoint>& kept)
      : metrics_(metrics), kept_(kept) {}
  void Record(const TrajectoryPoint& point) override {
    metrics_.Record(point);
    kept_.push_back(point);
  }

 private:
  TrajectorySink& metrics_;
  std::vector<TrajectoryPoint>& kept_;
};

class ActuatorSweepBase final : public SweepBase {
 public:
  explicit ActuatorSweepBase(std::unique_ptr<ScenarioTemplate> base) : base_(std::move(base)) {}

  std::unique_ptr<SweepBase> Copy() const override {
    return std::make_unique<ActuatorSweepBase>(base_->Copy());
  }

  MetricElements Validate(const std::vector<std::string>& overrides, const std::string&,
                          SweepSpec* keep, long slot) const override {
    // the element can only be `actuator`, which LoadSweep checks once: no axis renames it
    ScenarioSpec scenario = base_->Instantiate(overrides);
    if (keep != nullptr) keep->scenarios[static_cast<std::size_t>(slot)] = std::move(scenario);
    return {{"actuator"}, {"actuator"}};
  }

  void Prepare(const SweepSpec& spec, long index) override {
    built_.reset();
    const long slot = KeptSlot(spec, index);
    if (slot < 0) built_ = base_->Instantiate(PointOverrides(spec, index));
    scenario_ = built_ ? &*built_ : &spec.scenarios[static_cast<std::size_t>(slot)];
    keep_ = spec.trajectories != TrajectoryPolicy::kNone;
  }

  RunStats Run(Simulation& simulation, TrajectorySink& metrics) override {
    trajectory_.clear();
    const ScenarioSpec& s = *scenario_;
    if (!keep_) return simulation.Run(BuildSystem(s), s.solver, s.Request(), metrics);
    KeepingSink sink(metrics, trajectory_);
    return simulation.Run(BuildSystem(s), s.solver, s.Request(), sink);
  }

  std::string TrajectoryCsv() const override {
    if (!keep_) return "";
    return FormatTrajectoryCsv(trajectory_, scenario_->PhaseTolerance(),
                               scenario_->excitation.has_value());
  }

 private:
  std::unique_ptr<ScenarioTemplate> base_;
  std::optional<ScenarioSpec> built_;           // the point, when not kept in the spec
  const ScenarioSpec* scenario_ = nullptr;      // the prepared point
  bool keep_ = false;                           // the spec keeps trajectories
  std::vector<TrajectoryPoint> trajectory_;     // kept trajectory, re-used by every point
};

}  // namespace

std::unique_ptr<SweepBase> OpenActuatorSweepBase(const std::string& path) {
  return std::make_unique<ActuatorSweepBase>(std::make_unique<ScenarioTemplate>(path));
}

}  // namespace musclesim
