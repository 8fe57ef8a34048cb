// The sweep file's keys described once (core/part_fields.h): what the reader, its messages and
// the table in docs/guide/sweeps.md derive from.
#include <cstdint>
#include <optional>
#include <utility>

#include "musclesim/core/input_ranges.h"
#include "musclesim/sweep/sweep_file.h"
#include "sweep/sweep_names.h"

namespace musclesim {

namespace {

using Spec = SweepSpec;

// A random sweep's number of points: at most kMaxSweepPoints.
constexpr InputRange kSampleRange{
    1.0, static_cast<double>(kMaxSweepPoints), "-",
    "a sweep may have at most 1e9 points: a running sweep keeps a bit per point in memory and "
    "about 150 bytes per point on disk"};
// A seed is read as a double: beyond 2^53 not every integer is one.
constexpr InputRange kSeedRange{0.0, 9007199254740992.0, "-",
                                "beyond 2^53 a double does not hold every integer"};

bool IsRandom(const Spec& spec) { return spec.mode == SweepMode::kRandom; }

// A whole number of mode random's, which the other modes refuse.
NumberField<Spec> RandomOnly(const char* key, const InputRange& range, const char* doc,
                             std::function<double(const Spec&)> get,
                             std::function<void(Spec&, double)> set) {
  NumberField<Spec> field{key, range, std::nullopt, doc, std::move(get), std::move(set)};
  field.integer = true;
  field.given = IsRandom;
  return field;
}

// An optional number of the metric options, `member` of MetricOptions.
NumberField<Spec> MetricOption(const char* key, std::optional<double> MetricOptions::*member,
                               const InputRange& range, const char* doc) {
  NumberField<Spec> field{
      key,
      range,
      std::nullopt,
      doc,
      [member](const Spec& s) { return (s.metric_options.*member).value_or(0.0); },
      [member](Spec& s, double v) { s.metric_options.*member = v; }};
  field.given = [member](const Spec& s) { return (s.metric_options.*member).has_value(); };
  return field;
}

PartVariant<Spec> Sweep() {
  PartVariant<Spec> sweep = OnlyVariant<Spec>(
      "sweep", "a run of the base scenario per point, each summarised by the metrics",
      {RandomOnly(
           "samples", kSampleRange, "how many points mode random draws: required there only",
           [](const Spec& s) { return static_cast<double>(s.samples); },
           [](Spec& s, double v) { s.samples = static_cast<long>(v); }),
       RandomOnly(
           "seed", kSeedRange,
           "mode random's draws are a pure function of (seed, index, axis): required there only",
           [](const Spec& s) { return static_cast<double>(s.seed); },
           [](Spec& s, double v) { s.seed = static_cast<std::uint64_t>(v); }),
       MetricOption("metric_options.window[0]", &MetricOptions::window_start, kTimeRange,
                    "where mean_shortening_velocity's window begins; the run's start by default"),
       MetricOption("metric_options.window[1]", &MetricOptions::window_end, kTimeRange,
                    "where it ends, after it begins; the run's end by default"),
       MetricOption("metric_options.target_length", &MetricOptions::target_length, kLengthRange,
                    "the length time_to_length waits for: required by it")});
  sweep.words = {
      EnumField("mode", &Spec::mode, kSweepModeNames,
                "grid: the cartesian product of the axes; zip: their i-th values together; "
                "random: `samples` draws"),
      EnumField("trajectories", &Spec::trajectories, kTrajectoryPolicyNames,
                "which points' per-run CSVs are kept, in <output stem>_trajectories/")};
  sweep.texts = {{"base", "the base scenario's file, relative to the sweep file",
                  [](const Spec& s) { return s.base; },
                  [](Spec& s, std::string v) { s.base = std::move(v); }, true},
                 {"output", "the summary CSV, relative to the working directory; -o overrides it",
                  [](const Spec& s) { return s.output; },
                  [](Spec& s, std::string v) { s.output = std::move(v); }}};
  sweep.other_keys = {"parameters", "metrics", "metric_options.element"};
  return sweep;
}

}  // namespace

const std::vector<PartVariant<SweepSpec>>& SweepFileBlock() {
  static const std::vector<PartVariant<SweepSpec>> block{Sweep()};
  return block;
}

}  // namespace musclesim
