// Turning a finished run into text: the trajectory CSV and the stats JSON. Formatting
// happens here, after integration, never inside the solver loop.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "musclesim/solver/simulation.h"

namespace musclesim {

enum class Phase { kConcentric, kEccentric, kIsometric };
std::string_view ToString(Phase phase);

// docs/model.md section 6: concentric if v > tolerance, eccentric if v < -tolerance.
inline Phase ClassifyPhase(double shortening_velocity, double tolerance) {
  if (shortening_velocity > tolerance) return Phase::kConcentric;
  if (shortening_velocity < -tolerance) return Phase::kEccentric;
  return Phase::kIsometric;
}

// The header line of every trajectory CSV.
inline constexpr std::string_view kTrajectoryHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,"
    "load,phase";

// Header and one row per point, numbers with 17 significant digits.
std::string FormatTrajectoryCsv(const std::vector<TrajectoryPoint>& trajectory,
                                double phase_tolerance);

// A JSON object with the counters, wall_seconds, final_time, status and message.
std::string FormatStatsJson(const RunStats& stats);

}  // namespace musclesim
