// One run of a scenario: its system built and integrated by a Simulation, every recorded row
// handed to a sink as it is produced. What the rows hold is the scenario's RunColumns
// (scenario/run_columns.h): the CSV writer (io/writers/run_csv.h) streams them to a file, a
// ColumnRecorder keeps them in memory for code (and the Python module's NumPy arrays).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "musclesim/scenario/run_columns.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// Integrates `scenario` on `simulation` (whose CVODE memory a caller running many scenarios
// re-uses), handing every recorded row to `sink`. A solver failure, a collapsed element among
// them, is a status (kFailed) with its message, not an exception; an exception from the sink
// ends the run and propagates. Throws ParameterError when the scenario's parts do not fit.
RunStats RunScenario(const Scenario& scenario, Simulation& simulation, NetworkSink& sink);
// The same on `system`, built from `scenario` (a LoadedScenario's): not built again.
RunStats RunScenario(const Scenario& scenario, const NetworkSystem& system, Simulation& simulation,
                     NetworkSink& sink);

// Keeps a run's rows column by column, as RunColumns lays them out.
class ColumnRecorder final : public NetworkSink {
 public:
  // The columns of `scenario` built as `system`, which must outlive the recorder.
  ColumnRecorder(const Scenario& scenario, const NetworkSystem& system);

  // A row straight from the state when the columns allow (RunColumns::FillFromState).
  bool RecordState(double t, const double* y) override;
  void Record(double t, const NetworkSample& sample) override;
  // Room for `rows` rows in every column, so that recording allocates no more.
  void Reserve(std::size_t rows);
  // Forgets the rows, keeping their memory: for the next run of the same scenario.
  void Clear();

  const RunColumns& layout() const { return layout_; }
  std::size_t rows() const { return rows_; }
  // Column c's values: numbers, or for a phase column the shortening velocities [m/s] that
  // layout().PhaseOf classifies.
  const std::vector<double>& column(std::size_t c) const { return columns_[c]; }
  std::vector<double>& column(std::size_t c) { return columns_[c]; }

 private:
  void Keep();

  const NetworkSystem& system_;
  RunColumns layout_;
  std::vector<std::vector<double>> columns_;
  std::vector<double> row_;
  std::vector<ElementSample> scratch_;
  std::size_t rows_ = 0;
};

// A run in memory: its columns and its counters.
struct RecordedRun {
  RunColumns columns;                       // the names, and how phase columns classify
  std::vector<std::vector<double>> values;  // per column (a phase column: see ColumnRecorder)
  RunStats stats;

  // The phase of row `row` of phase column `c`.
  Phase phase(std::size_t c, std::size_t row) const { return columns.PhaseOf(c, values[c][row]); }
};

// RunScenario on a new Simulation into a ColumnRecorder.
RecordedRun RunScenario(const Scenario& scenario);
// The same on `system`, built from `scenario`.
RecordedRun RunScenario(const Scenario& scenario, const NetworkSystem& system);

// The number of rows a run of `scenario` records on its output grid (an every-step run: 0,
// unknown before it runs), for reserving memory.
std::size_t ExpectedRows(const Scenario& scenario);

}  // namespace musclesim
