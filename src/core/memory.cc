#include "musclesim/core/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

// The process's address space and resident set [bytes], from /proc/self/statm; 0 where it
// cannot be read.
std::pair<double, double> SizeAndResident() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return {0.0, 0.0};
  unsigned long size = 0, resident = 0;
  const bool read = std::fscanf(statm, "%lu %lu", &size, &resident) == 2;
  std::fclose(statm);
  const double page = static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  return read ? std::pair{size * page, resident * page} : std::pair{0.0, 0.0};
}

}  // namespace

double AllocatableBytes() {
  const auto [size, resident] = SizeAndResident();
  double bytes =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE) - resident;
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit limit{};
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
      bytes = std::min(bytes, static_cast<double>(limit.rlim_cur) - size);
    }
  }
  return std::max(bytes, 0.0);
}

std::string MebibytesText(double bytes) {
  return FormatNumber(std::ceil(bytes / (1024.0 * 1024.0))) + " MiB";
}

}  // namespace musclesim
