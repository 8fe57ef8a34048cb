// Private: one row of a sweep's summary as text, and the checks a row read back from
// PATH.partial must pass before `--resume` trusts it. Layout: index, one field per axis,
// status, one field per metric, steps, rhs_evals, wall_seconds, message.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_runner.h"

namespace musclesim {

// ok: the run completed; failed: the integrator stopped it; invalid: the point is not a
// valid scenario (found when it ran, in sweeps too large to validate every point up front).
std::optional<RowStatus> ParseRowStatus(std::string_view text);

// RFC 4180 quoting of one field; a newline becomes a space so that a row stays one line.
std::string CsvField(const std::string& text);

// The fields of one CSV line as written (quoted fields keep their quotes), or nullopt when
// its quoting is broken.
std::optional<std::vector<std::string>> SplitCsvFields(const std::string& line);

// A row read back: its index and status, or why it cannot be trusted.
struct CheckedRow {
  long index = -1;                    // the point; -1 when unreadable [-]
  RowStatus status = RowStatus::kOk;  // [-]
  std::string problem;                // empty when the row is well formed [-]
};

// Checks a row against the sweep: the number of fields, an index in [0, points), the axis
// values of that point, a known status, numbers where numbers belong.
CheckedRow CheckRow(const SweepSpec& spec, long points, const std::string& line);

}  // namespace musclesim
