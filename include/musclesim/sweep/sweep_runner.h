// Running a sweep: points on worker threads with dynamic scheduling (each thread reuses one
// Simulation), rows written to PATH.partial in batches as they finish (within 0.05 s), the
// summary CSV written
// atomically at the end with rows sorted by index. With MPI (sweep_mpi.h) the same rows are
// spread over ranks. Progress and cancellation go through a SweepObserver (sweep_observer.h).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_points.h"
#include "musclesim/sweep/sweep_observer.h"

namespace musclesim {

// The summary's header: index, one column per axis (its path), status (ok, failed, or
// invalid for a point found not to be a valid scenario when it ran), the metrics, steps,
// rhs_evals, wall_seconds, message.
std::string SummaryHeader(const SweepSpec& spec);

// How a point's run went: a row with metrics, a solver failure, or a point that is not a
// valid scenario (found when it ran, for a sweep too large to validate up front).
enum class RowStatus { kOk, kFailed, kInvalid };
std::string_view ToString(RowStatus status);

// One point's row of the summary (SummaryHeader's columns), as values.
struct SweepRow {
  long index = 0;                   // the point [-]
  std::vector<std::string> values;  // its axis values, as the summary writes them [-]
  std::vector<double> numbers;      // the same as numbers (NaN for a word) [their units]
  RowStatus status = RowStatus::kOk;
  std::vector<double> metrics;    // spec.metrics' values, NaN where there is none (a failed
                                  // or invalid point, a length never reached) [their units]
  long steps = 0, rhs_evals = 0;  // the run's counters [-]
  double wall_seconds = 0.0;      // [s]
  std::string message;            // why it failed or is invalid [-]
};

// The summary's CSV line of `row` (without its newline): what PATH holds for it.
std::string FormatSummaryRow(const SweepRow& row);

struct SweepRunOptions {
  std::string output;   // summary CSV path; PATH.partial holds the rows done so far; empty:
                        // the summary is kept in memory (SweepOutcome::rows) and no file is
                        // written, which rules out resume and kept trajectories [-]
  int jobs = 0;         // worker threads (per MPI rank); 0: std::thread::hardware_concurrency [-]
  bool resume = false;  // skip the points whose rows are already in PATH.partial [-]
  SweepObserver* observer = nullptr;  // not owned; null: no progress, never stops early
};

struct SweepOutcome {
  long points = 0;   // in the sweep [-]
  long resumed = 0;  // rows taken from PATH.partial [-]
  long ran = 0;      // points run now [-]
  long failed = 0;   // failed rows in the summary [-]
  long invalid = 0;  // invalid rows in the summary (points not valid scenarios) [-]
  bool interrupted = false;
  std::vector<SweepRow> rows;  // the summary by index, when kept in memory (output empty) [-]
};

// PATH.partial, left by an interrupted sweep, met without `resume`: resuming continues it,
// deleting it starts again.
class InterruptedSweepError : public InputError {
 public:
  explicit InterruptedSweepError(std::string partial_path)
      : InputError(partial_path +
                   " exists: an earlier sweep was interrupted. Resume the sweep "
                   "to continue it, or delete the file to start again"),
        partial_path_(std::move(partial_path)) {}
  const std::string& partial_path() const { return partial_path_; }

 private:
  std::string partial_path_;
};

// Runs every point not yet in the summary on `options.jobs` threads of this process,
// reporting to `options.observer`.
//
// PATH.partial starts with a signature of the sweep (a hash of the base scenario file, the
// points and the metrics) and is locked while the sweep runs. Throws InputError when
// another running sweep holds PATH.partial, when it exists without `resume`
// (InterruptedSweepError), or when it
// belongs to another sweep (naming what changed). On `resume`, rows of PATH.partial that
// are malformed (field count, index, axis values, status, numbers) or repeat a point are
// dropped and their points run again; the observer's OnNotice says so. Rethrows a
// worker's I/O error.
SweepOutcome RunSweep(const SweepPlan& plan, const SweepRunOptions& options);

// Where the summary goes, checked before any point runs (RunSweep does; a caller running the
// sweep another way, over MPI, calls it first): a path that cannot take the summary would
// otherwise fail only after the whole sweep. Throws InputError for a directory, a path whose
// directory does not exist, and the sweep file or its base scenario (an input the summary
// would replace); an empty path is the summary in memory, which cannot keep trajectories.
void CheckSummaryPath(const SweepSpec& spec, const std::string& path);

}  // namespace musclesim
