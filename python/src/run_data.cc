#include "run_data.h"

#include <pybind11/numpy.h>

#include <cstring>

#include "musclesim/scenario/sensitivity_run.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// Keeps a run with sensitivities column by column: the run's own columns from each row's
// sample, then the derivatives.
class SensitivityRecorder final : public SensitivityRowSink {
 public:
  SensitivityRecorder(const RunColumns& layout, std::size_t derivatives, RunData& data)
      : layout_(layout), derivatives_(derivatives), data_(data), row_(layout.size()) {
    data_.values.resize(layout.size() + derivatives);
  }
  void Record(double t, const NetworkSample& sample, const double*,
              const double* derivatives) override {
    layout_.Fill(t, sample, row_.data());
    for (std::size_t c = 0; c < row_.size(); ++c) data_.values[c].push_back(row_[c]);
    for (std::size_t k = 0; k < derivatives_; ++k) {
      data_.values[row_.size() + k].push_back(derivatives[k]);
    }
  }

 private:
  const RunColumns& layout_;
  std::size_t derivatives_;
  RunData& data_;
  std::vector<double> row_;
};

RunData WithSensitivities(const Scenario& scenario, const std::vector<std::string>& parameters,
                          const std::shared_ptr<const NetworkSystem>& system) {
  std::vector<SensitivityRequest> requests;
  for (const std::string& path : parameters) requests.push_back({path, "sensitivities"});
  const SensitivityRun run(scenario, requests, system);
  RunData data;
  data.layout.emplace(run.scenario(), run.system());
  for (const std::string& path : run.paths()) {
    for (const std::string& column : run.columns())
      data.extra.push_back("d_" + column + "/d_" + path);
  }
  for (std::size_t i = 0; i < run.paths().size(); ++i) {
    data.sensitivities.push_back({run.paths()[i], std::string(ToString(run.sources()[i]))});
  }
  SensitivityRecorder recorder(*data.layout, data.extra.size(), data);
  Simulation simulation;
  data.stats = run.Run(simulation, recorder);
  return data;
}

// `values` handed to NumPy without a copy: the array owns the vector.
py::array_t<double> Array(std::vector<double>&& values) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule free(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(static_cast<py::ssize_t>(owned->size()), owned->data(), free);
}

// A phase column's words as a NumPy str array (<U10), written as UCS-4 in place.
py::array Phases(const RunColumns& layout, std::size_t c, const std::vector<double>& values) {
  constexpr std::size_t kWidth = 10;  // "concentric"
  py::array words(py::dtype("<U10"),
                  std::vector<py::ssize_t>{static_cast<py::ssize_t>(values.size())});
  auto* out = static_cast<char32_t*>(words.mutable_data());
  std::memset(out, 0, values.size() * kWidth * sizeof(char32_t));
  for (std::size_t r = 0; r < values.size(); ++r) {
    const std::string_view word = ToString(layout.PhaseOf(c, values[r]));
    for (std::size_t i = 0; i < word.size(); ++i)
      out[r * kWidth + i] = static_cast<char32_t>(word[i]);
  }
  return words;
}

}  // namespace

RunData RunData::Of(const Scenario& scenario, const std::vector<std::string>& parameters,
                    const std::shared_ptr<const NetworkSystem>& system) {
  if (!parameters.empty() || !scenario.sensitivities.empty()) {
    return WithSensitivities(scenario, parameters, system);
  }
  RecordedRun run = system ? RunScenario(scenario, *system) : RunScenario(scenario);
  RunData data;
  data.layout.emplace(std::move(run.columns));
  data.values = std::move(run.values);
  data.stats = run.stats;
  return data;
}

Result MakeResult(RunData&& data) {
  Result result;
  const RunColumns& layout = *data.layout;
  result.rows = data.values.empty() ? 0 : static_cast<py::ssize_t>(data.values[0].size());
  for (std::size_t c = 0; c < data.values.size(); ++c) {
    const bool own = c < layout.size();
    const std::string& name = own ? layout.names()[c] : data.extra[c - layout.size()];
    if (own && layout.is_phase(c)) {
      result.columns[py::str(name)] = Phases(layout, c, data.values[c]);
    } else {
      result.columns[py::str(name)] = Array(std::move(data.values[c]));
    }
  }
  result.stats = StatsDict(data.stats, data.sensitivities);
  result.run_stats = data.stats;
  return result;
}

py::dict StatsDict(const RunStats& s, const std::vector<SensitivityNote>& notes) {
  py::dict stats;
  stats["steps"] = s.steps;
  stats["rhs_evals"] = s.rhs_evals;
  stats["jac_evals"] = s.jac_evals;
  stats["linear_setups"] = s.linear_setups;
  stats["newton_iters"] = s.newton_iters;
  stats["newton_conv_fails"] = s.newton_conv_fails;
  stats["error_test_fails"] = s.error_test_fails;
  stats["wall_seconds"] = s.wall_seconds;
  stats["final_time"] = s.final_time;
  stats["linear_solver"] = std::string(ToString(s.linear_solver));
  stats["status"] = std::string(ToString(s.status));
  stats["message"] = s.message;
  if (notes.empty()) return stats;
  stats["sensitivity_rhs_evals"] = s.sensitivity_rhs_evals;
  stats["sensitivity_newton_iters"] = s.sensitivity_newton_iters;
  stats["sensitivity_newton_conv_fails"] = s.sensitivity_newton_conv_fails;
  stats["sensitivity_error_test_fails"] = s.sensitivity_error_test_fails;
  py::list parameters;
  for (const SensitivityNote& note : notes) {
    parameters.append(
        py::dict(py::arg("path") = note.path, py::arg("derivative") = note.derivative));
  }
  stats["sensitivities"] = parameters;
  return stats;
}

}  // namespace musclesim::python
