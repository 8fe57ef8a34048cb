// Private: the rows of a running sweep, appended to PATH.partial as they finish, and the
// summary PATH written from them at the end. PATH.partial starts with the sweep's signature
// (sweep_signature.h) and the summary's header; it is locked (flock) while a sweep writes
// it, so that a second sweep on the same output is refused rather than mixed in, and the
// kernel releases the lock when the process ends however it ends. Memory: one bit a point.
#pragma once

#include <string>
#include <vector>

#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_summary_row.h"

namespace musclesim {

struct FinishedRow;  // sweep_workers.h

class SummaryFile {
 public:
  // Opens and locks PATH.partial. With `resume`, keeps its rows that pass CheckRow (the
  // others are dropped from the file, and their points run again: see dropped()), after
  // checking that it belongs to this sweep; without, refuses an existing one. Throws
  // InputError when another sweep holds the file, when it exists without `resume`, or when
  // it belongs to another sweep; std::runtime_error on an I/O error.
  SummaryFile(const SweepSpec& spec, std::string path, bool resume);
  ~SummaryFile();
  SummaryFile(const SummaryFile&) = delete;
  SummaryFile& operator=(const SummaryFile&) = delete;

  long Points() const { return points_; }
  long Count() const { return count_; }  // rows in the summary
  // What resuming dropped from PATH.partial and why, for the user; empty if nothing.
  const std::string& dropped() const { return dropped_; }

  // Up to `max` indices neither in the summary nor handed out before, in order: those that
  // MPI rank `owner` keeps (SweepSpec::share_*) while it has any left, then those of the
  // rank with the most left.
  std::vector<long> Hand(long max, int owner = 0);
  long Unhanded() const { return unhanded_; }

  // Takes one finished row; Flush writes it. Not thread-safe: callers serialise.
  void Add(long index, const std::string& row, RowStatus status);
  // The same for a row of this process's workers (sweep_workers.h).
  void Add(FinishedRow& row);
  // Writes the rows taken since the last Flush through to PATH.partial, in one write.
  void Flush();
  // The sweep's outcome; when every point is in, writes PATH (rows sorted by index) and
  // removes PATH.partial. Releases the lock.
  SweepOutcome Close();

 private:
  void Resume(const SweepSpec& spec, const std::string& signature);
  void Append(const std::string& text);

  std::string path_, partial_path_, header_;
  int fd_ = -1;  // PATH.partial, locked
  long points_ = 0;
  std::vector<bool> done_;  // per point: its row is in
  long count_ = 0, resumed_ = 0, failed_ = 0, invalid_ = 0;
  long next_ = 0, unhanded_ = 0;  // Hand's cursor; points not in and not handed out
  // with several ranks keeping shares: each rank's cursor and its points not yet handed out
  long share_block_ = 1;
  int share_ranks_ = 1;
  std::vector<long> share_next_, share_left_;
  std::string pending_;  // rows taken, not yet written
  std::string dropped_;
};

}  // namespace musclesim
