#include "musclesim/io/writers/run_csv.h"

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

constexpr std::size_t kBlockBytes = 1 << 16;

}  // namespace

std::string CsvHeader(const RunColumns& columns) {
  std::string header;
  for (const std::string& name : columns.names()) header += (header.empty() ? "" : ",") + name;
  return header;
}

void AppendCsvRow(std::string& csv, const RunColumns& columns, const double* row) {
  const std::vector<char>& phase = columns.phase_flags();
  for (std::size_t c = 0; c < phase.size(); ++c) {
    if (c > 0) csv += ',';
    if (phase[c]) {
      csv += ToString(columns.PhaseOf(c, row[c]));
    } else {
      csv += FormatFull(row[c]);
    }
  }
}

std::string FormatRunCsv(const RecordedRun& run) {
  const RunColumns& columns = run.columns;
  std::string csv = CsvHeader(columns) + "\n";
  const std::size_t rows = run.values.empty() ? 0 : run.values[0].size();
  std::vector<double> row(columns.size());
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) row[c] = run.values[c][r];
    AppendCsvRow(csv, columns, row.data());
    csv += '\n';
  }
  return csv;
}

RunCsvWriter::RunCsvWriter(StreamedOutput& output, const Scenario& scenario,
                           const NetworkSystem& system)
    : output_(output), system_(system), columns_(scenario, system), row_(columns_.size()) {
  buffer_.reserve(kBlockBytes + 4096);
  buffer_ += CsvHeader(columns_);
  buffer_ += '\n';
}

bool RunCsvWriter::RecordState(double t, const double* y) {
  if (!columns_.FillFromState(system_, t, y, row_.data(), scratch_)) return false;
  Append();
  return true;
}

void RunCsvWriter::Record(double t, const NetworkSample& sample) {
  columns_.Fill(t, sample, row_.data());
  Append();
}

void RunCsvWriter::Append() {
  AppendCsvRow(buffer_, columns_, row_.data());
  buffer_ += '\n';
  ++rows_;
  if (buffer_.size() >= kBlockBytes) Flush();
}

void RunCsvWriter::Flush() {
  output_.Write(buffer_);
  buffer_.clear();
}

SensitivityCsvWriter::SensitivityCsvWriter(StreamedOutput& output, const SensitivityRun& run)
    : output_(output),
      columns_(run.scenario(), run.system()),
      derivatives_(run.paths().size() * run.columns().size()),
      row_(columns_.size()) {
  std::string header = CsvHeader(columns_);
  for (const std::string& path : run.paths()) {
    for (const std::string& column : run.columns()) header += ",d_" + column + "/d_" + path;
  }
  output_.Write(header + "\n");
}

void SensitivityCsvWriter::Record(double t, const NetworkSample& sample, const double*,
                                  const double* derivatives) {
  columns_.Fill(t, sample, row_.data());
  AppendCsvRow(buffer_, columns_, row_.data());
  for (std::size_t k = 0; k < derivatives_; ++k) {
    buffer_ += ',';
    buffer_ += FormatFull(derivatives[k]);
  }
  buffer_ += '\n';
  ++rows_;
  if (buffer_.size() > kBlockBytes) Flush();
}

void SensitivityCsvWriter::Flush() {
  output_.Write(buffer_);
  buffer_.clear();
}

}  // namespace musclesim
