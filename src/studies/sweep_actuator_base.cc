// The single-actuator form of a sweep's base: its points are ScenarioSpecs, its one element
// the actuator, whose samples are the run's own trajectory.
#include <optional>

#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/trajectory_csv.h"
#include "studies/sweep_base.h"

namespace musclesim {

namespace {

class ActuatorSweepBase final : public SweepBase {
 public:
  explicit ActuatorSweepBase(std::unique_ptr<ScenarioTemplate> base) : base_(std::move(base)) {}

  std::unique_ptr<SweepBase> Copy() const override {
    return std::make_unique<ActuatorSweepBase>(base_->Copy());
  }

  MetricElements Validate(const std::vector<std::string>& overrides, const std::string&,
                          SweepSpec* keep) const override {
    // the element can only be `actuator`, which LoadSweep checks once: no axis renames it
    ScenarioSpec scenario = base_->Instantiate(overrides);
    if (keep != nullptr) keep->scenarios.push_back(std::move(scenario));
    return {{"actuator"}, {"actuator"}};
  }

  void Prepare(const SweepSpec& spec, long index) override {
    built_.reset();
    if (spec.scenarios.empty()) built_ = base_->Instantiate(PointOverrides(spec, index));
    scenario_ = built_ ? &*built_ : &spec.scenarios[static_cast<std::size_t>(index)];
  }

  RunStats Run(Simulation& simulation) override {
    trajectory_.clear();
    const ScenarioSpec& s = *scenario_;
    return simulation.Run(BuildSystem(s), s.solver, s.Request(), trajectory_);
  }

  const std::vector<TrajectoryPoint>& trajectory() const override { return trajectory_; }

  std::string TrajectoryCsv() const override {
    return FormatTrajectoryCsv(trajectory_, scenario_->PhaseTolerance(),
                               scenario_->excitation.has_value());
  }

 private:
  std::unique_ptr<ScenarioTemplate> base_;
  std::optional<ScenarioSpec> built_;           // the point, when not kept in the spec
  const ScenarioSpec* scenario_ = nullptr;      // the prepared point
  std::vector<TrajectoryPoint> trajectory_;     // re-used by every point
};

}  // namespace

std::unique_ptr<SweepBase> OpenActuatorSweepBase(const std::string& path) {
  return std::make_unique<ActuatorSweepBase>(std::make_unique<ScenarioTemplate>(path));
}

}  // namespace musclesim
