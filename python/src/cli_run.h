// A run as `musclesim run` makes it, without its files: the CSV text and the --stats JSON,
// parsed into NumPy columns. Scenario.run and run_many share it, so both give the CLI's
// columns, named and ordered as its CSV, to the last digit it prints (17 significant digits
// read back give the same double).
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace musclesim::python {

// What one run wrote: the CSV text and the stats JSON of `musclesim run --stats`.
struct RunText {
  std::string csv;
  std::string stats_json;
};

// `musclesim run PATH --set ... --sensitivity ...` (run_command.cc's branches and writers),
// the CSV written to a temporary file and read back. Needs no GIL; throws as the CLI does.
RunText RunLikeCli(const std::string& path, const std::vector<std::string>& overrides,
                   const std::vector<std::string>& sensitivities);

// The CSV split into columns: numbers, or text for the phase columns. Needs no GIL.
struct CsvColumns {
  std::vector<std::string> names;
  std::vector<bool> text;                          // per column: a phase column
  std::vector<std::vector<double>> numbers;        // per numeric column
  std::vector<std::vector<std::string>> texts;     // per text column
  std::size_t rows = 0;
};
CsvColumns SplitCsv(const std::string& csv);

// One run's columns ({name: 1-D array}, float64 or str for the phase columns) and stats.
struct Result {
  pybind11::dict columns;
  pybind11::dict stats;
  pybind11::ssize_t rows = 0;
};
Result MakeResult(const CsvColumns& columns, const std::string& stats_json);

}  // namespace musclesim::python
