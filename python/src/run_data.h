// A run's rows and counters held in C++ (made without the GIL), and their Python form: the
// CLI CSV's columns as NumPy arrays, the --stats JSON as a dict (musclesim.Result). No text
// in between: the numbers are the ones the CSV would print to 17 digits.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "musclesim/io/writers/stats_json.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/run_columns.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim::python {

struct RunData {
  std::optional<RunColumns> layout;         // the run's own columns
  std::vector<std::vector<double>> values;  // those columns', then `extra` ones'
  std::vector<std::string> extra;           // d_COLUMN/d_PATH of a run with sensitivities
  RunStats stats;
  std::vector<SensitivityNote> sensitivities;  // each parameter, with sensitivities

  // `scenario` run as `musclesim run` runs it; with `parameters` (key paths) and the
  // scenario's own `sensitivities:`, as `run --sensitivity`. Needs no GIL. `system`, when not
  // null, is scenario.Build()'s, not built again.
  static RunData Of(const Scenario& scenario, const std::vector<std::string>& parameters,
                    const std::shared_ptr<const NetworkSystem>& system = nullptr);
};

// One run in Python's hands.
struct Result {
  pybind11::dict columns;  // {name: 1-D array}: float64, or str for a phase column
  pybind11::dict stats;    // as --stats writes them
  pybind11::ssize_t rows = 0;
  RunStats run_stats;  // the same, typed
};

// The Python form of `data` (taken apart). Needs the GIL.
Result MakeResult(RunData&& data);

// The counters as the --stats JSON writes them, in its order.
pybind11::dict StatsDict(const RunStats& stats, const std::vector<SensitivityNote>& notes = {});

}  // namespace musclesim::python
