#include "sweep/sweep_signature.h"

#include <cinttypes>
#include <cstdio>
#include <vector>

#include "musclesim/io/writers/output_file.h"

namespace musclesim {

namespace {

std::string Hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

// Appends a field and a separator no field contains, so that ("ab", "c") and ("a", "bc")
// hash differently.
void Add(std::string& text, std::string_view field) { text.append(field).push_back('\x1f'); }

std::string Optional(const std::optional<double>& value) {
  return value ? FormatFull(*value) : "none";
}

}  // namespace

std::uint64_t Digest(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

SweepSignature SweepSignature::Of(const SweepSpec& spec) {
  std::string points;
  Add(points, ToString(spec.mode));
  Add(points, std::to_string(spec.samples));
  Add(points, std::to_string(spec.seed));
  for (const SweepAxis& axis : spec.axes) {
    Add(points, axis.path);
    if (axis.is_range()) {
      Add(points, "range");
      Add(points, FormatFull(axis.from));
      Add(points, FormatFull(axis.to));
      Add(points, std::to_string(axis.count));
      Add(points, axis.log_scale ? "log" : "linear");
    } else {
      Add(points, "list");
      for (const std::string& value : axis.values) Add(points, value);
    }
    points.push_back('\x1e');  // end of the axis
  }
  std::string metrics;
  for (const Metric metric : spec.metrics) Add(metrics, ToString(metric));
  Add(metrics, Optional(spec.metric_options.window_start));
  Add(metrics, Optional(spec.metric_options.window_end));
  Add(metrics, Optional(spec.metric_options.target_length));
  // the single actuator's metrics always read its actuator: leaving the element out keeps
  // the signatures of sweeps written before networks could be swept
  if (spec.form == ScenarioForm::kNetwork) Add(metrics, spec.metric_options.element);
  return {spec.base_digest, Digest(points), Digest(metrics)};
}

std::string SweepSignature::Line() const {
  return "# sweep base=" + Hex(base) + " points=" + Hex(points) + " metrics=" + Hex(metrics);
}

std::optional<SweepSignature> SweepSignature::Parse(const std::string& line) {
  char base[17], points[17], metrics[17], rest;
  // exactly three 16-digit fields and nothing after them
  if (line.size() != SweepSignature{}.Line().size() ||
      std::sscanf(line.c_str(), "# sweep base=%16[0-9a-f] points=%16[0-9a-f] metrics=%16[0-9a-f]%c",
                  base, points, metrics, &rest) != 3) {
    return std::nullopt;
  }
  SweepSignature signature;
  signature.base = std::strtoull(base, nullptr, 16);
  signature.points = std::strtoull(points, nullptr, 16);
  signature.metrics = std::strtoull(metrics, nullptr, 16);
  if (signature.Line() != line) return std::nullopt;
  return signature;
}

std::string SweepSignature::Differences(const SweepSignature& other) const {
  std::vector<std::string> parts;
  if (base != other.base) parts.push_back("the base scenario");
  if (points != other.points) parts.push_back("the axes");       // or mode, samples, seed
  if (metrics != other.metrics) parts.push_back("the metrics");  // or metric_options
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  }
  return text;
}

}  // namespace musclesim
