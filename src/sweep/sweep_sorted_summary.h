// Private: the summary CSV made from PATH.partial, whose rows are in the order they
// finished, sorted by index. Rows up to a memory budget are sorted in memory (any sweep of
// up to a million points or so); beyond it the rows are sorted in runs written beside the
// output and merged, so that a sweep of any size needs bounded memory at the end too.
#pragma once

#include <cstddef>
#include <string>

namespace musclesim {

// The memory the rows may take while sorted in one piece [bytes].
inline constexpr std::size_t kSortBudgetBytes = std::size_t{256} << 20;

// Writes `header` and then the lines of `partial` after its first `skip` lines, sorted by
// their leading index, to `path`: atomically (a temporary file renamed over it), or in place
// for "-" (standard output) and devices. Each index must appear once. Throws
// std::runtime_error naming the file on an I/O error; temporary files are removed.
void WriteSortedSummary(const std::string& partial, int skip, const std::string& header,
                        const std::string& path, std::size_t budget_bytes = kSortBudgetBytes);

}  // namespace musclesim
