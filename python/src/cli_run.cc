#include "cli_run.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "musclesim/io/network_csv.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/output_file.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/sensitivity_run.h"
#include "musclesim/io/trajectory_csv.h"
#include "temp_file.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

std::string ReadWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool IsTextColumn(const std::string& name) {
  const std::string suffix = ".phase";
  return name == "phase" ||
         (name.size() > suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0);
}

std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1) {
    fields.push_back(line.substr(start, comma - start));
  }
  fields.push_back(line.substr(start));
  return fields;
}

}  // namespace

RunText RunLikeCli(const std::string& path, const std::vector<std::string>& overrides,
                   const std::vector<std::string>& sensitivities) {
  TempFile file(".csv");
  RunText text;
  if (!sensitivities.empty() || HasSensitivities(path)) {
    SensitivityCsvRun run(path, overrides, sensitivities);
    StreamedOutput csv(file.path());
    const RunStats stats = run.Run(csv);
    csv.Commit();
    std::vector<SensitivityNote> notes;
    for (std::size_t i = 0; i < run.parameters().size(); ++i) {
      notes.push_back({run.parameters()[i], std::string(ToString(run.sources()[i]))});
    }
    text.stats_json = FormatStatsJson(stats, notes);
  } else if (IsNetworkScenario(path)) {
    const NetworkScenarioSpec spec = LoadNetworkScenario(path, overrides);
    const NetworkSystem system = spec.Build();
    StreamedOutput csv(file.path());
    NetworkCsvWriter writer(csv, system, spec.output.phase_tolerance);
    Simulation simulation;
    const RunStats stats = simulation.Run(system, spec.solver, spec.Request(), writer);
    writer.Flush();
    csv.Commit();
    text.stats_json = FormatStatsJson(stats);
  } else {
    const ScenarioSpec spec = LoadScenario(path, overrides);
    StreamedOutput csv(file.path());
    TrajectoryCsvWriter writer(csv, spec.PhaseTolerance(), spec.excitation.has_value());
    Simulation simulation;
    const RunStats stats = simulation.Run(BuildSystem(spec), spec.solver, spec.Request(), writer);
    writer.Flush();
    csv.Commit();
    text.stats_json = FormatStatsJson(stats);
  }
  text.csv = ReadWhole(file.path());
  return text;
}

CsvColumns SplitCsv(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  CsvColumns columns;
  columns.names = SplitCommas(line);
  for (const std::string& name : columns.names) columns.text.push_back(IsTextColumn(name));
  columns.numbers.resize(columns.names.size());
  columns.texts.resize(columns.names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = SplitCommas(line);
    if (fields.size() != columns.names.size()) {
      throw std::runtime_error("a CSV row has " + std::to_string(fields.size()) +
                               " fields where the header names " +
                               std::to_string(columns.names.size()));
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (columns.text[c]) {
        columns.texts[c].push_back(fields[c]);
      } else {
        columns.numbers[c].push_back(std::strtod(fields[c].c_str(), nullptr));
      }
    }
    ++columns.rows;
  }
  return columns;
}

Result MakeResult(const CsvColumns& columns, const std::string& stats_json) {
  py::module_ numpy = py::module_::import("numpy");
  Result result;
  for (std::size_t c = 0; c < columns.names.size(); ++c) {
    if (columns.text[c]) {
      result.columns[py::str(columns.names[c])] =
          numpy.attr("array")(columns.texts[c], py::arg("dtype") = "str");
    } else {
      const std::vector<double>& numbers = columns.numbers[c];
      py::array_t<double> values(static_cast<py::ssize_t>(numbers.size()));
      if (!numbers.empty()) {
        std::memcpy(values.mutable_data(), numbers.data(), numbers.size() * sizeof(double));
      }
      result.columns[py::str(columns.names[c])] = values;
    }
  }
  result.stats = py::module_::import("json").attr("loads")(stats_json);
  result.rows = static_cast<py::ssize_t>(columns.rows);
  return result;
}

}  // namespace musclesim::python
