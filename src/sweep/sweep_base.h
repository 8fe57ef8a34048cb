// Private: a sweep's points as the workers see them: each made by the sweep's PointFactory (or
// taken from those validated up front), run into the metric element's trajectory and, when
// kept, recorded whole for its trajectory CSV in the scenario's own columns.
//
// One object per thread: validation is const and may be asked of a shared one; Prepare and
// Run keep the point and its recorded trajectory in the object, so each worker thread runs
// points on its own Copy().
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/scenario/run.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_points.h"

namespace musclesim {

class SweepBase {
 public:
  explicit SweepBase(std::unique_ptr<PointFactory> points) : points_(std::move(points)) {}

  // An independent base, for another thread.
  std::unique_ptr<SweepBase> Copy() const { return std::make_unique<SweepBase>(points_->Copy()); }

  // Makes and validates point `index` of `spec` (InputError, as the factory says, or naming
  // metric_options.element when `element`, unless empty, is not one of its elements). Moves
  // the scenario into slot `slot` of keep's scenarios unless `keep` is null. Returns its
  // elements. Threads may validate into distinct slots at once.
  MetricElements Validate(const SweepSpec& spec, long index, const std::string& element,
                          SweepSpec* keep, long slot) const;

  // Makes point `index` of `spec` ready to run: its scenario as validated up front (kept in
  // `spec`, which must outlive the run), or made and validated now (InputError, as Validate).
  void Prepare(const SweepSpec& spec, long index);
  // Runs the prepared point on `simulation`, handing the metric element's points to
  // `metrics` as they are recorded and, when the spec keeps trajectories, keeping the rows
  // for TrajectoryCsv. A solver failure is a status; anything thrown (a system that cannot
  // be built) is the caller's to report.
  RunStats Run(Simulation& simulation, TrajectorySink& metrics);
  // The last Run's trajectory CSV (io/writers/run_csv.h); empty when the spec does not keep
  // trajectories.
  std::string TrajectoryCsv() const;

 private:
  std::unique_ptr<PointFactory> points_;
  std::optional<LoadedScenario> made_;           // the point, when not kept in the spec
  const Scenario* scenario_ = nullptr;           // the prepared point
  int element_ = 0;                              // the metric element's index
  bool keep_ = false;                            // the spec keeps trajectories
  std::shared_ptr<const NetworkSystem> system_;  // of the last run
  std::optional<ColumnRecorder> trajectory_;     // of the last run, when kept
};

// The index of the element a point's metrics read: the single actuator's own; a network's
// `element` (InputError if it has none of that name: an axis renamed it), or -1 while
// `element` is empty (not yet resolved).
int MetricElementIndex(const Scenario& scenario, const std::string& element);

}  // namespace musclesim
