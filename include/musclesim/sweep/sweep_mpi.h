// A sweep spread over the ranks of MPI_COMM_WORLD. Rank 0 hands out indices on request in
// small chunks (dynamic load balancing; to each rank the points it validated and kept, see
// SweepSpec::share_*, while it has any) and runs points on its own threads too; every rank
// runs its points on a WorkerPool and sends the finished rows back; rank 0 alone writes
// PATH.partial and PATH. Declared in every build; it works only in one configured with
// -DMUSCLESIM_WITH_MPI=ON. Initialising and finalising MPI is the program's business.
#pragma once

#include "musclesim/sweep/sweep_runner.h"

namespace musclesim {

// Runs the sweep on every rank of MPI_COMM_WORLD; every rank must call it with the same
// spec and options (each rank its own observer). MPI must be initialised with at least
// MPI_THREAD_FUNNELED, and this function called from the thread that initialised it.
//
// Returns on rank 0 the outcome RunSweep would give (its summary equals RunSweep's row for
// row but for wall_seconds); other ranks get an empty outcome. `options.jobs` counts the
// threads of each rank. The observer's OnProgress is called on rank 0 alone; StopRequested
// is polled on every rank. When an exception escapes on any rank, that rank reports it
// through OnRankError and ends the whole job with MPI_Abort (the other ranks would wait for
// it forever) with the error code OnRankError returns (1 without an observer).
//
// Throws only std::logic_error, when musclesim was built without MPI or MPI is not
// initialised (or already finalised).
SweepOutcome RunSweepMpi(const SweepPlan& plan, const SweepRunOptions& options);

}  // namespace musclesim
