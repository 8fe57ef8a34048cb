// A run's counters as the JSON `musclesim run --stats` writes.
#pragma once

#include <string>
#include <vector>

#include "musclesim/solver/simulation.h"

namespace musclesim {

// One parameter of a run with sensitivities, for the stats: its path and how its
// right-hand-side derivative is computed ("analytic" or "difference_quotient").
struct SensitivityNote {
  std::string path;
  std::string derivative;
};

// A JSON object with the counters, wall_seconds, final_time, status and message; with
// sensitivities, also their counters and `sensitivities`, one {path, derivative} each.
std::string FormatStatsJson(const RunStats& stats,
                            const std::vector<SensitivityNote>& sensitivities = {});

}  // namespace musclesim
