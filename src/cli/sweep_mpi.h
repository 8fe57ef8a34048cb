// Sweeps across MPI ranks. Rank 0 hands out indices on request in small chunks (dynamic
// load balancing) and runs points on its own threads too; every rank runs its points on a
// WorkerPool and sends the finished rows back; rank 0 alone writes PATH.partial and PATH.
// Without -DMUSCLESIM_WITH_MPI=ON this compiles to an always-inactive session.
#pragma once

#include "musclesim/studies/sweep_runner.h"

namespace musclesim::cli {

// MPI_Init_thread / MPI_Finalize around a sweep, only when the process was launched by
// mpirun (so a plain `musclesim sweep` never starts MPI).
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return size_ > 1; }
  bool is_root() const { return rank_ == 0; }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  bool initialised_ = false;
  int rank_ = 0;
  int size_ = 1;
};

// The MPI sweep; its summary equals RunSweep's row for row (but for wall_seconds). The
// outcome is meaningful on rank 0.
SweepOutcome RunSweepMpi(const SweepSpec& spec, const SweepRunOptions& options,
                         const MpiSession& session);

}  // namespace musclesim::cli
