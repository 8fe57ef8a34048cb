// What `musclesim optimize` writes of an optimum: the base scenario with the optimal controls
// as activation tables (a file `musclesim run` re-simulates), the re-simulation's final values
// against the problem's bounds, and the summary as JSON.
#pragma once

#include <string>
#include <vector>

#include "musclesim/io/readers/document.h"
#include "musclesim/optimize/problem_file.h"
#include "musclesim/scenario/run.h"

namespace musclesim {

// The scenario document `base` with each control's activation replaced by its table of the
// optimum's grid values (numbers kept exactly: the file re-runs the same numbers).
Document WithControlTables(Document base, const OptimalControlProblem& problem,
                           const OptimalControlResult& result);

// The base scenario file's text with the optimum's tables (WithControlTables), headed by a
// comment naming the problem.
std::string OptimumScenarioText(const ProblemFile& file, const OptimalControlResult& result);

// One final value of the re-simulation: the column's value at the run's last row, and by how
// much it lies outside the problem's bounds (0 inside).
struct FinalCheck {
  std::string column;
  double value = 0.0;
  double lower = 0.0, upper = 0.0;
  double violation = 0.0;
};
std::vector<FinalCheck> CheckFinalValues(const ProblemFile& file, const RecordedRun& run);

// The summary: IPOPT's status and counters, the objective, the violations of the shooting
// solution and of its re-simulation, the grid and every control's values on it.
std::string OptimumSummaryJson(const ProblemFile& file, const OptimalControlResult& result,
                               const RecordedRun& run, const std::vector<FinalCheck>& finals,
                               double wall_seconds);

}  // namespace musclesim
