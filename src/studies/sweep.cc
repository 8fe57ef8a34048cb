#include "musclesim/studies/sweep.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <memory>

#include "musclesim/errors.h"
#include "musclesim/model/enum_names.h"
#include "musclesim/io/network_scenario.h"
#include "io/yaml_fields.h"
#include "studies/sweep_base.h"
#include "studies/sweep_metric_element.h"
#include "studies/sweep_point_error.h"
#include "studies/sweep_share.h"
#include "studies/sweep_signature.h"
#include "studies/sweep_validation.h"

namespace musclesim {

constexpr EnumName<SweepMode> kModeNames[] = {
    {SweepMode::kGrid, "grid"},
    {SweepMode::kZip, "zip"},
    {SweepMode::kRandom, "random"},
};

std::string_view ToString(SweepMode mode) { return ToString(kModeNames, mode); }

constexpr EnumName<TrajectoryPolicy> kPolicyNames[] = {
    {TrajectoryPolicy::kNone, "none"},
    {TrajectoryPolicy::kAll, "all"},
    {TrajectoryPolicy::kFailed, "failed"},
};

std::string_view ToString(TrajectoryPolicy policy) { return ToString(kPolicyNames, policy); }

namespace {

// SplitMix64: a well-mixed 64-bit hash, here of (seed, index, axis).
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform draw in [0, 1) from the top 53 bits, identical on every platform.
double Uniform(std::uint64_t seed, long index, std::size_t axis) {
  const std::uint64_t h = Mix(Mix(Mix(seed) ^ static_cast<std::uint64_t>(index)) ^ axis);
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// Value i of `count` from `from` to `to`, both ends exact; geometric with `log_scale`.
std::string Spaced(double from, double to, long count, long i, bool log_scale) {
  double v;
  if (i == 0) {
    v = from;
  } else if (i == count - 1) {
    v = to;
  } else if (log_scale) {
    // in decades, so that decade steps land on round values (1e-5, not 1.0000000000000016e-05)
    v = std::pow(10.0, std::log10(from) + (std::log10(to) - std::log10(from)) * i / (count - 1));
  } else {
    v = from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1);
  }
  return FormatNumber(v);
}

std::string AxisValue(const SweepAxis& axis, long i) {
  return axis.is_range() ? Spaced(axis.from, axis.to, axis.count, i, axis.log_scale)
                         : axis.values[static_cast<std::size_t>(i)];
}

SweepAxis ReadAxis(const yaml::Source& src, const YAML::Node& key, const YAML::Node& node,
                   SweepMode mode) {
  SweepAxis axis;
  axis.path = key.as<std::string>();
  axis.location = yaml::Location(src, key);
  const std::string where = "parameters." + axis.path;
  if (node.IsSequence()) {
    if (node.size() == 0) yaml::Fail(src, node, where, "[]", "needs at least one value");
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!node[i].IsScalar()) {
        yaml::Fail(src, node[i], where + "[" + std::to_string(i) + "]", yaml::Describe(node[i]),
                   "must be a single value");
      }
      axis.values.push_back(node[i].Scalar());
    }
    return axis;
  }
  if (!node.IsMap()) {
    yaml::Fail(src, node, where, yaml::Describe(node),
               "must be a list of values or {from, to, count, scale}");
  }
  yaml::RequireMap(src, node, where, {"from", "to", "count", "scale"});
  axis.from = yaml::ReadNumber(src, yaml::Required(src, node, where, "from"), where + ".from");
  axis.to = yaml::ReadNumber(src, yaml::Required(src, node, where, "to"), where + ".to");
  if (node["scale"]) {
    const std::string scale = yaml::ReadString(src, node["scale"], where + ".scale");
    if (scale != "linear" && scale != "log") {
      yaml::Fail(src, node["scale"], where + ".scale", scale, "must be linear or log");
    }
    axis.log_scale = scale == "log";
  }
  if (!std::isfinite(axis.from)) yaml::Fail(src, node["from"], where + ".from", yaml::Describe(node["from"]), "must be finite");
  if (!std::isfinite(axis.to)) yaml::Fail(src, node["to"], where + ".to", yaml::Describe(node["to"]), "must be finite");
  if (axis.log_scale && !(axis.from > 0.0 && axis.to > 0.0)) {
    yaml::Fail(src, node, where, "from " + FormatNumber(axis.from) + " to " + FormatNumber(axis.to),
               "a log scale needs from > 0 and to > 0");
  }
  if (mode == SweepMode::kRandom) {
    if (node["count"]) {
      yaml::Fail(src, node["count"], where + ".count", yaml::Describe(node["count"]),
                 "random mode draws `samples` points; count is for grid and zip");
    }
    return axis;
  }
  const YAML::Node count_node = yaml::Required(src, node, where, "count");
  axis.count = yaml::ReadInteger(src, count_node, where + ".count");
  if (axis.count < 1) yaml::Fail(src, count_node, where + ".count", yaml::Describe(count_node), "must be >= 1");
  return axis;
}

// The points checked before anything runs: all of a small sweep; of a large one, point 0
// and, for a grid, the lines through it (every value of every axis, the others at their
// first value), or the first points of a zip or random sweep; at most kUpFrontPoints.
std::vector<long> UpFrontPoints(const SweepSpec& spec) {
  const long points = PointCount(spec);
  std::vector<long> chosen;
  if (points <= kUpFrontPoints || spec.mode != SweepMode::kGrid) {
    for (long i = 0; i < std::min(points, kUpFrontPoints); ++i) chosen.push_back(i);
    return chosen;
  }
  chosen.push_back(0);
  long stride = 1;  // index step of one value along axis k: the product of the later axes
  for (std::size_t k = spec.axes.size(); k-- > 0;) {
    const long n = AxisLength(spec.axes[k]);
    for (long j = 1; j < n && static_cast<long>(chosen.size()) < kUpFrontPoints; ++j) {
      chosen.push_back(j * stride);
    }
    stride *= n;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// Requires the product of the axis lengths within kMaxSweepPoints, without overflowing.
void CheckGridSize(const yaml::Source& src, const YAML::Node& parameters, const SweepSpec& spec) {
  long count = 1;
  bool overflow = false;
  std::string lengths;
  for (const SweepAxis& axis : spec.axes) {
    overflow = overflow || __builtin_mul_overflow(count, AxisLength(axis), &count);
    lengths += (lengths.empty() ? "" : " x ") + std::to_string(AxisLength(axis));
  }
  if (overflow || count > kMaxSweepPoints) {
    yaml::Fail(src, parameters, "parameters",
               lengths + " = " + (overflow ? "more than 9e18" : std::to_string(count)) + " points",
               "a sweep may have at most 1e9 points: a running sweep keeps a bit per point in "
               "memory and about 150 bytes per point on disk (150 GB at 1e9)");
  }
}

}  // namespace

long AxisLength(const SweepAxis& axis) {
  return axis.is_range() ? axis.count : static_cast<long>(axis.values.size());
}

long PointCount(const SweepSpec& spec) {
  if (spec.mode == SweepMode::kRandom) return spec.samples;
  if (spec.axes.empty()) return 0;
  if (spec.mode == SweepMode::kZip) return AxisLength(spec.axes.front());
  long count = 1;
  for (const SweepAxis& a : spec.axes) count *= AxisLength(a);
  return count;
}

std::vector<std::string> PointValues(const SweepSpec& spec, long index) {
  std::vector<std::string> values(spec.axes.size());
  switch (spec.mode) {
    case SweepMode::kGrid: {
      long rest = index;
      for (std::size_t k = spec.axes.size(); k-- > 0;) {
        const long n = AxisLength(spec.axes[k]);
        values[k] = AxisValue(spec.axes[k], rest % n);
        rest /= n;
      }
      break;
    }
    case SweepMode::kZip:
      for (std::size_t k = 0; k < spec.axes.size(); ++k) values[k] = AxisValue(spec.axes[k], index);
      break;
    case SweepMode::kRandom:
      for (std::size_t k = 0; k < spec.axes.size(); ++k) {
        const SweepAxis& a = spec.axes[k];
        const double u = Uniform(spec.seed, index, k);
        if (!a.is_range()) {
          const auto pick = std::min(static_cast<std::size_t>(u * a.values.size()), a.values.size() - 1);
          values[k] = a.values[pick];
        } else if (a.log_scale) {
          values[k] = FormatNumber(
              std::pow(10.0, std::log10(a.from) + (std::log10(a.to) - std::log10(a.from)) * u));
        } else {
          values[k] = FormatNumber(a.from + (a.to - a.from) * u);
        }
      }
      break;
  }
  return values;
}

std::vector<std::string> PointOverrides(const SweepSpec& spec, long index) {
  std::vector<std::string> overrides = PointValues(spec, index);
  for (std::size_t k = 0; k < overrides.size(); ++k) {
    overrides[k] = spec.axes[k].path + "=" + overrides[k];
  }
  return overrides;
}

SweepSpec LoadSweep(const std::string& path, int threads) {
  const YAML::Node root = yaml::LoadFile(path);
  const yaml::Source src{path};
  yaml::RequireMap(src, root, "",
                   {"base", "mode", "samples", "seed", "parameters", "metrics", "metric_options",
                    "trajectories", "output"});
  SweepSpec spec;
  spec.source = path;
  const std::string base = yaml::ReadString(src, yaml::Required(src, root, "", "base"), "base");
  spec.base = (std::filesystem::path(path).parent_path() / base).lexically_normal().string();

  if (root["mode"]) {
    const std::string mode = yaml::ReadString(src, root["mode"], "mode");
    if (mode == "grid") spec.mode = SweepMode::kGrid;
    else if (mode == "zip") spec.mode = SweepMode::kZip;
    else if (mode == "random") spec.mode = SweepMode::kRandom;
    else yaml::Fail(src, root["mode"], "mode", mode, "must be grid, zip or random");
  }
  if (spec.mode == SweepMode::kRandom) {
    const YAML::Node samples = yaml::Required(src, root, "", "samples");
    const double n = yaml::ReadNumber(src, samples, "samples");
    if (!(n >= 1 && n <= 1e9) || n != std::floor(n)) {
      yaml::Fail(src, samples, "samples", yaml::Describe(samples), "must be an integer from 1 to 1e9");
    }
    spec.samples = static_cast<long>(n);
    // no default seed: a documented, reproducible sweep names the seed it draws from
    const YAML::Node seed = root["seed"];
    if (!seed) {
      throw InputError("seed (" + yaml::Location(src, root) +
                       "): missing required key: mode random draws every value from a hash "
                       "of (seed, index, axis); give an integer >= 0");
    }
    const double value = yaml::ReadNumber(src, seed, "seed");
    if (!(value >= 0 && value <= 9.007199254740992e15) || value != std::floor(value)) {
      yaml::Fail(src, seed, "seed", yaml::Describe(seed), "must be an integer from 0 to 2^53");
    }
    spec.seed = static_cast<std::uint64_t>(value);
  } else {
    for (const char* key : {"samples", "seed"}) {
      if (root[key]) {
        yaml::Fail(src, root[key], key, yaml::Describe(root[key]),
                   "is for mode random only (this sweep is " + std::string(ToString(spec.mode)) +
                       ")");
      }
    }
  }

  const YAML::Node parameters = yaml::Required(src, root, "", "parameters");
  if (!parameters.IsMap() || parameters.size() == 0) {
    yaml::Fail(src, parameters, "parameters", yaml::Describe(parameters),
               "must map at least one dotted path to its values");
  }
  for (const auto& entry : parameters) {
    spec.axes.push_back(ReadAxis(src, entry.first, entry.second, spec.mode));
    if (spec.mode == SweepMode::kZip &&
        AxisLength(spec.axes.back()) != AxisLength(spec.axes.front())) {
      yaml::Fail(src, entry.second, "parameters." + spec.axes.back().path,
                 std::to_string(AxisLength(spec.axes.back())) + " values",
                 "zip needs every axis as long as the first (" +
                     std::to_string(AxisLength(spec.axes.front())) + " values)");
    }
  }
  if (spec.mode == SweepMode::kGrid) CheckGridSize(src, parameters, spec);

  const YAML::Node metrics = yaml::Required(src, root, "", "metrics");
  if (!metrics.IsSequence() || metrics.size() == 0) {
    yaml::Fail(src, metrics, "metrics", yaml::Describe(metrics), "must be a non-empty list of metric names");
  }
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string name = yaml::ReadString(src, metrics[i], "metrics[" + std::to_string(i) + "]");
    try {
      spec.metrics.push_back(ParseMetric(name));
    } catch (const ParameterError& e) {
      yaml::Fail(src, metrics[i], "metrics[" + std::to_string(i) + "]", name, e.rule());
    }
  }
  if (const YAML::Node options = root["metric_options"]) {
    // `element` is read once the base's elements are known, below
    yaml::RequireMap(src, options, "metric_options", {"window", "target_length", "element"});
    if (options["window"]) {
      const std::vector<double> w = yaml::ReadNumbers(src, options["window"], "metric_options.window", 2);
      if (!(std::isfinite(w[0]) && std::isfinite(w[1]) && w[1] > w[0])) {
        yaml::Fail(src, options["window"], "metric_options.window", yaml::Describe(options["window"]),
                   "must be [start, end] with end > start [s]");
      }
      spec.metric_options.window_start = w[0];
      spec.metric_options.window_end = w[1];
    }
    if (options["target_length"]) {
      const double target = yaml::ReadNumber(src, options["target_length"], "metric_options.target_length");
      if (!(std::isfinite(target) && target > 0.0)) {
        yaml::Fail(src, options["target_length"], "metric_options.target_length",
                   yaml::Describe(options["target_length"]), "must be finite and > 0 [m]");
      }
      spec.metric_options.target_length = target;
    }
  }
  for (std::size_t i = 0; i < spec.metrics.size(); ++i) {
    if (spec.metrics[i] == Metric::kTimeToLength && !spec.metric_options.target_length) {
      yaml::Fail(src, metrics[i], "metrics[" + std::to_string(i) + "]", "time_to_length",
                 "needs metric_options.target_length");
    }
  }
  if (root["trajectories"]) {
    const std::string policy = yaml::ReadString(src, root["trajectories"], "trajectories");
    if (policy == "none") spec.trajectories = TrajectoryPolicy::kNone;
    else if (policy == "all") spec.trajectories = TrajectoryPolicy::kAll;
    else if (policy == "failed") spec.trajectories = TrajectoryPolicy::kFailed;
    else yaml::Fail(src, root["trajectories"], "trajectories", policy, "must be none, all or failed");
  }
  if (root["output"]) {
    spec.output = yaml::ReadString(src, root["output"], "output");
  }

  // every point is a full scenario: validate them (or, for a large sweep, a sample of them)
  // before anything runs; a point's error is told in terms of the file at fault
  spec.base_digest = Digest(yaml::ReadText(spec.base));
  spec.network = IsNetworkScenario(spec.base);
  const std::unique_ptr<SweepBase> base_scenario = OpenSweepBase(spec);
  const RankShare share = WorldShare();
  const long points = PointCount(spec);
  spec.kept = points <= kUpFrontPoints;
  spec.share_rank = share.rank;
  spec.share_ranks = share.ranks;
  spec.share_block = ShareBlock(points, share.ranks);
  if (spec.kept) {
    const auto slots = static_cast<std::size_t>(KeptCount(spec));
    if (spec.network) spec.network_scenarios.resize(slots);
    else spec.scenarios.resize(slots);
  }
  const auto invalid = [&](long index, const std::string& message) {
    return InputError(PointErrorExplainer(spec, *base_scenario).Explain(index, message).message);
  };
  // point 0 first, alone: the element the metrics read is resolved from it, and every later
  // point must have it too
  MetricElements elements;
  try {
    const long slot = KeptSlot(spec, 0);
    elements = base_scenario->Validate(PointOverrides(spec, 0), spec.metric_options.element,
                                       slot >= 0 ? &spec : nullptr, slot);
  } catch (const InputError& e) {
    throw invalid(0, e.what());
  }
  spec.metric_options.element = ResolveMetricElement(src, root, spec, elements);
  // the rest on every core, each rank its share; the first invalid point of them all is told
  const std::vector<long> chosen = UpFrontPoints(spec);  // ascending, point 0 first
  std::vector<long> mine;
  for (std::size_t k = 1; k < chosen.size(); ++k) {
    // a kept point where it is kept; the sample of a large sweep in blocks of its positions
    const long owner = spec.kept ? PointOwner(spec, chosen[k])
                                 : static_cast<long>(k) / spec.share_block % share.ranks;
    if (owner == share.rank) mine.push_back(chosen[k]);
  }
  const std::optional<InvalidPoint> found =
      ValidatePoints(spec, *base_scenario, mine, threads > 0 ? threads : ValidationThreads(share));
  const long first = MinOverRanks(found ? found->index : std::numeric_limits<long>::max());
  if (first == std::numeric_limits<long>::max()) return spec;
  if (found && found->index == first) throw invalid(first, found->message);
  // another rank found it: this one reads the same error from the point itself
  try {
    base_scenario->Validate(PointOverrides(spec, first), spec.metric_options.element, nullptr, 0);
  } catch (const InputError& e) {
    throw invalid(first, e.what());
  }
  throw std::logic_error("sweep point " + std::to_string(first) + " is invalid on one rank only");
}

}  // namespace musclesim
