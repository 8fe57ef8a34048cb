#include "musclesim/core/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "musclesim/core/number_format.h"

namespace musclesim {

double AllocatableBytes() {
  double bytes = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit limit{};
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
      bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
    }
  }
  return bytes;
}

std::string MebibytesText(double bytes) {
  return FormatNumber(std::ceil(bytes / (1024.0 * 1024.0))) + " MiB";
}

}  // namespace musclesim
