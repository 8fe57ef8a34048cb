#include "musclesim/studies/sweep_runner.h"
#include "studies/sweep_workers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <thread>

#include "musclesim/errors.h"
#include "musclesim/io/output_file.h"
#include "musclesim/io/trajectory_csv.h"

namespace musclesim {

namespace {

// RFC 4180 quoting for the free-text message column.
std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

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
  State(const SweepSpec& s, std::unique_ptr<ScenarioTemplate> b) : spec(s), base(std::move(b)) {}
  const SweepSpec& spec;
  std::unique_ptr<ScenarioTemplate> base;  // this thread's own copy
  std::string trajectory_folder;
  Simulation simulation;                   // re-used by every point of this thread
  std::vector<TrajectoryPoint> trajectory;
};

PointRunner::PointRunner(const SweepSpec& spec, const ScenarioTemplate& base, std::string output)
    : state_(std::make_unique<State>(spec, base.Copy())) {
  const std::filesystem::path out(output);
  state_->trajectory_folder =
      (out.parent_path() / (out.stem().string() + "_trajectories")).string();
}

PointRunner::~PointRunner() = default;

std::string PointRunner::Run(long index, bool& failed) {
  State& s = *state_;
  const std::vector<std::string> values = PointValues(s.spec, index);
  std::string row = std::to_string(index);
  for (const std::string& v : values) row.append(",").append(CsvField(v));

  RunStats stats;
  double phase_tolerance = 0.0;
  s.trajectory.clear();
  try {
    // kept from validation for modest sweeps; rebuilt from the template for huge ones
    std::optional<ScenarioSpec> rebuilt;
    if (s.spec.scenarios.empty()) rebuilt = s.base->Instantiate(PointOverrides(s.spec, index));
    const ScenarioSpec& scenario =
        rebuilt ? *rebuilt : s.spec.scenarios[static_cast<std::size_t>(index)];
    const ActuatorSystem system(scenario.model.params, scenario.actuator, scenario.activation,
                                scenario.loads);
    stats = s.simulation.Run(system, scenario.solver, scenario.Request(), s.trajectory);
    phase_tolerance = scenario.PhaseTolerance();
  } catch (const std::exception& e) {
    stats.status = RunStatus::kFailed;
    stats.message = e.what();
  }
  failed = stats.status == RunStatus::kFailed;

  row += failed ? ",failed" : ",ok";
  for (Metric m : s.spec.metrics) {
    row += ',';
    if (!s.trajectory.empty() && !failed) {
      row += MetricField(ComputeMetric(m, s.trajectory, s.spec.metric_options));
    }
  }
  row.append(",").append(std::to_string(stats.steps));
  row.append(",").append(std::to_string(stats.rhs_evals));
  row.append(",").append(FormatFull(stats.wall_seconds));
  row.append(",").append(CsvField(stats.message));

  const bool keep = s.spec.trajectories == TrajectoryPolicy::kAll ||
                    (s.spec.trajectories == TrajectoryPolicy::kFailed && failed);
  if (keep && !s.trajectory.empty()) {
    std::filesystem::create_directories(s.trajectory_folder);
    WriteOutput(s.trajectory_folder + "/" + std::to_string(index) + ".csv",
                FormatTrajectoryCsv(s.trajectory, phase_tolerance));
  }
  return row;
}

SummaryFile::SummaryFile(std::string path, std::string header, bool resume, long points)
    : path_(std::move(path)),
      partial_path_(path_ + ".partial"),
      header_(std::move(header)),
      points_(points),
      partial_(nullptr, &std::fclose) {
  const bool exists = std::filesystem::exists(partial_path_);
  if (exists && !resume) {
    throw InputError(partial_path_ + " exists: an earlier sweep was interrupted. Pass --resume "
                     "to continue it, or delete the file to start again");
  }
  if (exists) {
    // keep every complete row; a line cut short by a kill has no newline and is dropped
    std::ifstream in(partial_path_);
    std::string line;
    std::getline(in, line);
    if (line != header_) {
      throw InputError(partial_path_ + ": its header differs from this sweep's (" + header_ +
                       "): it belongs to another sweep");
    }
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string row = text.substr(start, end - start);
      char* tail = nullptr;
      const long index = std::strtol(row.c_str(), &tail, 10);
      if (tail == row.c_str() || *tail != ',' || index < 0 || index >= points) continue;
      if (rows_.emplace(index, row).second && row.find(",failed,") != std::string::npos) ++failed_;
    }
  }
  resumed_ = Count();
  // rewrite the partial file with exactly the rows kept, then append to it
  partial_.reset(std::fopen(partial_path_.c_str(), "w"));
  if (!partial_) throw std::runtime_error(partial_path_ + ": cannot write");
  std::fprintf(partial_.get(), "%s\n", header_.c_str());
  for (const auto& [index, row] : rows_) std::fprintf(partial_.get(), "%s\n", row.c_str());
  std::fflush(partial_.get());
}

void SummaryFile::Add(long index, const std::string& row, bool failed) {
  std::fprintf(partial_.get(), "%s\n", row.c_str());
  std::fflush(partial_.get());
  if (rows_.emplace(index, row).second && failed) ++failed_;
}

std::vector<long> SummaryFile::Remaining() const {
  std::vector<long> todo;
  for (long i = 0; i < points_; ++i) {
    if (rows_.count(i) == 0) todo.push_back(i);
  }
  return todo;
}

SweepOutcome SummaryFile::Close() {
  SweepOutcome outcome;
  outcome.points = points_;
  outcome.resumed = resumed_;
  outcome.ran = Count() - resumed_;
  outcome.failed = failed_;
  outcome.interrupted = Count() < points_;
  if (outcome.interrupted) return outcome;
  std::string text = header_ + "\n";
  for (const auto& [index, row] : rows_) text += row + "\n";
  WriteOutput(path_, text);
  partial_.reset();
  std::filesystem::remove(partial_path_);
  return outcome;
}

WorkerPool::WorkerPool(const SweepSpec& spec, const ScenarioTemplate& base, std::string output,
                       int jobs) {
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

void WorkerPool::Work(const SweepSpec& spec, const ScenarioTemplate& base,
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
      bool failed = false;
      std::string row = runner.Run(index, failed);
      std::lock_guard<std::mutex> lock(mutex_);
      done_.push_back({index, std::move(row), failed});
      row_ready_.notify_all();
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
  row_ready_.wait_for(lock, std::chrono::duration<double>(seconds),
                      [this] { return !done_.empty() || running_ == 0 || error_; });
  if (error_) std::rethrow_exception(error_);
}

int WorkerThreads(int jobs) {
  if (jobs > 0) return jobs;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

SweepOutcome RunSweep(const SweepSpec& spec, const SweepRunOptions& options) {
  SweepObserver silent;
  SweepObserver& observer = options.observer != nullptr ? *options.observer : silent;
  const long points = PointCount(spec);
  SummaryFile summary(options.output, SummaryHeader(spec), options.resume, points);
  const std::vector<long> todo = summary.Remaining();
  observer.OnProgress(summary.Count(), points);

  const ScenarioTemplate base(spec.base);
  WorkerPool pool(spec, base, options.output,
                  std::min<long>(WorkerThreads(options.jobs), std::max<long>(1, todo.size())));
  pool.Push(todo);
  pool.Close();
  bool stopping = false;
  while (!pool.Finished()) {
    // the observer is asked on this thread only, so it need not be thread-safe
    if (!stopping && observer.StopRequested()) {
      pool.Stop();
      stopping = true;
    }
    pool.Wait(0.2);
    for (const WorkerPool::Row& row : pool.Take()) summary.Add(row.index, row.text, row.failed);
    observer.OnProgress(summary.Count(), points);
  }
  return summary.Close();
}

}  // namespace musclesim
