#include "cli/sweep_mpi_session.h"

#include <cstdlib>

#if MUSCLESIM_WITH_MPI
#include <mpi.h>
#endif

namespace musclesim::cli {

#if MUSCLESIM_WITH_MPI

namespace {

bool LaunchedByMpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!LaunchedByMpirun()) return;
  int provided = 0;
  // only the main thread of each rank calls MPI
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (initialised_) MPI_Finalize();
}

#else  // built without MPI: a session is never active

MpiSession::MpiSession(int&, char**&) {}
MpiSession::~MpiSession() = default;

#endif

}  // namespace musclesim::cli
