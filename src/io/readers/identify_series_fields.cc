// The time-series data file of `musclesim identify` described (identify_series_spec.h).
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/identify_series_spec.h"

namespace musclesim {

namespace {

// A start value or bound: the scenario's own rules check the value itself; this range keeps
// the fit's arithmetic (differences and squares of steps) finite.
constexpr InputRange kParameterRange{
    -1e12, 1e12, "the parameter's unit",
    "beyond 1e12 no quantity of a scenario lies, and steps between such values stay finite"};

// The optional number `member` of a parameter's entry, keyed `key`.
NumberField<SeriesParameterSpec> Optional(const char* key,
                                          std::optional<double> SeriesParameterSpec::*member,
                                          const char* doc) {
  NumberField<SeriesParameterSpec> field{
      key,
      kParameterRange,
      std::nullopt,
      doc,
      [member](const SeriesParameterSpec& p) { return (p.*member).value_or(0.0); },
      [member](SeriesParameterSpec& p, double v) { p.*member = v; }};
  field.given = [member](const SeriesParameterSpec& p) { return (p.*member).has_value(); };
  return field;
}

}  // namespace

const std::vector<PartVariant<IdentifySeriesSpec>>& IdentifySeriesFile() {
  static const std::vector<PartVariant<IdentifySeriesSpec>> file = [] {
    PartVariant<IdentifySeriesSpec> spec = OnlyVariant<IdentifySeriesSpec>(
        "file", "the experiment, the series measured in it and the parameters estimated", {});
    TextField<IdentifySeriesSpec> scenario{
        "scenario", "the scenario of the experiment's known inputs, relative to the data file",
        [](const IdentifySeriesSpec& s) { return s.scenario; },
        [](IdentifySeriesSpec& s, std::string path) { s.scenario = std::move(path); }};
    scenario.required = true;
    spec.texts = {std::move(scenario)};
    spec.other_keys = {"series", "parameters"};
    return std::vector{std::move(spec)};
  }();
  return file;
}

const std::vector<PartVariant<SeriesSpec>>& SeriesEntry() {
  static const std::vector<PartVariant<SeriesSpec>> entry = [] {
    PartVariant<SeriesSpec> series =
        OnlyVariant<SeriesSpec>("series[k]", "one measured trajectory: csv, noise or both", {});
    series.texts = {{"csv",
                     "its measured values, a column per quantity beside time, relative to the "
                     "data file; none for --design alone (then noise names the columns)",
                     [](const SeriesSpec& s) { return s.csv.value_or(""); },
                     [](SeriesSpec& s, std::string path) { s.csv = std::move(path); }}};
    series.other_keys = {"noise"};
    return std::vector{std::move(series)};
  }();
  return entry;
}

const std::vector<PartVariant<SeriesParameterSpec>>& SeriesParameterEntry() {
  static const std::vector<PartVariant<SeriesParameterSpec>> entry = [] {
    PartVariant<SeriesParameterSpec> parameter = OnlyVariant<SeriesParameterSpec>(
        "parameters[k]", "one parameter estimated",
        {Optional("start", &SeriesParameterSpec::start,
                  "where the fit starts, within bounds; the scenario's value by default"),
         Optional("bounds[0]", &SeriesParameterSpec::lower,
                  "the lowest value the fit may take; no bound by default"),
         Optional("bounds[1]", &SeriesParameterSpec::upper,
                  "the highest, above bounds[0]; bounds come both or neither")});
    TextField<SeriesParameterSpec> path{
        "path", "a dotted key path into the scenario, as --set takes it (model.f_iso)",
        [](const SeriesParameterSpec& p) { return p.path; },
        [](SeriesParameterSpec& p, std::string key) { p.path = std::move(key); }};
    path.required = true;
    parameter.texts = {std::move(path)};
    return std::vector{std::move(parameter)};
  }();
  return entry;
}

}  // namespace musclesim
