// Reads the data file of `musclesim identify` on time series.
#include "musclesim/io/readers/identify_series_spec.h"

#include <filesystem>
#include <set>

#include "musclesim/core/key_path.h"
#include "io/readers/part_fields_yaml.h"
#include "io/readers/yaml_fields.h"

namespace musclesim {

namespace {

// A noise level: a standard deviation in the column's own unit.
constexpr InputRange kNoiseRange{
    0.0, 1e12, "the column's unit",
    "a standard deviation is positive, and 1e12 is beyond any quantity a trajectory holds", true};

std::string Relative(const std::string& base_dir, const std::string& file) {
  return (std::filesystem::path(base_dir) / file).lexically_normal().string();
}

SeriesSpec ReadSeries(const yaml::Source& src, const Document& node, const std::string& path,
                      const std::string& base_dir, SeriesValues values) {
  const PartVariant<SeriesSpec>& entry = SeriesEntry().front();
  std::vector<std::string> keys;
  AddVariantKeys(entry, keys);
  // the caller holds the values: an entry gives at most their noise levels
  if (values == SeriesValues::kInMemory) std::erase(keys, std::string("csv"));
  yaml::RequireMap(src, node, path, keys);
  SeriesSpec series;
  series.at = yaml::Place(src, node);
  if (values == SeriesValues::kCsvFiles && !node["csv"] && !node["noise"]) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               "give csv (the measured values, to fit) or noise (the columns and their noise "
               "levels, enough for an experiment design)");
  }
  ReadFields(src, node, path, entry, series);
  if (series.csv) {
    series.csv = Relative(base_dir, *series.csv);
    series.csv_at = yaml::Place(src, node["csv"]);
  }
  if (const Document& noise = node["noise"]) {
    if (!noise.IsMap() || noise.size() == 0) {
      yaml::Fail(src, noise, path + ".noise", yaml::Describe(noise),
                 "must be a map from column names to standard deviations, e.g. {length: 2.0e-5}");
    }
    for (std::size_t i = 0; i < noise.size(); ++i) {
      const std::string& column = noise.key(i);
      series.noise.emplace_back(column, yaml::ReadNumberIn(src, noise.items()[i],
                                                           path + ".noise." + column, kNoiseRange));
    }
  }
  return series;
}

SeriesParameterSpec ReadParameter(const yaml::Source& src, const Document& node,
                                  const std::string& path) {
  const PartVariant<SeriesParameterSpec>& entry = SeriesParameterEntry().front();
  std::vector<std::string> keys;
  AddVariantKeys(entry, keys);
  yaml::RequireMap(src, node, path, keys);
  SeriesParameterSpec parameter;
  parameter.at = yaml::Place(src, node);
  ReadFields(src, node, path, entry, parameter);
  const auto steps = SplitKeyPath(parameter.path);
  if (!steps || steps->empty()) {
    yaml::Fail(src, node["path"], path + ".path", yaml::Describe(node["path"]),
               "must be a dotted key path into the scenario, e.g. model.f_iso or load[0].value");
  }
  if (const Document& bounds = node["bounds"]) {
    if (!(parameter.lower && parameter.upper && *parameter.lower < *parameter.upper)) {
      yaml::Fail(src, bounds, path + ".bounds", yaml::Describe(bounds),
                 "must be [lower, upper] with lower < upper");
    }
    if (parameter.start &&
        (*parameter.start < *parameter.lower || *parameter.start > *parameter.upper)) {
      yaml::Fail(src, node["start"], path + ".start", yaml::Describe(node["start"]),
                 "must lie within bounds " + yaml::Describe(bounds));
    }
  }
  return parameter;
}

}  // namespace

bool IsIdentifySeriesFile(const std::string& path) {
  const Document& root = yaml::LoadFile(path);
  return root.IsMap() && root["scenario"];
}

IdentifySeriesSpec LoadIdentifySeriesSpec(const std::string& path) {
  return ParseIdentifySeriesSpec(path, yaml::ReadText(path),
                                 std::filesystem::path(path).parent_path().string());
}

namespace {

IdentifySeriesSpec ReadSpec(const yaml::Source& src, const Document& root,
                            const std::string& base_dir, SeriesValues values) {
  const std::string& source = src.file;
  yaml::RequireMap(src, root, "", VariantKeys(IdentifySeriesFile(), "file"));
  IdentifySeriesSpec spec;
  spec.source = source;
  ReadFields(src, root, "", IdentifySeriesFile().front(), spec);
  spec.scenario = Relative(base_dir, spec.scenario);
  spec.scenario_at = yaml::Place(src, root["scenario"]);

  const Document& series = yaml::Required(src, root, "", "series");
  if (!series.IsSequence() || series.size() == 0) {
    yaml::Fail(src, series, "series", yaml::Describe(series),
               values == SeriesValues::kCsvFiles
                   ? "must be a list of one or more series, each {csv: FILE, noise: {COLUMN: SD}}"
                   : "must be a list of one or more series");
  }
  for (std::size_t i = 0; i < series.size(); ++i) {
    spec.series.push_back(
        ReadSeries(src, series[i], "series[" + std::to_string(i) + "]", base_dir, values));
  }

  const Document& parameters = yaml::Required(src, root, "", "parameters");
  if (!parameters.IsSequence() || parameters.size() == 0) {
    yaml::Fail(src, parameters, "parameters", yaml::Describe(parameters),
               "must be a list of one or more parameters, each {path: P, start: V, "
               "bounds: [L, U]}");
  }
  std::set<std::string> seen;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const std::string at = "parameters[" + std::to_string(i) + "]";
    spec.parameters.push_back(ReadParameter(src, parameters[i], at));
    if (!seen.insert(spec.parameters.back().path).second) {
      yaml::Fail(src, parameters[i]["path"], at + ".path", spec.parameters.back().path,
                 "is listed twice: each parameter once");
    }
  }
  return spec;
}

}  // namespace

IdentifySeriesSpec ParseIdentifySeriesSpec(const std::string& source, const std::string& text,
                                           const std::string& base_dir, SeriesValues values) {
  return ReadSpec(yaml::Source{source}, yaml::Parse(source, text), base_dir, values);
}

IdentifySeriesSpec ReadIdentifySeriesSpec(const Document& document, const std::string& name,
                                          const std::string& base_dir, SeriesValues values) {
  return ReadSpec(yaml::Source{name, name}, document, base_dir, values);
}

}  // namespace musclesim
