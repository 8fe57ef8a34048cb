// Private: a sweep's base scenario, in either form (the single actuator, io/scenario.h; a
// network, io/network_scenario.h): the points it makes, validated, and their runs, seen by
// the rest of the sweep as the trajectory of the one element the metrics read and, when
// kept, the run's trajectory CSV in the form's own layout.
//
// One object per thread: validation is const and may be asked of a shared one; Prepare and
// Run keep the point and its recorded trajectory in the object, so each worker thread runs
// points on its own Copy().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "musclesim/solver/simulation.h"
#include "musclesim/studies/sweep.h"

namespace musclesim {

// The elements of a point that the metrics may read, by name.
struct MetricElements {
  std::vector<std::string> all;        // every element, in the file's order
  std::vector<std::string> actuators;  // those that are actuators
};

class SweepBase {
 public:
  virtual ~SweepBase() = default;

  // An independent base read from the same text, for another thread.
  virtual std::unique_ptr<SweepBase> Copy() const = 0;

  // Validates the scenario that `overrides` ("path=value") make of the base: InputError as
  // the scenario reader says, or naming metric_options.element when `element` (unless
  // empty) is not one of its elements. Moves the scenario into slot `slot` of keep's
  // scenarios (of its form; the slot must exist) unless `keep` is null. Returns its elements.
  // Threads may validate into distinct slots at once.
  virtual MetricElements Validate(const std::vector<std::string>& overrides,
                                  const std::string& element, SweepSpec* keep,
                                  long slot) const = 0;

  // Makes point `index` of `spec` ready to run: its scenario as validated up front (kept in
  // `spec`, which must outlive the run), or made and validated now (InputError, as Validate).
  virtual void Prepare(const SweepSpec& spec, long index) = 0;
  // Runs the prepared point on `simulation`, handing the metric element's points to
  // `metrics` as they are recorded and, when the spec keeps trajectories, keeping what
  // TrajectoryCsv needs. A solver failure is a status; anything thrown (a system that cannot
  // be built) is the caller's to report.
  virtual RunStats Run(Simulation& simulation, TrajectorySink& metrics) = 0;
  // The last Run's trajectory CSV: io/trajectory_csv.h's for the single actuator,
  // io/network_csv.h's for a network; empty when the spec does not keep trajectories.
  virtual std::string TrajectoryCsv() const = 0;
};

// The base of `spec` (spec.base, read in the form spec.network says). Throws InputError if
// the file cannot be read or is not YAML.
std::unique_ptr<SweepBase> OpenSweepBase(const SweepSpec& spec);

// The two forms, made by OpenSweepBase.
std::unique_ptr<SweepBase> OpenActuatorSweepBase(const std::string& path);
std::unique_ptr<SweepBase> OpenNetworkSweepBase(const std::string& path);

}  // namespace musclesim
