// What this process may allocate, for the checks that refuse work too large for the machine
// before it is asked for (a linear solver's matrices, an optimal control program's grid):
// an allocation that fails deep inside a library ends in a signal rather than an error.
#pragma once

#include <string>

namespace musclesim {

// What this process may still allocate [bytes]: the machine's memory less what the process
// holds (its resident set), or under a limit such as ulimit -v (RLIMIT_AS, RLIMIT_DATA) the
// limit less its address space, whichever is less.
double AllocatableBytes();

// `bytes` in MiB for messages, rounded up ("1536 MiB").
std::string MebibytesText(double bytes);

}  // namespace musclesim
