// The data file of `musclesim identify` (docs/guide/identification.md): which measured curves
// to fit, read and validated into a plain struct.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

// What `musclesim identify` reads (docs/guide/identification.md): any subset of the curves.
struct IdentifySpec {
  std::string source;                       // the data file's path, for messages [-]
  std::optional<std::string> passive_csv;   // path; columns length [m], tension [N]
  std::optional<std::string> active_csv;    // path; columns length [m], tension [N]
  int active_count = 3;                     // Gaussians to fit [-], 1 to 12
  bool active_nonnegative = false;          // keep every amplitude >= 0 [-]
  std::optional<std::string> velocity_csv;  // path; columns shortening_velocity [m/s], tension [N]
  std::optional<double> velocity_f_iso;     // held fixed when given [N], > 0 and <= 1e9
  // where each csv is named (data.yaml:1:11), so that errors in its data point back [-]
  InputPlace passive_csv_at, active_csv_at, velocity_csv_at;
};

// The data file's blocks passive, active and velocity, each described once (core/part_fields.h):
// a block's `type` is its key, its fields' keys are within it. LoadIdentifySpec and
// `musclesim reference identify` derive from them.
const std::vector<PartVariant<IdentifySpec>>& IdentifyDataBlocks();

// Reads a data file; CSV paths are relative to it. Throws InputError with file:line:column.
IdentifySpec LoadIdentifySpec(const std::string& path);

}  // namespace musclesim
