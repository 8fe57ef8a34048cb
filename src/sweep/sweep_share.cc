#include "sweep/sweep_share.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace musclesim {

int ValidationThreads(const RankShare& share) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int ranks = local != nullptr ? std::max(1, std::atoi(local)) : share.ranks;
  return std::max(1, cores / ranks);
}

long ShareBlock(long points, int ranks) { return std::clamp<long>(points / (4L * ranks), 1, 64); }

int PointOwner(const SweepSpec& spec, long index) {
  return static_cast<int>((index / spec.share_block) % spec.share_ranks);
}

long KeptSlot(const SweepSpec& spec, long index) {
  if (!spec.kept || PointOwner(spec, index) != spec.share_rank) return -1;
  const long block = index / spec.share_block;
  return (block / spec.share_ranks) * spec.share_block + index % spec.share_block;
}

long KeptCount(const SweepSpec& spec) {
  long count = 0;
  const long points = PointCount(spec);
  for (long start = spec.share_rank * spec.share_block; start < points;
       start += spec.share_ranks * spec.share_block) {
    count += std::min(spec.share_block, points - start);
  }
  return count;
}

}  // namespace musclesim
