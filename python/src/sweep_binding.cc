// musclesim._run_many (many scenarios on C++ threads, for musclesim.run_many) and
// musclesim._sweep (a sweep file or dict, its summary in memory or written where asked); the
// GIL is released while anything runs, and nothing goes through a file the caller did not ask
// for.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "document.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/sweep/sweep_file.h"
#include "musclesim/sweep/sweep_observer.h"
#include "musclesim/sweep/sweep_runner.h"
#include "overrides.h"
#include "py_scenario.h"
#include "run_data.h"
#include "typed_objects.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

// One job: a Scenario in memory, or a file to read with overrides.
struct Job {
  std::optional<Scenario> scenario;
  std::string path;
  std::vector<std::string> overrides;
  std::shared_ptr<const NetworkSystem> system;  // the Scenario's, when it has one
};

// One run's outcome, or what it threw.
struct Outcome {
  RunData data;
  std::exception_ptr error;
};

int ThreadCount(int threads, std::size_t jobs) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int wanted = threads == 0 ? cores : threads;
  return std::max(1, std::min(wanted, static_cast<int>(jobs)));
}

std::vector<Job> JobsFrom(const AnyList& given) {
  std::vector<Job> jobs;
  for (std::size_t k = 0; k < given.size(); ++k) {
    const py::handle item = given[k];
    if (py::isinstance<PyScenario>(item)) {
      const PyScenario& s = item.cast<const PyScenario&>();
      jobs.push_back({s.scenario, "", {}, s.system});
      continue;
    }
    if ((py::isinstance<py::tuple>(item) || py::isinstance<py::list>(item)) && py::len(item) == 2) {
      const py::sequence pair = py::reinterpret_borrow<py::sequence>(item);
      jobs.push_back(
          {std::nullopt, PathText(pair[0], "run_many: a job's path"), OverridesFrom(pair[1]), {}});
      continue;
    }
    throw py::type_error("jobs[" + std::to_string(k) +
                         "] must be a Scenario or a (path, "
                         "overrides) pair, not " +
                         py::repr(item).cast<std::string>());
  }
  return jobs;
}

// Runs `work(k)` for every k < count on `workers` threads, this thread watching for Ctrl-C
// (Python's signal handlers run only on it, with the GIL); true when interrupted.
template <typename Work>
bool RunOnThreads(std::size_t count, int workers, Work work) {
  std::atomic<bool> stop{false};  // Ctrl-C: start no further job
  py::gil_scoped_release release;
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::condition_variable finished;
  int running = workers;
  const auto loop = [&] {
    for (std::size_t k = next++; k < count && !stop; k = next++) work(k);
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    finished.notify_all();
  };
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w) pool.emplace_back(loop);
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
  return stop;
}

std::vector<Result> RunMany(const AnyList& given, int threads,
                            const std::vector<std::string>& sensitivities) {
  const std::vector<Job> jobs = JobsFrom(given);
  std::vector<Outcome> outcomes(jobs.size());
  const bool interrupted =
      RunOnThreads(jobs.size(), ThreadCount(threads, jobs.size()), [&](std::size_t k) {
        try {
          const Job& job = jobs[k];
          if (job.scenario) {
            outcomes[k].data = RunData::Of(*job.scenario, sensitivities, job.system);
          } else {
            const LoadedScenario loaded =
                LoadBuiltScenario(job.path, Overrides(job.overrides, kOverrideLabel), job.path);
            outcomes[k].data = RunData::Of(loaded.scenario, sensitivities, loaded.system);
          }
        } catch (...) {
          outcomes[k].error = std::current_exception();
        }
      });
  if (interrupted) throw py::error_already_set();
  // the first bad job (in the list's order) raises: its error names file, key and value
  for (const Outcome& outcome : outcomes) {
    if (outcome.error) std::rethrow_exception(outcome.error);
  }
  std::vector<Result> results;
  for (Outcome& outcome : outcomes) results.push_back(MakeResult(std::move(outcome.data)));
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

// The sweep `spec` (a path, or a dict whose base may be a Scenario) read and validated.
SweepPlan PlanOf(const py::object& spec, int threads, const std::string& name) {
  if (py::isinstance<py::str>(spec) || py::hasattr(spec, "__fspath__")) {
    const std::string path = PathText(spec, "sweep");
    py::gil_scoped_release release;
    return LoadSweep(path, threads);
  }
  if (!py::isinstance<py::dict>(spec)) {
    throw py::type_error("sweep expects a path or a dict, not " +
                         py::str(py::type::of(spec).attr("__name__")).cast<std::string>());
  }
  py::dict copy = py::reinterpret_borrow<py::dict>(spec).attr("copy")();
  std::optional<PyScenario> base;
  if (copy.contains("base") && py::isinstance<PyScenario>(copy["base"])) {
    base = copy["base"].cast<PyScenario>();
    copy["base"] = base->display;  // its name in messages
  } else if (copy.contains("base") && !copy["base"].is_none() &&
             !py::isinstance<py::str>(copy["base"]) && !py::hasattr(copy["base"], "__fspath__")) {
    throw py::type_error("base must be a scenario file's path or a Scenario, not " +
                         py::repr(copy["base"]).cast<std::string>());
  }
  const Document document = DocumentFrom(copy, "");
  py::gil_scoped_release release;
  if (!base) return ReadSweep(document, name, nullptr, "", threads);
  return ReadSweep(document, name, &base->scenario, base->ToYaml(), threads);
}

// The summary's columns from rows kept in memory: (header, [arrays]).
py::tuple SummaryColumns(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  py::list header, columns;
  const auto numbers = [&](auto value) {
    py::array_t<double> out(n);
    for (py::ssize_t r = 0; r < n; ++r)
      out.mutable_at(r) = value(rows[static_cast<std::size_t>(r)]);
    return out;
  };
  const auto counts = [&](auto value) {
    py::array_t<std::int64_t> out(n);
    for (py::ssize_t r = 0; r < n; ++r)
      out.mutable_at(r) = value(rows[static_cast<std::size_t>(r)]);
    return out;
  };
  const auto texts = [&](auto value) {
    py::list out;
    for (const SweepRow& row : rows) out.append(value(row));
    return py::module_::import("numpy").attr("array")(out, py::arg("dtype") = "object");
  };
  header.append("index");
  columns.append(counts([](const SweepRow& r) { return r.index; }));
  for (std::size_t k = 0; k < spec.axes.size(); ++k) {
    header.append(spec.axes[k].path);
    columns.append(spec.axes[k].is_numeric()
                       ? py::object(numbers([k](const SweepRow& r) { return r.numbers[k]; }))
                       : py::object(texts([k](const SweepRow& r) { return r.values[k]; })));
  }
  header.append("status");
  columns.append(texts([](const SweepRow& r) { return std::string(ToString(r.status)); }));
  for (std::size_t m = 0; m < spec.metrics.size(); ++m) {
    header.append(std::string(ToString(spec.metrics[m])));
    columns.append(numbers([m](const SweepRow& r) { return r.metrics[m]; }));
  }
  header.append("steps");
  columns.append(counts([](const SweepRow& r) { return r.steps; }));
  header.append("rhs_evals");
  columns.append(counts([](const SweepRow& r) { return r.rhs_evals; }));
  header.append("wall_seconds");
  columns.append(numbers([](const SweepRow& r) { return r.wall_seconds; }));
  header.append("message");
  columns.append(texts([](const SweepRow& r) { return r.message; }));
  return py::make_tuple(header, columns);
}

// Runs a sweep; returns its summary's columns when kept in memory (output None), else None
// (the summary is the file `output`).
py::object Sweep(const py::object& spec, int threads, const py::object& output, bool resume,
                 const std::string& name) {
  if (threads < 0) throw py::value_error("threads = " + std::to_string(threads) + ": must be >= 0");
  const SweepPlan plan = PlanOf(spec, threads, name);
  if (plan.spec.trajectories != TrajectoryPolicy::kNone && output.is_none()) {
    throw InputError(InputFault{InputPlace{name}, "trajectories",
                                std::string(ToString(plan.spec.trajectories)),
                                "the runs' CSVs are written beside the summary: give "
                                "sweep(..., output=PATH)"});
  }
  SweepRunOptions options;
  options.output = output.is_none() ? "" : PathText(output, "sweep(output)");
  options.jobs = threads;
  options.resume = resume;
  InterruptObserver observer;
  options.observer = &observer;
  SweepOutcome outcome;
  {
    py::gil_scoped_release release;
    try {
      outcome = RunSweep(plan, options);
    } catch (const InterruptedSweepError& e) {
      throw InputError(e.partial_path() +
                       " exists: an earlier sweep was interrupted. Pass "
                       "resume=True to continue it, or delete the file to start again");
    }
  }
  if (observer.interrupted()) throw py::error_already_set();
  if (!output.is_none()) return py::none();
  return SummaryColumns(plan.spec, outcome.rows);
}

}  // namespace

void BindSweep(py::module_& m) {
  m.def("_run_many", &RunMany, py::arg("jobs"), py::arg("threads"), py::arg("sensitivities"),
        "run_many's C++ half: every job, a Scenario or a (path, overrides) pair (overrides: "
        "None, a list of \"key=value\" strings as --set takes them, or a dict), run on "
        "`threads` C++ threads (0: every core) with the GIL released, each recorded in memory; "
        "one Result per job, in order. A bad job raises (the first in the list's order) after "
        "every job has run. musclesim.run_many is the public way.");
  m.def("_sweep", &Sweep, py::arg("spec"), py::arg("threads"), py::arg("output"), py::arg("resume"),
        py::arg("name"),
        "Runs the sweep `spec` (a sweep file's path, or a dict of its keys whose base may be a "
        "Scenario) as `musclesim sweep` does (threads 0: every core), GIL released, Ctrl-C "
        "stopping it. With `output`, the summary is that file (and `resume` continues an "
        "interrupted one) and None is returned; without, it is kept in memory and returned as "
        "(header, columns). musclesim.sweep() makes the structured array.");
}

}  // namespace musclesim::python
