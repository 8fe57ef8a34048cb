// Running a sweep: points on worker threads with dynamic scheduling (each thread reuses one
// Simulation), rows flushed to PATH.partial as they finish, the summary CSV written
// atomically at the end with rows sorted by index. With MPI (sweep_mpi.h) the same rows are
// spread over ranks. Progress and cancellation go through a SweepObserver (sweep_observer.h).
#pragma once

#include <string>

#include "musclesim/io/scenario.h"
#include "musclesim/studies/sweep.h"
#include "musclesim/studies/sweep_observer.h"

namespace musclesim {

// The summary's header: index, one column per axis (its path), status, the metrics, steps,
// rhs_evals, wall_seconds, message.
std::string SummaryHeader(const SweepSpec& spec);

struct SweepRunOptions {
  std::string output;   // summary CSV path; PATH.partial holds the rows done so far
  int jobs = 0;         // worker threads (per MPI rank); 0: std::thread::hardware_concurrency
  bool resume = false;  // skip the indices already in PATH.partial
  SweepObserver* observer = nullptr;  // not owned; null: no progress, never stops early
};

struct SweepOutcome {
  long points = 0;      // in the sweep
  long resumed = 0;     // taken from PATH.partial
  long ran = 0;         // run now
  long failed = 0;      // failed rows in the summary
  bool interrupted = false;
};

// Runs every point not yet in the summary on `options.jobs` threads of this process,
// reporting to `options.observer`. Throws InputError when PATH.partial exists without
// `resume` or belongs to another sweep, and rethrows a worker's I/O error.
SweepOutcome RunSweep(const SweepSpec& spec, const SweepRunOptions& options);

}  // namespace musclesim
