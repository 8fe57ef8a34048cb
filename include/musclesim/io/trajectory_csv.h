// Turning a run into text: the trajectory CSV (whole, or streamed row by row as the run
// records them) and the stats JSON. Formatting never happens inside the right-hand side.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "musclesim/io/output_file.h"
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

// The header line of every trajectory CSV of a scenario giving `activation`.
inline constexpr std::string_view kTrajectoryHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,"
    "load,phase";
// The header of one giving `excitation` (activation dynamics, docs/model.md section 8): the
// same with the column `excitation` right after `activation`.
inline constexpr std::string_view kTrajectoryHeaderWithExcitation =
    "t,length,shortening_velocity,activation,excitation,tension_passive,tension_active,"
    "tension_total,load,phase";

// Header and one row per point, numbers with 17 significant digits; `with_excitation` adds
// the excitation column (a scenario with activation dynamics).
std::string FormatTrajectoryCsv(const std::vector<TrajectoryPoint>& trajectory,
                                double phase_tolerance, bool with_excitation = false);

// Appends one CSV row (with its newline) for `point` to `csv`.
void AppendTrajectoryRow(std::string& csv, const TrajectoryPoint& point, double phase_tolerance,
                         bool with_excitation = false);

// Streams a run's CSV into `output` as the simulation records it: the header at once, rows
// in blocks of about 64 KiB, so that memory does not grow with the run's length. Keeps the
// count of rows and the last point. Flush() before committing the output.
class TrajectoryCsvWriter final : public TrajectorySink {
 public:
  TrajectoryCsvWriter(StreamedOutput& output, double phase_tolerance,
                      bool with_excitation = false);
  void Record(const TrajectoryPoint& point) override;
  void Flush();

  long rows() const { return rows_; }
  const TrajectoryPoint& last() const { return last_; }  // valid once rows() > 0

 private:
  StreamedOutput& output_;
  double phase_tolerance_;  // [m/s]
  bool with_excitation_;    // the excitation column
  std::string buffer_;
  long rows_ = 0;
  TrajectoryPoint last_{};
};

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
