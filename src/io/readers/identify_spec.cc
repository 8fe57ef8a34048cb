// Reads the data file of `musclesim identify`.
#include <filesystem>

#include "musclesim/io/readers/identify_spec.h"
#include "io/readers/yaml_fields.h"

namespace musclesim {

IdentifySpec LoadIdentifySpec(const std::string& path) {
  const Document& root = yaml::LoadFile(path);
  const yaml::Source src{path};
  yaml::RequireMap(src, root, "", {"passive", "active", "velocity"});
  if (root.size() == 0) {
    yaml::Fail(src, root, "", "{}", "give at least one of passive, active, velocity");
  }
  IdentifySpec spec;
  spec.source = path;
  // a CSV path relative to the data file, and where the data file names it
  const auto csv = [&](const Document& block, const std::string& name, InputPlace& at) {
    const Document& node = yaml::Required(src, block, name, "csv");
    const std::string file = yaml::ReadString(src, node, name + ".csv");
    if (file.empty()) yaml::Fail(src, node, name + ".csv", "\"\"", "must name a CSV file");
    at = yaml::Place(src, node);
    return (std::filesystem::path(path).parent_path() / file).lexically_normal().string();
  };
  if (const Document& passive = root["passive"]) {
    yaml::RequireMap(src, passive, "passive", {"csv"});
    spec.passive_csv = csv(passive, "passive", spec.passive_csv_at);
  }
  if (const Document& active = root["active"]) {
    yaml::RequireMap(src, active, "active", {"csv", "count", "nonnegative"});
    spec.active_csv = csv(active, "active", spec.active_csv_at);
    if (active["count"]) {
      spec.active_count = yaml::ReadInteger(src, active["count"], "active.count");
      if (spec.active_count < 1 || spec.active_count > 12) {
        yaml::Fail(src, active["count"], "active.count", yaml::Describe(active["count"]),
                   "must be an integer from 1 to 12");
      }
    }
    if (active["nonnegative"]) {
      spec.active_nonnegative = yaml::ReadBool(src, active["nonnegative"], "active.nonnegative");
    }
  }
  if (const Document& velocity = root["velocity"]) {
    yaml::RequireMap(src, velocity, "velocity", {"csv", "f_iso"});
    spec.velocity_csv = csv(velocity, "velocity", spec.velocity_csv_at);
    if (velocity["f_iso"]) {
      spec.velocity_f_iso =
          yaml::ReadNumberIn(src, velocity["f_iso"], "velocity.f_iso", kPositiveForceRange);
    }
  }
  return spec;
}

}  // namespace musclesim
