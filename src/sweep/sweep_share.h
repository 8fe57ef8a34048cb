// Private: how the points of a sweep validated up front are shared among MPI ranks (each
// validates and keeps its blocks of points, SweepSpec::share_*), and the few MPI calls that
// validation needs, which do nothing in a build without MPI or a process without it.
#pragma once

#include "musclesim/sweep/sweep.h"

namespace musclesim {

struct RankShare {
  int rank = 0;
  int ranks = 1;
};

// This process's rank among MPI_COMM_WORLD's when MPI is initialised (and not finalised);
// {0, 1} otherwise.
RankShare WorldShare();

// The smallest `value` over every rank (collective: every rank must call it); `value` itself
// for one rank.
long MinOverRanks(long value);

// Threads that validation may use on this host: every core, divided among the MPI ranks
// started on it (OMPI_COMM_WORLD_LOCAL_SIZE, else all of `share.ranks`).
int ValidationThreads(const RankShare& share);

// The block size sharing `points` among `ranks`: small enough that every rank has some
// blocks, at most 64 points so that the shares stay interleaved.
long ShareBlock(long points, int ranks);

// The rank that keeps point `index` of `spec`.
int PointOwner(const SweepSpec& spec, long index);

// Where point `index` is in this rank's kept scenarios; -1 when it is not kept here.
long KeptSlot(const SweepSpec& spec, long index);

// How many of the sweep's points this rank keeps.
long KeptCount(const SweepSpec& spec);

}  // namespace musclesim
