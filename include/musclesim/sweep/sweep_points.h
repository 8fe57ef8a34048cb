// Where a sweep's points come from: the scenario of each point, made in memory. A sweep
// takes a base Scenario whose numbers its axes set through parameter handles, or a function
// making a point's scenario from its axis values (as Drake's Monte Carlo takes a simulator
// factory); sweep files are read into the first (sweep_file.h). PlanSweep then checks the
// points before any runs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "musclesim/scenario/scenario.h"
#include "musclesim/sweep/sweep.h"

namespace musclesim {

// Makes the scenario of any point of a sweep. Not shared between threads: each thread makes
// its own Copy().
class PointFactory {
 public:
  virtual ~PointFactory() = default;
  virtual std::unique_ptr<PointFactory> Copy() const = 0;
  // The scenario of point `index` of `spec`, and its system when making it built one (a
  // network read with the point's words); null otherwise, and the run builds it. Throws
  // InputError, complete and printable, naming the axis (or axes) whose values make it
  // invalid and the rule they break.
  virtual LoadedScenario Make(const SweepSpec& spec, long index) const = 0;
};

// Points that are `base` with each axis's number set through the parameter handle at the
// axis's path (SetParameters: every value checked against its key's range, then the point as
// a whole). Every axis must be numeric (SweepAxis::is_numeric). Throws InputError naming an
// axis whose path names no number of `base` (the axis's location first when it has one).
std::unique_ptr<PointFactory> ParameterPoints(Scenario base, const SweepSpec& spec);

// A function making a point's scenario from its index and its axis values (PointNumbers):
// called from several threads at once, so it must be safe to. A ParameterError or InputError
// it throws makes the point invalid, with its message.
using ScenarioMaker = std::function<Scenario(long index, const std::vector<double>& values)>;
std::unique_ptr<PointFactory> FunctionPoints(ScenarioMaker make);

// A sweep ready to run: its spec, its points validated (up to kUpFrontPoints, kept in the
// spec) and the element its metrics read resolved.
struct SweepPlan {
  SweepSpec spec;
  std::unique_ptr<PointFactory> points;
};

// The elements of a point that metrics may read, by name.
struct MetricElements {
  std::vector<std::string> all;        // every element, in the scenario's order
  std::vector<std::string> actuators;  // those that are actuators
};

// Chooses the element the metrics read from point 0's elements, or throws InputError; the
// default (ResolveElementInMemory) takes spec.metric_options.element when set, else the
// only actuator.
using ElementResolver =
    std::function<std::string(const SweepSpec& spec, const MetricElements& elements)>;
std::string ResolveElementInMemory(const SweepSpec& spec, const MetricElements& elements);

// Validates the points of `spec` made by `points` before anything runs: every point of a
// sweep of at most kUpFrontPoints (kept in spec.scenarios), else point 0 and, for a grid,
// every value of every axis with the others at their first value. Point 0 first, alone: the
// element the metrics read is resolved from it (`resolve`), and every later point checked
// must have it. Validates on `threads` threads (0: every core, shared with the other MPI
// ranks of this host); under MPI (initialised, more than one rank) every rank of
// MPI_COMM_WORLD must call it with the same sweep, and the ranks share the work and agree on
// the first invalid point. Throws the InputError of the first invalid point.
SweepPlan PlanSweep(SweepSpec spec, std::unique_ptr<PointFactory> points, int threads = 0,
                    const ElementResolver& resolve = ResolveElementInMemory);

}  // namespace musclesim
