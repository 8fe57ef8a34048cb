#include "musclesim/sweep/sweep_mpi.h"
#include "sweep/sweep_workers.h"
#include "sweep/sweep_share.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#if MUSCLESIM_WITH_MPI
#include <mpi.h>
#endif

namespace musclesim {

#if MUSCLESIM_WITH_MPI

namespace {

enum Tag : int {
  kRequest = 1,  // worker -> root: {1 for more work or 0 when it stops, its thread count}
  kWork = 2,     // root -> worker: indices (longs); none means stop
  kResult = 3,   // worker -> root: finished rows, one per line, its status letter in front
  kDone = 4,     // worker -> root: every row of this rank has been sent (empty message)
};

// A row's status as one letter on the wire: O ok, F failed, I invalid.
char StatusLetter(RowStatus status) {
  switch (status) {
    case RowStatus::kOk: return 'O';
    case RowStatus::kFailed: return 'F';
    case RowStatus::kInvalid: return 'I';
  }
  return '?';
}

RowStatus StatusOfLetter(char letter) {
  return letter == 'F' ? RowStatus::kFailed : letter == 'I' ? RowStatus::kInvalid : RowStatus::kOk;
}

std::string Encode(const std::vector<WorkerPool::Row>& rows) {
  std::string text;
  for (const WorkerPool::Row& row : rows) {
    text.append(1, StatusLetter(row.status)).append(row.text).append("\n");
  }
  return text;
}

// Points a rank keeps queued beyond its running ones, so that its threads never wait for
// the next chunk while a request goes to rank 0 and back.
std::size_t LowWater(int jobs) { return static_cast<std::size_t>(4 * jobs); }

// Rank 0: serves requests, runs its own share, gathers every row.
SweepOutcome Root(const SweepSpec& spec, const SweepRunOptions& options, int ranks,
                  SweepObserver& observer, WorkerPool& pool) {
  SummaryFile summary(spec, options.output, options.resume);
  if (!summary.dropped().empty()) observer.OnNotice(summary.dropped());
  const long points = summary.Points();
  observer.OnProgress(summary.Count(), points);

  // rank `rank` gets the points it validated and keeps while it has any (SweepSpec::share_*)
  const auto chunk = [&](int workers, int rank) {
    // small chunks near the end keep every rank busy until the last point
    const long size = std::clamp<long>(summary.Unhanded() / (4L * ranks * workers), 1, 64);
    return summary.Hand(size, rank);
  };

  // a rank that was told to stop may still be running points: it is done only when it says so,
  // after its last rows (messages between two ranks arrive in the order they were sent)
  int done_ranks = 0;
  bool closed = false, stopping = false;
  while (done_ranks < ranks - 1 || !pool.Finished()) {
    // feed this rank's own threads
    if (!stopping && observer.StopRequested()) {
      pool.Stop();
      stopping = closed = true;
    }
    if (!closed && summary.Unhanded() == 0) {
      pool.Close();
      closed = true;
    }
    if (!closed && pool.Queued() < LowWater(pool.jobs())) pool.Push(chunk(pool.jobs(), 0));
    for (const WorkerPool::Row& row : pool.Take()) summary.Add(row.index, row.text, row.status);

    // serve every message waiting, then sleep until a row or 1 ms passes
    for (;;) {
      int waiting = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
      if (!waiting) break;
      if (status.MPI_TAG == kRequest) {
        int wants[2] = {0, 1};  // {wants more, that rank's threads}
        MPI_Recv(wants, 2, MPI_INT, status.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::vector<long> indices;
        if (wants[0] != 0 && summary.Unhanded() > 0 && !stopping) {
          indices = chunk(wants[1], status.MPI_SOURCE);
        }
        MPI_Send(indices.data(), static_cast<int>(indices.size()), MPI_LONG, status.MPI_SOURCE,
                 kWork, MPI_COMM_WORLD);
      } else if (status.MPI_TAG == kDone) {
        MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        ++done_ranks;
      } else if (status.MPI_TAG == kResult) {
        int bytes = 0;
        MPI_Get_count(&status, MPI_CHAR, &bytes);
        std::string text(static_cast<std::size_t>(bytes), '\0');
        MPI_Recv(text.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kResult, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        std::size_t start = 0;
        for (std::size_t end; (end = text.find('\n', start)) != std::string::npos;
             start = end + 1) {
          const std::string row = text.substr(start + 1, end - start - 1);
          summary.Add(std::strtol(row.c_str(), nullptr, 10), row, StatusOfLetter(text[start]));
        }
      }
    }
    summary.Flush();
    observer.OnProgress(summary.Count(), points);
    pool.Wait(0.001);
  }
  return summary.Close();
}

// Other ranks: ask for the next chunk before the local queue runs dry, without waiting for
// the answer, and send the finished rows back as they come.
void Worker(SweepObserver& observer, WorkerPool& pool) {
  bool closed = false, stopping = false, asked = false;
  const auto receive_work = [&](const MPI_Status& status) {
    int count = 0;
    MPI_Get_count(&status, MPI_LONG, &count);
    std::vector<long> indices(static_cast<std::size_t>(count));
    MPI_Recv(indices.data(), count, MPI_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    asked = false;
    if (stopping) return;  // the pool is stopped: points handed since are simply not run
    if (indices.empty()) {
      pool.Close();
      closed = true;
    } else {
      pool.Push(indices);
    }
  };
  while (!pool.Finished()) {
    const std::vector<WorkerPool::Row> rows = pool.Take();
    if (!rows.empty()) {
      const std::string text = Encode(rows);
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
    }
    // a stop here ends this rank's threads at once; rank 0 hears of it with the next request
    if (!stopping && observer.StopRequested()) {
      pool.Stop();
      stopping = true;
    }
    if (asked) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(0, kWork, MPI_COMM_WORLD, &arrived, &status);
      if (arrived) receive_work(status);
    }
    if (!closed && !asked && (stopping || pool.Queued() < LowWater(pool.jobs()))) {
      int wants[2] = {stopping ? 0 : 1, pool.jobs()};
      MPI_Send(wants, 2, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
      asked = true;
      if (stopping) closed = true;  // its answer is awaited below
    }
    pool.Wait(0.001);
  }
  if (asked) {  // an answer still on its way: take it, so that nothing is left unreceived
    MPI_Status status;
    MPI_Probe(0, kWork, MPI_COMM_WORLD, &status);
    receive_work(status);
  }
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kDone, MPI_COMM_WORLD);
}

}  // namespace

SweepOutcome RunSweepMpi(const SweepPlan& plan, const SweepRunOptions& options) {
  const SweepSpec& spec = plan.spec;
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (initialised == 0 || finalised != 0) {
    throw std::logic_error("RunSweepMpi: MPI is not initialised (call MPI_Init_thread first)");
  }
  SweepObserver silent;
  SweepObserver& observer = options.observer != nullptr ? *options.observer : silent;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  try {
    const auto base = std::make_unique<SweepBase>(plan.points->Copy());
    const int jobs = WorkerThreads(options.jobs);
    WorkerPool pool(spec, *base, options.output, jobs, LowWater(jobs));
    if (rank == 0) return Root(spec, options, ranks, observer, pool);
    Worker(observer, pool);
    return {};
  } catch (const std::exception& e) {
    // the other ranks would wait for this one forever: end them all
    MPI_Abort(MPI_COMM_WORLD, observer.OnRankError(rank, e));
    throw;
  }
}

RankShare WorldShare() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (initialised == 0 || finalised != 0) return {};
  RankShare share;
  MPI_Comm_rank(MPI_COMM_WORLD, &share.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &share.ranks);
  return share;
}

long MinOverRanks(long value) {
  if (WorldShare().ranks == 1) return value;
  long least = value;
  MPI_Allreduce(&value, &least, 1, MPI_LONG, MPI_MIN, MPI_COMM_WORLD);
  return least;
}

#else  // built without MPI

RankShare WorldShare() { return {}; }

long MinOverRanks(long value) { return value; }

SweepOutcome RunSweepMpi(const SweepPlan&, const SweepRunOptions&) {
  throw std::logic_error("RunSweepMpi: musclesim was built without MPI (-DMUSCLESIM_WITH_MPI=ON)");
}

#endif

}  // namespace musclesim
