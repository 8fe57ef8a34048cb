// Progress of `musclesim sweep` on standard error: a bar with rate and ETA on a terminal
// (redrawn at most every 0.2 s), a plain line every ten seconds otherwise, so that logs of
// batch jobs stay short.
#pragma once

namespace musclesim::cli {

class ProgressReport {
 public:
  explicit ProgressReport(bool quiet);  // quiet: never prints

  // `done` of `total` points are finished. The first call only marks the start, so the rate
  // counts the work done from then on (not points resumed from an earlier run).
  void Update(long done, long total);
  // Prints the last state once more, whatever the time since the last print; a newline
  // ends the bar. Does nothing if Update was never called.
  void Finish();

 private:
  void Print(bool final);

  bool quiet_, terminal_;
  bool started_ = false;
  long start_done_ = 0, done_ = 0, total_ = 0;  // points
  double start_ = 0.0, last_print_ = -1e9;      // steady-clock time [s]
};

}  // namespace musclesim::cli
