// musclesim.run_many (many scenarios on C++ threads) and musclesim._run_sweep (a sweep file,
// whose summary musclesim.sweep reads back); the GIL is released while anything runs.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cli_run.h"
#include "musclesim/core/errors.h"
#include "file_alias.h"
#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_observer.h"
#include "musclesim/sweep/sweep_runner.h"
#include "overrides.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

struct Job {
  std::string path;
  std::vector<std::string> overrides;
};

// One run's outcome: its CSV's columns and stats, or what it threw.
struct Outcome {
  CsvColumns columns;
  std::string stats_json;
  std::exception_ptr error;
};

int ThreadCount(int threads, std::size_t jobs) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int wanted = threads == 0 ? cores : threads;
  return std::max(1, std::min(wanted, static_cast<int>(jobs)));
}

py::list RunMany(const py::list& jobs_in, int threads,
                 const std::vector<std::string>& sensitivities) {
  std::vector<Job> jobs;
  for (const py::handle item : jobs_in) {
    const py::tuple pair = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
    if (pair.size() != 2) throw py::value_error("jobs: every job must be a (path, overrides) pair");
    jobs.push_back({PathText(pair[0], "run_many: a job's path"), OverridesFrom(pair[1])});
  }
  std::vector<Outcome> outcomes(jobs.size());
  const int workers = ThreadCount(threads, jobs.size());
  std::atomic<bool> stop{false};  // Ctrl-C: start no further job
  {
    py::gil_scoped_release release;
    std::atomic<std::size_t> next{0};
    std::mutex mutex;
    std::condition_variable finished;
    int running = workers;
    const auto work = [&] {
      for (std::size_t k = next++; k < jobs.size() && !stop; k = next++) {
        try {
          const RunText text = RunLikeCli(jobs[k].path, jobs[k].overrides, sensitivities);
          outcomes[k].columns = SplitCsv(text.csv);
          outcomes[k].stats_json = text.stats_json;
        } catch (...) {
          outcomes[k].error = std::current_exception();
        }
      }
      const std::lock_guard<std::mutex> lock(mutex);
      --running;
      finished.notify_all();
    };
    std::vector<std::thread> pool;
    for (int w = 0; w < workers; ++w) pool.emplace_back(work);
    // this thread watches for Ctrl-C (Python's signal handlers run only on it, with the GIL)
    std::unique_lock<std::mutex> lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(100));
      if (running == 0 || stop) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) stop = true;  // the KeyboardInterrupt stays pending
      }
      lock.lock();
    }
    lock.unlock();
    for (std::thread& thread : pool) thread.join();
  }
  if (stop) throw py::error_already_set();
  // the first bad job (in the list's order) raises: its error names file, key and value
  for (const Outcome& outcome : outcomes) {
    if (outcome.error) std::rethrow_exception(outcome.error);
  }
  py::list results;
  for (const Outcome& outcome : outcomes) {
    results.append(py::cast(MakeResult(outcome.columns, outcome.stats_json)));
  }
  return results;
}

// Stops a sweep at Ctrl-C: polled between rows on the thread that called sweep().
class InterruptObserver : public SweepObserver {
 public:
  bool StopRequested() override {
    if (interrupted_) return true;
    py::gil_scoped_acquire gil;
    interrupted_ = PyErr_CheckSignals() != 0;  // the KeyboardInterrupt stays pending
    return interrupted_;
  }
  // Ctrl-C was seen: its KeyboardInterrupt is pending, even when the last points finished
  // anyway and the summary is whole.
  bool interrupted() const { return interrupted_; }

 private:
  bool interrupted_ = false;
};

py::dict RunSweepFile(const std::string& path, const std::string& output, bool output_given,
                      bool resume, int threads, const std::string& display) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  SweepOutcome outcome;
  InterruptObserver observer;
  {
    py::gil_scoped_release release;
    outcome = WithFileAlias(path, display, [&] {
      const SweepSpec spec = LoadSweep(path, threads);
      if (spec.trajectories != TrajectoryPolicy::kNone && !output_given) {
        throw InputError("trajectories = " + std::string(ToString(spec.trajectories)) + " (" +
                         display + "): the runs' CSVs are written beside the summary: give "
                         "sweep(..., output=PATH)");
      }
      SweepRunOptions options;
      options.output = output;
      options.jobs = threads;
      options.resume = resume;
      options.observer = &observer;
      return RunSweep(spec, options);
    });
  }
  if (observer.interrupted()) throw py::error_already_set();
  py::dict result;
  result["points"] = outcome.points;
  result["failed"] = outcome.failed;
  result["invalid"] = outcome.invalid;
  return result;
}

}  // namespace

void BindSweep(py::module_& m) {
  m.def("run_many", &RunMany, py::arg("jobs"), py::arg("threads") = 0,
        py::arg("sensitivities") = std::vector<std::string>{},
        "Runs every job, a (path, overrides) pair (overrides: None, a list of \"key=value\" "
        "strings as --set takes them, or a dict), on `threads` C++ threads (0: every core) "
        "with the GIL released. The scenario may be single-actuator or a network. Returns, "
        "in the jobs' order, one Result each, as Scenario.run() gives: .columns exactly "
        "`musclesim run`'s CSV columns (float64; the phase columns str), .stats its --stats "
        "dict, .status 'completed', 'limit' or 'failed'; `sensitivities` (dotted paths) adds "
        "the d_<column>/d_<path> columns to every run, as Scenario.run does. SI units. A bad job raises (the "
        "first in the list's order) after every job has run; musclesim.table() stacks the "
        "results into one structured array.");
  m.def("_run_sweep", &RunSweepFile, py::arg("path"), py::arg("output"), py::arg("output_given"),
        py::arg("resume"), py::arg("threads"), py::arg("display"),
        "Runs the sweep file `path` as `musclesim sweep PATH -o output --jobs threads "
        "[--resume]` does (threads 0: every core), GIL released, Ctrl-C stopping it (the rows "
        "done stay in output.partial); returns {points, failed, invalid}; input errors name "
        "the file `display` in place of `path`. musclesim.sweep() reads the summary back.");
}

}  // namespace musclesim::python
