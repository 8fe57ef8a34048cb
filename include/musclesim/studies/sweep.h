// Parameter sweeps: many scenario runs made from one base scenario by overriding values at
// dotted paths (as `--set` does), summarised by metrics. This header holds the sweep file
// and its points; sweep_runner.h runs them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/studies/metrics.h"
#include "musclesim/io/scenario.h"

namespace musclesim {

enum class SweepMode { kGrid, kZip, kRandom };
std::string_view ToString(SweepMode mode);

enum class TrajectoryPolicy { kNone, kAll, kFailed };
std::string_view ToString(TrajectoryPolicy policy);

// One swept parameter. Grid and zip take `values`; random draws from [from, to] (uniform,
// or log-uniform with `log_scale`), or picks uniformly among `values` when given a list.
struct SweepAxis {
  std::string path;                  // dotted path into the scenario, e.g. load[0].value
  std::vector<std::string> values;   // the values as text, exactly as --set receives them
  double from = 0.0, to = 0.0;       // random: the draw's range
  bool log_scale = false;
  bool is_range() const { return values.empty(); }
};

struct SweepSpec {
  std::string source;                // the sweep file
  std::string base;                  // the base scenario, resolved relative to the sweep file
  SweepMode mode = SweepMode::kGrid;
  long samples = 0;                  // random: number of points
  std::uint64_t seed = 1;            // random: the draws are a pure function of seed and index
  std::vector<SweepAxis> axes;
  std::vector<Metric> metrics;
  MetricOptions metric_options;
  TrajectoryPolicy trajectories = TrajectoryPolicy::kNone;
  std::string output;                // summary CSV, relative to the working directory
  // The validated scenario of every point, kept from validation when there are at most
  // kKeptScenarioLimit points (larger sweeps rebuild each point's scenario when it runs).
  std::vector<ScenarioSpec> scenarios;
};

inline constexpr long kKeptScenarioLimit = 50000;

// Reads and validates a sweep file, then every point of it against the base scenario, so
// that nothing runs before all points are known to be valid. Throws InputError naming the
// file, line, column and, for a bad point, the axis and value.
SweepSpec LoadSweep(const std::string& path);

// Number of points: the product of the axis lengths (grid), their common length (zip), or
// `samples` (random).
long PointCount(const SweepSpec& spec);

// The axis values of point `index` (0-based), in axis order. Grid: the last axis varies
// fastest. Random: each draw depends only on (seed, index, axis), so any point can be made
// alone, in any order, on any process.
std::vector<std::string> PointValues(const SweepSpec& spec, long index);

// The point as --set overrides: "path=value" for every axis.
std::vector<std::string> PointOverrides(const SweepSpec& spec, long index);

}  // namespace musclesim
