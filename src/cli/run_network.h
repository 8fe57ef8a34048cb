// `musclesim run` on a network scenario (io/network_scenario.h).
#pragma once

#include <string>
#include <vector>

#include "cli/arguments.h"

namespace musclesim::cli {

// Loads args.positional[0] as a network with `overrides`, runs it and writes its CSV as
// `musclesim run` does; returns the exit code.
int RunNetwork(const Arguments& args, const std::vector<std::string>& overrides);

}  // namespace musclesim::cli
