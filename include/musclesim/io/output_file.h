// Writing result files so that a failed run never destroys an earlier result: the text
// goes to a temporary file beside the target, which is renamed over it only when complete.
#pragma once

#include <string>

#include "musclesim/model/number_format.h"  // FormatFull, which the writers of files use

namespace musclesim {

// Writes `content` to `path` atomically; "-" writes to standard output, and an existing
// device or pipe (/dev/null, a FIFO) is written in place, never replaced. Throws
// std::runtime_error naming the path and the system's reason on failure.
void WriteOutput(const std::string& path, const std::string& content);

}  // namespace musclesim
