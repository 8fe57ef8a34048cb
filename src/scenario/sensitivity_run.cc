#include "musclesim/scenario/sensitivity_run.h"

#include <algorithm>

#include "musclesim/core/enum_names.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/key_path.h"
#include "scenario/sensitivity_columns.h"
#include "scenario/sensitivity_derivatives.h"

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

struct SensitivityRun::Prepared {
  Scenario scenario;
  BuiltScenario base;
  std::vector<std::string> paths;
  std::vector<std::string> network_paths;  // the numbers paths[i] name, for dropping repeats
  std::vector<double> values;
  std::vector<DerivativeSource> sources;
  std::vector<std::unique_ptr<ParameterDerivative>> derivatives;
  std::vector<SensitivityParameter> parameters;  // point into `derivatives`
  std::vector<std::string> columns;
};

namespace {

// A column name must not break the CSV's header: no comma, quote or control character.
bool FitsCsvHeader(const std::string& path) {
  return std::none_of(path.begin(), path.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return c == ',' || c == '"' || byte < 0x20 || byte == 0x7f;
  });
}

// The handle on `request`'s path, or an InputError saying why there is none.
Parameter HandleOf(const Scenario& scenario, const SensitivityRequest& request,
                   std::string& where) {
  const std::string& path = request.path;
  const std::string label = request.where.empty() ? "" : request.where + " ";
  // a path of the key paths' syntax, as the resolver splits them, that a CSV header can hold
  const std::optional<std::vector<KeyPathStep>> steps = SplitKeyPath(path);
  if (!FitsCsvHeader(path) || !steps || steps->empty() || steps->front().key.empty()) {
    // the path as given, cut short: it may be anything
    const std::string shown = path.size() > 80 ? path.substr(0, 80) + "..." : path;
    throw InputError(label + "'" + shown + "': ",
                     InputFault{std::nullopt, "", path,
                                "not a dotted key path such as model.f_iso or load[0].value "
                                "(names without commas, quotes or control characters, indices "
                                "in brackets)"});
  }
  try {
    Parameter parameter = scenario.parameter(path);
    where = label + parameter.path();
    return parameter;
  } catch (const ParameterError& error) {
    throw InputError(label + path + ": ",
                     InputFault{std::nullopt, path, std::nullopt,
                                error.rule() + ": a sensitivity needs a number of the scenario's "
                                               "dynamics"});
  }
}

}  // namespace

SensitivityRun::SensitivityRun(const Scenario& scenario,
                               const std::vector<SensitivityRequest>& parameters,
                               std::shared_ptr<const NetworkSystem> system)
    : prepared_(std::make_unique<Prepared>()) {
  Prepared& p = *prepared_;
  p.scenario = scenario;
  std::vector<SensitivityRequest> requests = parameters;
  for (std::size_t i = 0; i < scenario.sensitivities.size(); ++i) {
    const std::string at = i < scenario.sensitivities_at.size() ? scenario.sensitivities_at[i] : "";
    requests.push_back({scenario.sensitivities[i], (at.empty() ? "" : at + ": ") +
                                                       "sensitivities[" + std::to_string(i) + "]"});
  }
  p.base = BuildScenario(scenario, std::move(system));
  if (!scenario.controllers.empty() && !requests.empty()) {
    // the controllers' terms of the sensitivity equations (docs/model.md 10) are not derived
    const SensitivityRequest& first = requests.front();
    throw InputError((first.where.empty() ? "" : first.where + " ") + first.path +
                     ": sensitivities of a network with controllers are not supported yet (" +
                     scenario.source + " has controllers[0] " + scenario.controllers.front().name +
                     "); run it without sensitivities");
  }
  if (scenario.HasSkeleton() && !requests.empty()) {
    // the skeleton's terms (docs/model.md 15.5) are not derived yet
    const SensitivityRequest& first = requests.front();
    throw InputError((first.where.empty() ? "" : first.where + " ") + first.path +
                     ": sensitivities of a scenario with bodies, joints or wrap surfaces are "
                     "not supported yet (" +
                     scenario.source + " has them); run it without sensitivities");
  }
  for (const SensitivityRequest& request : requests) {
    std::string where;
    const Parameter parameter = HandleOf(scenario, request, where);
    // a repeat, under its own or another name of the number (load.value, load[0].value)
    const std::string& target = parameter.network_path();
    if (std::find(p.network_paths.begin(), p.network_paths.end(), target) !=
        p.network_paths.end()) {
      continue;
    }
    p.network_paths.push_back(target);
    ResolvedParameter resolved =
        ResolveParameter(p.scenario, p.base, parameter, where, request.size);
    p.paths.push_back(resolved.path);
    p.values.push_back(resolved.value);
    p.sources.push_back(resolved.source);
    p.derivatives.push_back(std::move(resolved.derivative));
    const double scale = ParameterSize(resolved.value, request.size);
    p.parameters.push_back({p.derivatives.back().get(), std::move(resolved.initial), scale});
  }
  p.columns = SensitivityColumns(scenario.form, *p.base.system, p.parameters).names();
}

SensitivityRun::~SensitivityRun() = default;

const Scenario& SensitivityRun::scenario() const { return prepared_->scenario; }
const NetworkSystem& SensitivityRun::system() const { return *prepared_->base.system; }
const std::vector<std::string>& SensitivityRun::paths() const { return prepared_->paths; }
const std::vector<double>& SensitivityRun::values() const { return prepared_->values; }
const std::vector<DerivativeSource>& SensitivityRun::sources() const { return prepared_->sources; }
const std::vector<std::string>& SensitivityRun::columns() const { return prepared_->columns; }

namespace {

// Evaluates the differentiated columns of each row for a SensitivityRowSink.
class ColumnsSink final : public SensitivitySink {
 public:
  ColumnsSink(ScenarioForm form, const NetworkSystem& system,
              const std::vector<SensitivityParameter>& parameters, SensitivityRowSink& out)
      : columns_(form, system, parameters), out_(out) {
    values_.resize(columns_.names().size());
    derivatives_.resize(columns_.names().size() * parameters.size());
  }
  void Record(double t, const double* y, const double* const* s) override {
    columns_.Evaluate(t, y, s, values_.data(), derivatives_.data());
    out_.Record(t, columns_.sample(), values_.data(), derivatives_.data());
  }

 private:
  SensitivityColumns columns_;
  SensitivityRowSink& out_;
  std::vector<double> values_, derivatives_;
};

// Collects the rows into a SensitivityTable.
class TableSink final : public SensitivityRowSink {
 public:
  TableSink(SensitivityTable& table, std::size_t columns, std::size_t parameters)
      : table_(table), columns_(columns), derivatives_(columns * parameters) {}
  void Record(double t, const NetworkSample&, const double* values,
              const double* derivatives) override {
    table_.times.push_back(t);
    table_.values.insert(table_.values.end(), values, values + columns_);
    table_.derivatives.insert(table_.derivatives.end(), derivatives, derivatives + derivatives_);
  }

 private:
  SensitivityTable& table_;
  std::size_t columns_, derivatives_;
};

}  // namespace

RunStats SensitivityRun::Run(Simulation& simulation, SensitivityRowSink& sink,
                             const std::vector<double>& output_times) const {
  const Prepared& p = *prepared_;
  NetworkRunRequest request = p.scenario.Request();
  if (!output_times.empty()) request.output_times = output_times;
  ColumnsSink columns(p.scenario.form, *p.base.system, p.parameters, sink);
  return simulation.Run(*p.base.system, p.scenario.solver, request, p.parameters, columns);
}

SensitivityTable RunWithSensitivities(const Scenario& scenario,
                                      const std::vector<std::string>& parameters,
                                      const std::vector<double>& output_times,
                                      const std::vector<double>& sizes) {
  std::vector<SensitivityRequest> requests;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    requests.push_back({parameters[i], "", i < sizes.size() ? sizes[i] : 0.0});
  }
  const SensitivityRun run(scenario, requests);
  SensitivityTable table;
  table.columns = run.columns();
  table.parameters = run.paths();
  table.parameter_values = run.values();
  table.sources = run.sources();
  TableSink sink(table, table.columns.size(), table.parameters.size());
  Simulation simulation;
  table.stats = run.Run(simulation, sink, output_times);
  return table;
}

}  // namespace musclesim
