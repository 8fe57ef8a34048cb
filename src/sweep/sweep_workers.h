// Private: the machinery of a sweep, shared by the thread and MPI runners: one point's
// runner and the pool of worker threads (the summary file is in sweep_summary.h).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_base.h"
#include "sweep/sweep_summary.h"
#include "sweep/sweep_summary_row.h"

namespace musclesim {

// Runs single points. One per thread: it owns its copy of the base, Simulation and buffers.
class PointRunner {
 public:
  // `output` is the summary path, which names the trajectory folder.
  PointRunner(const SweepSpec& spec, const SweepBase& base, std::string output);
  ~PointRunner();

  // Runs point `index` and returns its summary row. A point not validated up front that is
  // not a valid scenario gives an `invalid` row saying why.
  SweepRow Run(long index);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// A point's row as a worker finished it.
struct FinishedRow {
  long index;
  std::string text;  // FormatSummaryRow's
  RowStatus status;
  SweepRow row;
};

// Worker threads that run the points pushed to them, each thread with its own
// PointRunner, taking the next queued index as soon as it is free (dynamic scheduling).
class WorkerPool {
 public:
  using Row = FinishedRow;

  // `low_water`: Wait wakes for a finished row only when fewer points than this are queued
  // (the owner should queue more), the pool is closing, or a thread stopped; otherwise rows
  // wait for the owner's next call, so that the owner's thread does not wake for every row.
  WorkerPool(const SweepSpec& spec, const SweepBase& base, std::string output, int jobs,
             std::size_t low_water);
  ~WorkerPool();  // closes and joins
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void Push(const std::vector<long>& indices);  // queue more points
  void Close();                                 // no more points will come
  void Stop();                                  // drop queued points, close; running ones finish
  std::vector<Row> Take();                      // rows finished since the last call
  std::size_t Queued() const;                   // points not yet started
  bool Finished() const;                        // closed, and every thread has stopped
  // Waits until a row finishes with fewer than low_water points queued (or the pool closed),
  // a thread stops, or `seconds` pass. Rethrows a worker's exception (an I/O error, say).
  void Wait(double seconds);
  int jobs() const { return static_cast<int>(threads_.size()); }

 private:
  void Work(const SweepSpec& spec, const SweepBase& base, const std::string& output);

  mutable std::mutex mutex_;
  std::condition_variable work_ready_, row_ready_;
  std::deque<long> queue_;
  std::vector<Row> done_;
  bool closed_ = false;
  std::size_t low_water_ = 0;
  int running_ = 0;
  std::exception_ptr error_;
  std::vector<std::thread> threads_;
};

// Worker threads for `jobs`: `jobs` itself when > 0, otherwise one per core
// (std::thread::hardware_concurrency, at least 1).
int WorkerThreads(int jobs);

}  // namespace musclesim
