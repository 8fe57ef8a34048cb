#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_workers.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/output_file.h"

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
  std::unique_ptr<SweepBase> base;  // this thread's own copy
  MetricAccumulator metrics;        // of the running point
  std::string trajectory_folder;
  Simulation simulation;  // re-used by every point of this thread
};

PointRunner::PointRunner(const SweepSpec& spec, const SweepBase& base, std::string output)
    : state_(std::make_unique<State>(spec, base.Copy())) {
  const std::filesystem::path out(output);
  state_->trajectory_folder =
      (out.parent_path() / (out.stem().string() + "_trajectories")).string();
}

PointRunner::~PointRunner() = default;

SweepRow PointRunner::Run(long index) {
  State& s = *state_;
  SweepRow row;
  row.index = index;
  row.values = PointValues(s.spec, index);
  row.numbers = PointNumbers(s.spec, index);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.metrics.assign(s.spec.metrics.size(), nan);

  // kept from validation for small sweeps; built (and so validated) here for large ones
  try {
    s.base->Prepare(s.spec, index);
  } catch (const InputError& e) {
    row.status = RowStatus::kInvalid;
    row.message = e.what();  // the factory's, naming the axes at fault
    return row;
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
  row.status = failed ? RowStatus::kFailed : RowStatus::kOk;
  for (std::size_t m = 0; m < s.spec.metrics.size(); ++m) {
    if (s.metrics.points() > 0 && !failed) row.metrics[m] = s.metrics.Value(s.spec.metrics[m]);
  }
  row.steps = stats.steps;
  row.rhs_evals = stats.rhs_evals;
  row.wall_seconds = stats.wall_seconds;
  row.message = stats.message;

  const bool keep = s.spec.trajectories == TrajectoryPolicy::kAll ||
                    (s.spec.trajectories == TrajectoryPolicy::kFailed && failed);
  if (keep && s.metrics.points() > 0) {
    std::filesystem::create_directories(s.trajectory_folder);
    WriteOutput(s.trajectory_folder + "/" + std::to_string(index) + ".csv",
                s.base->TrajectoryCsv());
  }
  return row;
}

std::string FormatSummaryRow(const SweepRow& row) {
  std::string text = std::to_string(row.index);
  for (const std::string& v : row.values) text.append(",").append(CsvField(v));
  text.append(",").append(ToString(row.status));
  for (double value : row.metrics) text.append(",").append(MetricField(value));
  if (row.status == RowStatus::kInvalid)
    return text.append(",0,0,0,").append(CsvField(row.message));
  text.append(",").append(std::to_string(row.steps));
  text.append(",").append(std::to_string(row.rhs_evals));
  text.append(",").append(FormatFull(row.wall_seconds));
  return text.append(",").append(CsvField(row.message));
}

WorkerPool::WorkerPool(const SweepSpec& spec, const SweepBase& base, std::string output, int jobs,
                       std::size_t low_water)
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

void WorkerPool::Work(const SweepSpec& spec, const SweepBase& base, const std::string& output) {
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
      SweepRow row = runner.Run(index);
      std::string text = FormatSummaryRow(row);
      const RowStatus status = row.status;
      std::lock_guard<std::mutex> lock(mutex_);
      done_.push_back({index, std::move(text), status, std::move(row)});
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

namespace {

// The summary of a sweep kept in memory: the rows by index, no file, no resume.
class SummaryTable {
 public:
  explicit SummaryTable(long points) : points_(points), unhanded_(points) {}
  long Points() const { return points_; }
  long Count() const { return static_cast<long>(rows_.size()); }
  const std::string& dropped() const { return dropped_; }
  long Unhanded() const { return unhanded_; }
  std::vector<long> Hand(long max) {
    std::vector<long> indices;
    for (; next_ < points_ && static_cast<long>(indices.size()) < max; ++next_) {
      indices.push_back(next_);
    }
    unhanded_ -= static_cast<long>(indices.size());
    return indices;
  }
  void Add(WorkerPool::Row& row) { rows_.push_back(std::move(row.row)); }
  void Flush() {}
  SweepOutcome Close() {
    std::sort(rows_.begin(), rows_.end(),
              [](const SweepRow& a, const SweepRow& b) { return a.index < b.index; });
    SweepOutcome outcome;
    outcome.points = points_;
    outcome.ran = Count();
    for (const SweepRow& row : rows_) {
      outcome.failed += row.status == RowStatus::kFailed;
      outcome.invalid += row.status == RowStatus::kInvalid;
    }
    outcome.interrupted = Count() < points_;
    outcome.rows = std::move(rows_);
    return outcome;
  }

 private:
  long points_, next_ = 0, unhanded_;
  std::vector<SweepRow> rows_;
  std::string dropped_;
};

// The thread runner's loop: points handed to the pool a few at a time, rows into `summary`.
template <typename Summary>
SweepOutcome RunWithSummary(const SweepPlan& plan, const SweepRunOptions& options,
                            SweepObserver& observer, Summary& summary) {
  if (!summary.dropped().empty()) observer.OnNotice(summary.dropped());
  const long points = summary.Points();
  observer.OnProgress(summary.Count(), points);

  const auto base = std::make_unique<SweepBase>(plan.points->Copy());
  const int jobs = static_cast<int>(
      std::min<long>(WorkerThreads(options.jobs), std::max<long>(1, summary.Unhanded())));
  // indices go out a few at a time, so that a sweep of any size starts at once
  const auto low_water = static_cast<std::size_t>(4 * jobs);
  WorkerPool pool(plan.spec, *base, options.output, jobs, low_water);
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
    for (WorkerPool::Row& row : pool.Take()) summary.Add(row);
    summary.Flush();
    observer.OnProgress(summary.Count(), points);
  }
  return summary.Close();
}

}  // namespace

void SummaryFile::Add(FinishedRow& row) { Add(row.index, row.text, row.status); }

SweepOutcome RunSweep(const SweepPlan& plan, const SweepRunOptions& options) {
  SweepObserver silent;
  SweepObserver& observer = options.observer != nullptr ? *options.observer : silent;
  CheckSummaryPath(plan.spec, options.output);
  if (options.output.empty()) {
    if (options.resume) {
      throw InputError("resume continues the summary file of an interrupted sweep: give its path");
    }
    SummaryTable summary(PointCount(plan.spec));
    return RunWithSummary(plan, options, observer, summary);
  }
  SummaryFile summary(plan.spec, options.output, options.resume);
  return RunWithSummary(plan, options, observer, summary);
}

}  // namespace musclesim
