#include "sweep/sweep_validation.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <limits>
#include <mutex>
#include <thread>

#include "musclesim/core/errors.h"
#include "sweep/sweep_share.h"

namespace musclesim {

std::optional<InvalidPoint> ValidatePoints(SweepSpec& spec, const SweepBase& base,
                                           const std::vector<long>& indices, int threads) {
  // chunks of consecutive points taken in order, so that the first invalid point is found
  // with only the chunks before it checked
  constexpr std::size_t kChunk = 16;
  const std::size_t count = indices.size();
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_bad{std::numeric_limits<std::size_t>::max()};
  std::mutex mutex;
  std::optional<InvalidPoint> invalid;  // at position first_bad
  std::exception_ptr error;

  // each thread validates on its own copy of the base: yaml-cpp promises nothing about
  // reading one document from several threads
  const auto work = [&](const SweepBase& own) {
    try {
      for (;;) {
        const std::size_t start = next.fetch_add(kChunk);
        if (start >= count || start > first_bad.load()) return;
        for (std::size_t i = start; i < std::min(count, start + kChunk); ++i) {
          const long index = indices[i];
          const long slot = KeptSlot(spec, index);
          try {
            own.Validate(spec, index, spec.metric_options.element, slot >= 0 ? &spec : nullptr,
                         slot);
          } catch (const InputError& e) {
            std::lock_guard<std::mutex> lock(mutex);
            if (i < first_bad.load()) {
              first_bad = i;
              invalid = InvalidPoint{index, e.what()};
            }
            return;  // the later points of this chunk cannot be the first invalid one
          }
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      first_bad = 0;  // stop every thread
    }
  };

  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  const int helpers =
      static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)),
                                             std::max<std::size_t>(1, chunks))) -
      1;
  std::vector<std::thread> pool;
  std::vector<std::unique_ptr<SweepBase>> copies;
  for (int t = 0; t < helpers; ++t) copies.push_back(base.Copy());
  for (int t = 0; t < helpers; ++t)
    pool.emplace_back(work, std::cref(*copies[static_cast<std::size_t>(t)]));
  work(base);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return invalid;
}

}  // namespace musclesim
