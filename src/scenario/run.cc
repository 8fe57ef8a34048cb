#include "musclesim/scenario/run.h"

#include <cmath>

#include "musclesim/solver/integration_session.h"

namespace musclesim {

RunStats RunScenario(const Scenario& scenario, Simulation& simulation, NetworkSink& sink) {
  return RunScenario(scenario, scenario.Build(), simulation, sink);
}

RunStats RunScenario(const Scenario& scenario, const NetworkSystem& system, Simulation& simulation,
                     NetworkSink& sink) {
  return simulation.Run(system, scenario.solver, scenario.Request(), sink);
}

ColumnRecorder::ColumnRecorder(const Scenario& scenario, const NetworkSystem& system)
    : system_(system), layout_(scenario, system), columns_(layout_.size()), row_(layout_.size()) {}

void ColumnRecorder::Clear() {
  for (std::vector<double>& column : columns_) column.clear();
  rows_ = 0;
}

void ColumnRecorder::Reserve(std::size_t rows) {
  for (std::vector<double>& column : columns_) column.reserve(rows);
}

bool ColumnRecorder::RecordState(double t, const double* y) {
  if (!layout_.FillFromState(system_, t, y, row_.data(), scratch_)) return false;
  Keep();
  return true;
}

void ColumnRecorder::Record(double t, const NetworkSample& sample) {
  layout_.Fill(t, sample, row_.data());
  Keep();
}

void ColumnRecorder::Keep() {
  for (std::size_t c = 0; c < row_.size(); ++c) columns_[c].push_back(row_[c]);
  ++rows_;
}

std::size_t ExpectedRows(const Scenario& scenario) {
  if (scenario.output.every_step || !(scenario.output.interval > 0.0)) return 0;
  const double rows = (scenario.t_end - scenario.t_start) / scenario.output.interval;
  if (!(rows < 1e8)) return 0;  // not reserved: a run that long ends on a limit first
  return GridRows(OutputGrid{scenario.output.interval, {}}, scenario.t_start, scenario.t_end);
}

RecordedRun RunScenario(const Scenario& scenario) {
  return RunScenario(scenario, scenario.Build());
}

RecordedRun RunScenario(const Scenario& scenario, const NetworkSystem& system) {
  ColumnRecorder recorder(scenario, system);
  recorder.Reserve(ExpectedRows(scenario));
  Simulation simulation;
  RecordedRun run{recorder.layout(), {}, {}};
  run.stats = simulation.Run(system, scenario.solver, scenario.Request(), recorder);
  run.values.reserve(recorder.layout().size());
  for (std::size_t c = 0; c < recorder.layout().size(); ++c) {
    run.values.push_back(std::move(recorder.column(c)));
  }
  return run;
}

}  // namespace musclesim
