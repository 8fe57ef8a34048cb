#include "musclesim/io/sensitivity_run.h"

#include <algorithm>

#include "io/sensitivity_columns.h"
#include "io/sensitivity_setup.h"
#include "io/yaml_fields.h"
#include "musclesim/io/network_csv.h"
#include "musclesim/io/trajectory_csv.h"
#include "musclesim/model/enum_names.h"
#include "musclesim/model/number_format.h"

namespace musclesim {

constexpr EnumName<DerivativeSource> kSourceNames[] = {
    {DerivativeSource::kAnalytic, "analytic"},
    {DerivativeSource::kDifferenceQuotient, "difference_quotient"},
};

std::string_view ToString(DerivativeSource source) { return ToString(kSourceNames, source); }

int SensitivityTable::FindColumn(const std::string& name) const {
  const auto found = std::find(columns.begin(), columns.end(), name);
  return found == columns.end() ? -1 : static_cast<int>(found - columns.begin());
}

namespace {

// Collects the rows into a SensitivityTable.
class TableSink final : public SensitivitySink {
 public:
  TableSink(const SensitivitySetup& setup, SensitivityTable& table)
      : columns_(setup), table_(table) {
    table_.columns = columns_.names();
    values_.resize(table_.columns.size());
    derivatives_.resize(table_.columns.size() * setup.parameters.size());
  }
  void Record(double t, const double* y, const double* const* s) override {
    columns_.Evaluate(t, y, s, values_.data(), derivatives_.data());
    table_.times.push_back(t);
    table_.values.insert(table_.values.end(), values_.begin(), values_.end());
    table_.derivatives.insert(table_.derivatives.end(), derivatives_.begin(), derivatives_.end());
  }

 private:
  SensitivityColumns columns_;
  SensitivityTable& table_;
  std::vector<double> values_, derivatives_;
};

// Streams the CSV: the plain run's row, then the derivatives.
class CsvSink final : public SensitivitySink {
 public:
  CsvSink(const SensitivitySetup& setup, StreamedOutput& output)
      : setup_(setup), columns_(setup), output_(output) {
    std::string header;
    if (setup.actuator != nullptr) {
      with_excitation_ = setup.actuator->excitation().has_value();
      header = std::string(with_excitation_ ? kTrajectoryHeaderWithExcitation : kTrajectoryHeader);
    } else {
      format_.emplace(*setup.system, setup.phase_tolerance);
      header = format_->header();
    }
    for (const std::string& path : setup.paths) {
      for (const std::string& column : columns_.names()) header += ",d_" + column + "/d_" + path;
    }
    output_.Write(header + "\n");
    values_.resize(columns_.names().size());
    derivatives_.resize(columns_.names().size() * setup.parameters.size());
  }
  void Record(double t, const double* y, const double* const* s) override {
    if (setup_.actuator != nullptr) {
      const ActuatorSystem& actuator = *setup_.actuator;
      const ActuatorSample sample = with_excitation_ ? actuator.Observe(t, y[0], y[1], y[2])
                                                     : actuator.Observe(t, y[0], y[1]);
      AppendTrajectoryRow(buffer_, {t, sample}, *setup_.phase_tolerance, with_excitation_);
    } else {
      setup_.system->Observe(t, y, sample_);
      format_->AppendRow(buffer_, t, sample_);
    }
    buffer_.pop_back();  // the newline: the derivatives follow on the row
    columns_.Evaluate(t, y, s, values_.data(), derivatives_.data());
    for (double d : derivatives_) {
      buffer_ += ',';
      buffer_ += FormatFull(d);
    }
    buffer_ += '\n';
    ++rows_;
    if (buffer_.size() > (1u << 16)) Flush();
  }
  void Flush() {
    output_.Write(buffer_);
    buffer_.clear();
  }
  long rows() const { return rows_; }

 private:
  const SensitivitySetup& setup_;
  SensitivityColumns columns_;
  StreamedOutput& output_;
  bool with_excitation_ = false;
  std::optional<NetworkCsvFormat> format_;
  NetworkSample sample_;
  std::string buffer_;
  std::vector<double> values_, derivatives_;
  long rows_ = 0;
};

}  // namespace

bool HasSensitivities(const std::string& path) {
  try {
    const YAML::Node root = yaml::LoadFile(path);
    return root.IsMap() && root["sensitivities"].IsDefined();
  } catch (const std::exception&) {
    return false;
  }
}

SensitivityTable RunWithSensitivities(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      const std::vector<std::string>& parameters,
                                      const std::vector<double>& output_times) {
  SensitivitySetup setup = PrepareSensitivities(path, overrides, parameters);
  if (!output_times.empty()) setup.request.output_times = output_times;
  SensitivityTable table;
  table.parameters = setup.paths;
  table.parameter_values = setup.values;
  table.sources = setup.sources;
  TableSink sink(setup, table);
  Simulation simulation;
  table.stats = simulation.Run(*setup.system, setup.solver, setup.request, setup.parameters, sink);
  return table;
}

SensitivityCsvRun::SensitivityCsvRun(const std::string& path,
                                     const std::vector<std::string>& overrides,
                                     const std::vector<std::string>& parameters)
    : setup_(std::make_unique<SensitivitySetup>(PrepareSensitivities(path, overrides, parameters))) {}

SensitivityCsvRun::~SensitivityCsvRun() = default;

const std::string& SensitivityCsvRun::output_file() const { return setup_->output_file; }
const std::string& SensitivityCsvRun::name() const { return setup_->name; }
const std::vector<std::string>& SensitivityCsvRun::parameters() const { return setup_->paths; }
const std::vector<DerivativeSource>& SensitivityCsvRun::sources() const {
  return setup_->sources;
}

RunStats SensitivityCsvRun::Run(StreamedOutput& output) {
  CsvSink sink(*setup_, output);
  Simulation simulation;
  const RunStats stats =
      simulation.Run(*setup_->system, setup_->solver, setup_->request, setup_->parameters, sink);
  sink.Flush();
  rows_ = sink.rows();
  return stats;
}

}  // namespace musclesim
