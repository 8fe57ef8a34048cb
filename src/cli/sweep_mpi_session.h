// MPI_Init_thread / MPI_Finalize around `musclesim sweep`, only when the process was launched
// by mpirun, so that a plain `musclesim sweep` never starts MPI. Initialising MPI is the
// program's business; the sweep itself (musclesim/sweep/sweep_mpi.h) only uses it.
// Without -DMUSCLESIM_WITH_MPI=ON this compiles to an always-inactive session.
#pragma once

namespace musclesim::cli {

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
  [[maybe_unused]] bool initialised_ = false;  // read and set only in an MPI build
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace musclesim::cli
