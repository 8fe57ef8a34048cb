// musclesim.run_many (many scenarios on C++ threads) and musclesim._run_sweep (a sweep file,
// whose summary musclesim.sweep reads back); the GIL is released while anything runs.
#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/studies/sweep.h"
#include "musclesim/studies/sweep_runner.h"
#include "network_values.h"
#include "overrides.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

struct Job {
  std::string path;
  std::vector<std::string> overrides;
};

// One run's outcome, columns in order.
struct Outcome {
  RunStats stats;
  std::vector<std::pair<std::string, std::vector<double>>> columns;
  std::exception_ptr error;
};

// The single actuator's numeric trajectory columns (its CSV's, without phase; excitation
// always, equal to the activation without activation dynamics).
void RunSingle(const Job& job, Outcome& out) {
  const RunResult result = RunScenarioFile(job.path, job.overrides);
  out.stats = result.stats;
  const char* names[] = {"t", "length", "shortening_velocity", "activation", "excitation",
                         "tension_passive", "tension_active", "tension_total", "load"};
  for (const char* name : names) out.columns.emplace_back(name, std::vector<double>());
  for (const TrajectoryPoint& p : result.trajectory) {
    const double values[] = {p.t, p.sample.length, p.sample.shortening_velocity,
                             p.sample.activation, p.sample.excitation, p.sample.tension.passive,
                             p.sample.tension.active, p.sample.tension.total, p.sample.load};
    for (std::size_t c = 0; c < out.columns.size(); ++c) out.columns[c].second.push_back(values[c]);
  }
}

// A network's numeric CSV columns (network_values.h).
void RunNetwork(const Job& job, Outcome& out) {
  const NetworkScenarioSpec spec = LoadNetworkScenario(job.path, job.overrides);
  const NetworkSystem system = spec.Build();
  Simulation simulation;
  const NetworkRunResult result = simulation.Run(system, spec.solver, spec.Request());
  out.stats = result.stats;
  out.columns.emplace_back("t", result.times);
  for (const std::string& name : NumericNetworkColumns(system)) {
    out.columns.emplace_back(name, std::vector<double>());
    out.columns.back().second.reserve(result.times.size());
  }
  std::vector<double> row;
  for (const NetworkSample& sample : result.samples) {
    row.clear();
    AppendNumericNetworkValues(system, sample, row);
    for (std::size_t c = 0; c < row.size(); ++c) out.columns[c + 1].second.push_back(row[c]);
  }
}

int ThreadCount(int threads, std::size_t jobs) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int wanted = threads == 0 ? cores : threads;
  return std::max(1, std::min(wanted, static_cast<int>(jobs)));
}

py::list RunMany(const py::list& jobs_in, int threads) {
  std::vector<Job> jobs;
  for (const py::handle item : jobs_in) {
    const py::tuple pair = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
    if (pair.size() != 2) throw py::value_error("jobs: every job must be a (path, overrides) pair");
    jobs.push_back({pair[0].cast<std::string>(), OverridesFrom(pair[1])});
  }
  std::vector<Outcome> outcomes(jobs.size());
  const int workers = ThreadCount(threads, jobs.size());
  {
    py::gil_scoped_release release;
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      for (std::size_t k = next++; k < jobs.size(); k = next++) {
        try {
          if (IsNetworkScenario(jobs[k].path)) {
            RunNetwork(jobs[k], outcomes[k]);
          } else {
            RunSingle(jobs[k], outcomes[k]);
          }
        } catch (...) {
          outcomes[k].error = std::current_exception();
        }
      }
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
  }
  // the first bad job (in the list's order) raises: its error names file, key and value
  for (const Outcome& outcome : outcomes) {
    if (outcome.error) std::rethrow_exception(outcome.error);
  }
  py::list results;
  for (Outcome& outcome : outcomes) {
    py::dict columns;
    for (auto& [name, values] : outcome.columns) {
      columns[py::str(name)] =
          py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
    }
    py::dict result;
    result["status"] = std::string(ToString(outcome.stats.status));
    result["steps"] = outcome.stats.steps;
    result["final_time"] = outcome.stats.final_time;
    result["message"] = outcome.stats.message;
    result["columns"] = columns;
    results.append(result);
  }
  return results;
}

py::dict RunSweepFile(const std::string& path, const std::string& output, int threads) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  SweepOutcome outcome;
  {
    py::gil_scoped_release release;
    const SweepSpec spec = LoadSweep(path, threads);
    SweepRunOptions options;
    options.output = output;
    options.jobs = threads;
    outcome = RunSweep(spec, options);
  }
  py::dict result;
  result["points"] = outcome.points;
  result["failed"] = outcome.failed;
  result["invalid"] = outcome.invalid;
  return result;
}

}  // namespace

void BindSweep(py::module_& m) {
  m.def("run_many", &RunMany, py::arg("jobs"), py::arg("threads") = 0,
        "Runs every job, a (path, overrides) pair (overrides: None, a list of \"key=value\" "
        "strings as --set takes them, or a dict), on `threads` C++ threads (0: every core) "
        "with the GIL released. The scenario may be single-actuator or a network. Returns, "
        "in the jobs' order, dicts {status: \"completed\"|\"limit\"|\"failed\", steps, "
        "final_time [s], message, columns: {name: float64 array}}. Columns: a single "
        "actuator's t, length, shortening_velocity, activation, excitation (= activation "
        "without activation dynamics), tension_passive, tension_active, tension_total, load; "
        "a network's t and its CSV's columns without the text <actuator>.phase (as "
        "Stepper.sample()). SI units. A bad job raises (the first in the list's order) after "
        "every job has run.");
  m.def("_run_sweep", &RunSweepFile, py::arg("path"), py::arg("output"), py::arg("threads") = 0,
        "Runs the sweep file `path` as `musclesim sweep PATH -o output --jobs threads` does "
        "(threads 0: every core), GIL released; returns {points, failed, invalid}. "
        "musclesim.sweep() reads the summary back.");
}

}  // namespace musclesim::python
