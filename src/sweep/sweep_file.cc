// LoadSweep: the sweep file read with io's YAML helpers; its points made from the base file by
// FilePoints (sweep_file_points.cc).
#include "musclesim/sweep/sweep_file.h"

#include <cmath>
#include <filesystem>
#include <memory>

#include "io/readers/part_fields_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "sweep/sweep_file_points.h"
#include "sweep/sweep_metric_element.h"
#include "sweep/sweep_signature.h"

namespace musclesim {

namespace {

SweepAxis ReadAxis(const yaml::Source& src, const std::string& key, TextPosition key_at,
                   const Document& node, SweepMode mode) {
  SweepAxis axis;
  axis.path = key;
  axis.place = yaml::Place(src, key_at);
  const std::string where = "parameters." + axis.path;
  if (node.IsSequence()) {
    if (node.size() == 0) yaml::Fail(src, node, where, "[]", "needs at least one value");
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!node[i].IsScalar()) {
        yaml::Fail(src, node[i], where + "[" + std::to_string(i) + "]", yaml::Describe(node[i]),
                   "must be a single value");
      }
      axis.values.push_back(node[i].Scalar());
      double number = 0.0;
      if (DecodeNumber(node[i].Scalar(), number)) axis.numbers.push_back(number);
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
  if (!std::isfinite(axis.from))
    yaml::Fail(src, node["from"], where + ".from", yaml::Describe(node["from"]), "must be finite");
  if (!std::isfinite(axis.to))
    yaml::Fail(src, node["to"], where + ".to", yaml::Describe(node["to"]), "must be finite");
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
  const Document& count_node = yaml::Required(src, node, where, "count");
  axis.count = yaml::ReadInteger(src, count_node, where + ".count");
  if (axis.count < 1)
    yaml::Fail(src, count_node, where + ".count", yaml::Describe(count_node), "must be >= 1");
  return axis;
}

// Requires the product of the axis lengths within kMaxSweepPoints, without overflowing.
void CheckGridSize(const yaml::Source& src, const Document& parameters, const SweepSpec& spec) {
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

// Mode random's `samples` and `seed` required, other modes' refused (their values are read
// with the file's other fields).
void CheckSampling(const yaml::Source& src, const Document& root, const SweepSpec& spec) {
  if (spec.mode != SweepMode::kRandom) {
    for (const char* key : {"samples", "seed"}) {
      if (root[key]) {
        yaml::Fail(
            src, root[key], key, yaml::Describe(root[key]),
            "is for mode random only (this sweep is " + std::string(ToString(spec.mode)) + ")");
      }
    }
    return;
  }
  yaml::Required(src, root, "", "samples");
  // no default seed: a documented, reproducible sweep names the seed it draws from
  if (!root["seed"]) {
    throw InputError(InputFault{yaml::Place(src, root), "seed", std::nullopt,
                                "missing required key: mode random draws every value from a "
                                "hash of (seed, index, axis); give an integer >= 0"});
  }
}

// The axes of `parameters`: zip's all of one length, a grid's product within the limit.
void ReadAxes(const yaml::Source& src, const Document& root, SweepSpec& spec) {
  const Document& parameters = yaml::Required(src, root, "", "parameters");
  if (!parameters.IsMap() || parameters.size() == 0) {
    yaml::Fail(src, parameters, "parameters", yaml::Describe(parameters),
               "must map at least one dotted path to its values");
  }
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const Document& values = parameters.items()[i];
    spec.axes.push_back(
        ReadAxis(src, parameters.key(i), parameters.key_position(i), values, spec.mode));
    if (spec.mode == SweepMode::kZip &&
        AxisLength(spec.axes.back()) != AxisLength(spec.axes.front())) {
      yaml::Fail(src, values, "parameters." + spec.axes.back().path,
                 std::to_string(AxisLength(spec.axes.back())) + " values",
                 "zip needs every axis as long as the first (" +
                     std::to_string(AxisLength(spec.axes.front())) + " values)");
    }
  }
  if (spec.mode == SweepMode::kGrid) CheckGridSize(src, parameters, spec);
}

// The `metrics` list, parsed; the node, for messages about its entries.
const Document& ReadMetrics(const yaml::Source& src, const Document& root, SweepSpec& spec) {
  const Document& metrics = yaml::Required(src, root, "", "metrics");
  if (!metrics.IsSequence() || metrics.size() == 0) {
    yaml::Fail(src, metrics, "metrics", yaml::Describe(metrics),
               "must be a non-empty list of metric names");
  }
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const std::string name =
        yaml::ReadString(src, metrics[i], "metrics[" + std::to_string(i) + "]");
    try {
      spec.metrics.push_back(ParseMetric(name));
    } catch (const ParameterError& e) {
      yaml::Fail(src, metrics[i], "metrics[" + std::to_string(i) + "]", name, e.rule());
    }
  }
  return metrics;
}

// The rules between the metric options and the metrics: the window's end after its start,
// time_to_length's target.
void CheckMetricOptions(const yaml::Source& src, const Document& root, const Document& metrics,
                        const SweepSpec& spec) {
  const MetricOptions& options = spec.metric_options;
  if (options.window_start && options.window_end &&
      !(*options.window_end > *options.window_start)) {
    const Document& window = root["metric_options"]["window"];
    yaml::Fail(src, window, "metric_options.window", yaml::Describe(window),
               "must be [start, end] with end > start [s]");
  }
  for (std::size_t i = 0; i < spec.metrics.size(); ++i) {
    if (spec.metrics[i] == Metric::kTimeToLength && !options.target_length) {
      yaml::Fail(src, metrics[i], "metrics[" + std::to_string(i) + "]", "time_to_length",
                 "needs metric_options.target_length");
    }
  }
}

// Everything a sweep file says but its base: the axes, the mode, the metrics and where the
// summary goes. `base_dir` is where a base path is relative to.
SweepSpec ReadSweepSpec(const yaml::Source& src, const Document& root,
                        const std::string& base_dir) {
  yaml::RequireMap(src, root, "", VariantKeys(SweepFileBlock(), "sweep"));
  SweepSpec spec;
  spec.source = src.file;
  ReadFields(src, root, "", SweepFileBlock().front(), spec);
  spec.base = (std::filesystem::path(base_dir) / spec.base).lexically_normal().string();
  CheckSampling(src, root, spec);
  ReadAxes(src, root, spec);
  CheckMetricOptions(src, root, ReadMetrics(src, root, spec), spec);
  return spec;
}

// The spec's points made from the base file spec.base, validated.
SweepPlan PlanFromFile(const yaml::Source& src, const Document& root, SweepSpec spec, int threads) {
  // every point is a full scenario: validate them (or, for a large sweep, a sample of them)
  // before anything runs; a point's error is told in terms of the file at fault
  spec.base_digest = Digest(yaml::ReadText(spec.base));
  auto base_file = std::make_unique<ScenarioTemplate>(spec.base);
  spec.form = base_file->form();
  if (base_file->has_sensitivities()) {
    // a sweep's points are plain runs reduced to metrics: a list that would be ignored is refused
    throw InputError(spec.base +
                     ": sensitivities: a sweep runs its points without "
                     "sensitivities; remove the key from the base scenario (musclesim run "
                     "computes them)");
  }
  std::unique_ptr<PointFactory> points = FilePoints(std::move(base_file), spec);
  const auto resolve = [&](const SweepSpec& s, const MetricElements& elements) {
    return ResolveMetricElement(src, root, s, elements);
  };
  return PlanSweep(std::move(spec), std::move(points), threads, resolve);
}

}  // namespace

SweepPlan LoadSweep(const std::string& path, int threads) {
  const Document& root = yaml::LoadFile(path);
  const yaml::Source src{path};
  SweepSpec spec = ReadSweepSpec(src, root, std::filesystem::path(path).parent_path().string());
  return PlanFromFile(src, root, std::move(spec), threads);
}

SweepPlan ReadSweep(const Document& document, const std::string& name, const Scenario* base,
                    const std::string& base_text, int threads) {
  const Document& root = document;
  const yaml::Source src{name, name};
  SweepSpec spec = ReadSweepSpec(src, root, "");
  if (base == nullptr) return PlanFromFile(src, root, std::move(spec), threads);
  if (!base->sensitivities.empty()) {
    throw InputError(spec.base +
                     ": sensitivities: a sweep runs its points without "
                     "sensitivities; remove them from the base scenario");
  }
  spec.base_digest = Digest(base_text);
  spec.form = base->form;
  std::unique_ptr<PointFactory> points = ParameterPoints(*base, spec);
  const auto resolve = [&](const SweepSpec& s, const MetricElements& elements) {
    return ResolveMetricElement(src, root, s, elements);
  };
  return PlanSweep(std::move(spec), std::move(points), threads, resolve);
}

}  // namespace musclesim
