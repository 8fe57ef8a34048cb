#include "musclesim/studies/sweep_runner.h"
#include "studies/sweep_workers.h"
#include "studies/sweep_point_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "musclesim/errors.h"
#include "musclesim/io/output_file.h"

namespace musclesim {

namespace {

std::string MetricField(double value) { return std::isfinite(value) ? FormatFull(value) : ""; }

}  // namespace

std::string SummaryHeader(const SweepSpec& spec) {
  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "," + std::string
  std::string header = "index";
  for (const SweepAxis& axis : spec.axes) header.append(",").append(axis.path);
  header += ",status";
  for (Metric m : spec.metrics) header.append(",").append(ToString(m));
  return header + ",steps,rhs_evals,wall_seconds,message";
}

struct PointRunner::State {
  State(const SweepSpec& s, std::unique_ptr<SweepBase> b)
      : spec(s), base(std::move(b)), metrics(s.metrics, s.metric_options) {}
  const SweepSpec& spec;
  std::unique_ptr<SweepBase> base;                 // this thread's own copy
  MetricAccumulator metrics;                       // of the running point
  std::unique_ptr<PointErrorExplainer> explainer;  // made at this thread's first invalid point
  std::string trajectory_folder;
  Simulation simulation;                           // re-used by every point of this thread
};

PointRunner::PointRunner(const SweepSpec& spec, const SweepBase& base, std::string output)
    : state_(std::make_unique<State>(spec, base.Copy())) {
  const std::filesystem::path out(output);
  state_->trajectory_folder =
      (out.parent_path() / (out.stem().string() + "_trajectories")).string();
}

PointRunner::~PointRunner() = default;

std::string PointRunner::Run(long index, RowStatus& status) {
  State& s = *state_;
  const std::vector<std::string> values = PointValues(s.spec, index);
  std::string row = std::to_string(index);
  for (const std::string& v : values) row.append(",").append(CsvField(v));

  // kept from validation for small sweeps; built (and so validated) here for large ones
  try {
    s.base->Prepare(s.spec, index);
  } catch (const InputError& e) {
    std::string message = e.what();
    try {
      if (!s.explainer) s.explainer = std::make_unique<PointErrorExplainer>(s.spec, *s.base);
      message = s.explainer->Explain(index, message).message;
    } catch (const std::exception&) {
      // the base file went away since the sweep started: keep the reader's own message
    }
    status = RowStatus::kInvalid;
    row.append(",").append(ToString(status));
    for (std::size_t m = 0; m < s.spec.metrics.size(); ++m) row += ',';
    return row.append(",0,0,0,").append(CsvField(message));
  }

  RunStats stats;
  s.metrics.Reset();
  try {
    stats = s.base->Run(s.simulation, s.metrics);
  } catch (const std::exception& e) {
    stats.status = RunStatus::kFailed;
    stats.message = e.what();
  }
  const bool failed = stats.status == RunStatus::kFailed;
  status = failed ? RowStatus::kFailed : RowStatus::kOk;

  row.append(",").append(ToString(status));
  for (Metric m : s.spec.metrics) {
    row += ',';
    if (s.metrics.points() > 0 && !failed) row += MetricField(s.metrics.Value(m));
  }
  row.append(",").append(std::to_string(stats.steps));
  row.append(",").append(std::to_string(stats.rhs_evals));
  row.append(",").append(FormatFull(stats.wall_seconds));
  row.append(",").append(CsvField(stats.message));

  const bool keep = s.spec.trajectories == TrajectoryPolicy::kAll ||
                    (s.spec.trajectories == TrajectoryPolicy::kFailed && failed);
  if (keep && s.metrics.points() > 0) {
    std::filesystem::create_directories(s.trajectory_folder);
    WriteOutput(s.trajectory_folder + "/" + std::to_string(index) + ".csv",
                s.base->TrajectoryCsv());
  }
  return row;
}

WorkerPool::WorkerPool(const SweepSpec& spec, const SweepBase& base, std::string output,
                       int jobs, std::size_t low_water)
    : low_water_(low_water) {
  running_ = jobs;
  for (int j = 0; j < jobs; ++j) {
    threads_.emplace_back([this, &spec, &base, output] { Work(spec, base, output); });
  }
}

WorkerPool::~WorkerPool() {
  {
    // leaving early (an error): drop the points not started
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.clear();
    closed_ = true;
    work_ready_.notify_all();
  }
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::Work(const SweepSpec& spec, const SweepBase& base,
                      const std::string& output) {
  try {
    PointRunner runner(spec, base, output);
    for (;;) {
      long index = 0;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        work_ready_.wait(lock, [this] { return !queue_.empty() || closed_; });
        if (queue_.empty()) break;
        index = queue_.front();
        queue_.pop_front();
      }
      RowStatus status = RowStatus::kOk;
      std::string row = runner.Run(index, status);
      std::lock_guard<std::mutex> lock(mutex_);
      done_.push_back({index, std::move(row), status});
      if (queue_.size() < low_water_ || closed_) row_ready_.notify_all();
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = std::current_exception();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  --running_;
  row_ready_.notify_all();
}

void WorkerPool::Push(const std::vector<long>& indices) {
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.insert(queue_.end(), indices.begin(), indices.end());
  work_ready_.notify_all();
}

void WorkerPool::Close() {
  std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  work_ready_.notify_all();
}

void WorkerPool::Stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.clear();
  closed_ = true;
  work_ready_.notify_all();
}

std::vector<WorkerPool::Row> WorkerPool::Take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Row> rows;
  rows.swap(done_);
  return rows;
}

std::size_t WorkerPool::Queued() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

bool WorkerPool::Finished() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return running_ == 0 && done_.empty();
}

void WorkerPool::Wait(double seconds) {
  std::unique_lock<std::mutex> lock(mutex_);
  row_ready_.wait_for(lock, std::chrono::duration<double>(seconds), [this] {
    return (!done_.empty() && (queue_.size() < low_water_ || closed_)) || running_ == 0 || error_;
  });
  if (error_) std::rethrow_exception(error_);
}

int WorkerThreads(int jobs) {
  if (jobs > 0) return jobs;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

SweepOutcome RunSweep(const SweepSpec& spec, const SweepRunOptions& options) {
  SweepObserver silent;
  SweepObserver& observer = options.observer != nullptr ? *options.observer : silent;
  CheckSummaryPath(spec, options.output);
  SummaryFile summary(spec, options.output, options.resume);
  if (!summary.dropped().empty()) observer.OnNotice(summary.dropped());
  const long points = summary.Points();
  observer.OnProgress(summary.Count(), points);

  const std::unique_ptr<SweepBase> base = OpenSweepBase(spec);
  const int jobs = static_cast<int>(
      std::min<long>(WorkerThreads(options.jobs), std::max<long>(1, summary.Unhanded())));
  // indices go out a few at a time, so that a sweep of any size starts at once
  const auto low_water = static_cast<std::size_t>(4 * jobs);
  WorkerPool pool(spec, *base, options.output, jobs, low_water);
  bool stopping = false, closed = false;
  while (!pool.Finished()) {
    // the observer is asked on this thread only, so it need not be thread-safe
    if (!stopping && observer.StopRequested()) {
      pool.Stop();
      stopping = closed = true;
    }
    if (!closed && pool.Queued() < low_water) {
      const std::vector<long> indices = summary.Hand(16L * jobs);
      if (indices.empty()) {
        pool.Close();
        closed = true;
      } else {
        pool.Push(indices);
      }
    }
    pool.Wait(closed ? 0.2 : 0.05);
    for (const WorkerPool::Row& row : pool.Take()) summary.Add(row.index, row.text, row.status);
    summary.Flush();
    observer.OnProgress(summary.Count(), points);
  }
  return summary.Close();
}

}  // namespace musclesim
