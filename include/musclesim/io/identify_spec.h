// The data file of `musclesim identify` (README "Identification"): which measured curves
// to fit, read and validated into a plain struct.
#pragma once

#include <optional>
#include <string>

namespace musclesim {

// What `musclesim identify` reads (README "Identification"): any subset of the curves.
struct IdentifySpec {
  std::string source;
  std::optional<std::string> passive_csv;   // columns length,tension
  std::optional<std::string> active_csv;    // columns length,tension
  int active_count = 3;
  bool active_nonnegative = false;
  std::optional<std::string> velocity_csv;  // columns shortening_velocity,tension
  std::optional<double> velocity_f_iso;     // held fixed when given [N]
};

// Reads a data file; CSV paths are relative to it. Throws InputError with file:line:column.
IdentifySpec LoadIdentifySpec(const std::string& path);

}  // namespace musclesim
