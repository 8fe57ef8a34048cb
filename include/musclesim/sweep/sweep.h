// Parameter sweeps: many runs of scenarios made from one base by changing values at key
// paths, each run summarised by metrics of one element (the single actuator's, or the one
// metric_options.element names). This header holds a sweep's axes and points;
// sweep_points.h makes their scenarios (from a Scenario in memory, or a function),
// sweep_file.h reads sweep files, sweep_runner.h runs them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/sweep/metrics.h"

namespace musclesim {

enum class SweepMode { kGrid, kZip, kRandom };
std::string_view ToString(SweepMode mode);

enum class TrajectoryPolicy { kNone, kAll, kFailed };
std::string_view ToString(TrajectoryPolicy policy);

// One swept parameter: a list of `values`, or a range [from, to]. Grid and zip space a
// range's `count` values evenly (geometrically with `log_scale`), computed when asked for,
// so that a long axis costs no memory; random draws from it (uniform, or log-uniform with
// `log_scale`), or picks uniformly among `values` when given a list.
struct SweepAxis {
  std::string path;                 // key path into the scenario, e.g. load[0].value [-]
  std::vector<std::string> values;  // a list's values as written, the summary's text [-]
  std::vector<double> numbers;      // the same as numbers, when every one is a number
  double from = 0.0, to = 0.0;      // a range's ends, in the unit of the swept value
  long count = 0;                   // grid and zip: values in the range; 0 for a list [-]
  bool log_scale = false;           // geometric spacing (draws) in the range [-]
  InputPlace place;                 // of the axis in the sweep file (none in code) [-]
  bool is_range() const { return values.empty(); }
  // A range, or a list of numbers: the axis sets a number through a parameter handle.
  bool is_numeric() const { return is_range() || numbers.size() == values.size(); }
};

struct SweepSpec {
  std::string source;             // the sweep file, or a name for a sweep made in code [-]
  std::string base;               // the base scenario: its file, resolved relative to the
                                  // sweep file, or its name [-]
  std::uint64_t base_digest = 0;  // a hash of the base (its file's bytes): resume checks it [-]
  ScenarioForm form = ScenarioForm::kActuator;  // the base's form [-]
  SweepMode mode = SweepMode::kGrid;
  long samples = 0;        // random: number of points [-]
  std::uint64_t seed = 0;  // random: the draws are a pure function of seed and index [-]
  std::vector<SweepAxis> axes;
  std::vector<Metric> metrics;
  MetricOptions metric_options;  // units as in MetricOptions
  TrajectoryPolicy trajectories = TrajectoryPolicy::kNone;
  std::string output;  // summary CSV, relative to the working directory [-]
  // The validated scenarios of the points when all of them were validated up front (at most
  // kUpFrontPoints points: `kept`); otherwise each point is built and validated when it
  // runs, an invalid one becoming an `invalid` row of the summary. Under MPI each rank
  // validates and keeps only its share: the blocks of `share_block` consecutive points whose
  // block number modulo `share_ranks` is `share_rank`, in index order (a rank that runs a
  // point of another's share builds it again); in one process, every point.
  bool kept = false;
  std::vector<Scenario> scenarios;
  int share_rank = 0, share_ranks = 1;  // [-]
  long share_block = 1;                 // [-]
};

// The most points a sweep may have. While it runs, a sweep keeps one bit per point in memory
// (125 MB at 1e9) and each finished row, about 150 bytes, on disk in PATH.partial: 150 GB at
// 1e9, and as much again for PATH. More would outgrow the disks of most machines.
inline constexpr long kMaxSweepPoints = 1000000000L;

// Sweeps of at most this many points are validated point by point before anything runs
// (0.1 to 0.4 ms a point, on every core, and under MPI shared among the ranks: a few seconds
// at most), so that a bad value fails at once. Larger
// sweeps validate point 0 and, for a grid, every value of every axis with the other axes at
// their first value (points of the grid, at most this many), and the rest as they run.
inline constexpr long kUpFrontPoints = 10000;

// Number of points: the product of the axis lengths (grid), their common length (zip), or
// `samples` (random).
long PointCount(const SweepSpec& spec);

// The number of values of a grid or zip axis.
long AxisLength(const SweepAxis& axis);

// The axis values of point `index` (0-based), in axis order, as the summary writes them.
// Grid: the last axis varies fastest. Random: each draw depends only on (seed, index, axis),
// so any point can be made alone, in any order, on any process.
std::vector<std::string> PointValues(const SweepSpec& spec, long index);

// The same as numbers (NaN for a value of a list that is not a number): each is the double
// its text reads back as.
std::vector<double> PointNumbers(const SweepSpec& spec, long index);

// The point as "path=value" overrides of a base file's document, for every axis.
std::vector<std::string> PointOverrides(const SweepSpec& spec, long index);

}  // namespace musclesim
