// Watching and steering a running sweep: progress, a stop request and, under MPI, the error
// that is about to end every rank. The library never prints and keeps no process-wide state;
// whoever runs the sweep (the CLI, a notebook, a test) decides what progress looks like and
// when to stop, so two sweeps in one process never affect each other.
#pragma once

#include <exception>
#include <string>

namespace musclesim {

// Hooks a sweep calls while it runs. Every method has a do-nothing default; override what
// you need. Passed by pointer in SweepRunOptions: the caller owns it and keeps it alive
// until the sweep returns.
class SweepObserver {
 public:
  virtual ~SweepObserver() = default;

  // `done` of `total` points are in the summary, counting the rows resumed from
  // PATH.partial. Called first before any point runs (done = the resumed rows), then
  // whenever rows have come in, and last after the final row is in or the sweep stopped;
  // `done` never decreases. Called only on the thread that runs the sweep, and under MPI
  // on rank 0 alone. Throttling output is the observer's business.
  virtual void OnProgress(long /*done*/, long /*total*/) {}

  // Something the user should know that does not stop the sweep, as one printable line:
  // rows of PATH.partial dropped on resume, and why. Called before any point runs, on the
  // thread that runs the sweep (rank 0 under MPI).
  virtual void OnNotice(const std::string& /*message*/) {}

  // Polled on the thread that runs the sweep (on every MPI rank) between rows and at least
  // every 0.2 s. Once it returns true the sweep starts no new points, lets the running ones
  // finish, keeps their rows in PATH.partial and returns an interrupted outcome.
  virtual bool StopRequested() { return false; }

  // Under MPI: `error` escaped the sweep on rank `rank` (this process), and the library is
  // about to end every rank with MPI_Abort, since the others would otherwise wait for this
  // one forever. Returns the error code passed to MPI_Abort (the job's exit status).
  virtual int OnRankError(int /*rank*/, const std::exception& /*error*/) { return 1; }
};

}  // namespace musclesim
