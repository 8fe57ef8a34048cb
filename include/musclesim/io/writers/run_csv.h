// A run as CSV: the scenario's RunColumns (scenario/run_columns.h) as a header line and one
// row per recorded point, numbers with 17 significant digits (read back, the same doubles),
// phases as words. Whole, or streamed row by row as the run records them, so that memory does
// not grow with the run's length. Formatting never happens inside the right-hand side.
#pragma once

#include <string>
#include <vector>

#include "musclesim/io/writers/output_file.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/run_columns.h"
#include "musclesim/scenario/sensitivity_run.h"

namespace musclesim {

// The header line of `columns`, without its newline.
std::string CsvHeader(const RunColumns& columns);

// Appends one row (`row` as RunColumns::Fill writes it), without its newline, to `csv`.
void AppendCsvRow(std::string& csv, const RunColumns& columns, const double* row);

// The header and every row of `run`, each line ending in a newline.
std::string FormatRunCsv(const RecordedRun& run);

// Streams a run's CSV into `output`: the header at once, rows in blocks of about 64 KiB.
// Keeps the count of rows and the last one. Flush() before committing the output.
class RunCsvWriter final : public NetworkSink {
 public:
  // The columns of `scenario` built as `system`, which must outlive the writer.
  RunCsvWriter(StreamedOutput& output, const Scenario& scenario, const NetworkSystem& system);
  // A row straight from the state when the columns allow (RunColumns::FillFromState).
  bool RecordState(double t, const double* y) override;
  void Record(double t, const NetworkSample& sample) override;
  void Flush();

  const RunColumns& columns() const { return columns_; }
  long rows() const { return rows_; }
  // The last row's values (RunColumns::Fill's); valid once rows() > 0.
  const std::vector<double>& last() const { return row_; }

 private:
  void Append();

  StreamedOutput& output_;
  const NetworkSystem& system_;
  RunColumns columns_;
  std::vector<double> row_;
  std::vector<ElementSample> scratch_;
  std::string buffer_;
  long rows_ = 0;
};

// Streams a run with sensitivities (`musclesim run --sensitivity`): each row's columns as
// RunCsvWriter writes them, then d_COLUMN/d_PATH for every parameter (in order) and every
// differentiated column of the run (SensitivityRun::columns). Flush() before committing.
class SensitivityCsvWriter final : public SensitivityRowSink {
 public:
  // Keeps no reference to `run`.
  SensitivityCsvWriter(StreamedOutput& output, const SensitivityRun& run);
  void Record(double t, const NetworkSample& sample, const double* values,
              const double* derivatives) override;
  void Flush();
  long rows() const { return rows_; }

 private:
  StreamedOutput& output_;
  RunColumns columns_;
  std::size_t derivatives_;  // parameters x differentiated columns
  std::vector<double> row_;
  std::string buffer_;
  long rows_ = 0;
};

}  // namespace musclesim
