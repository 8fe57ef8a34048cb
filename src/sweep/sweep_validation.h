// Private: validating a sweep's points before it runs, on several threads, keeping each
// validated scenario in its slot of the spec (SweepSpec::kept) when asked.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/sweep/sweep.h"
#include "sweep/sweep_base.h"

namespace musclesim {

struct InvalidPoint {
  long index = 0;
  std::string message;  // the InputError's, as the scenario reader gave it [-]
};

// Validates the points `indices` (ascending) of `spec` with `base` (and copies of it) on up
// to `threads` threads; when spec.kept, moves each scenario into its slot (KeptSlot), which must
// exist. Returns the first invalid point of `indices` (the lowest index), if any: the points after
// it may be left unchecked. Rethrows any other exception.
std::optional<InvalidPoint> ValidatePoints(SweepSpec& spec, const SweepBase& base,
                                           const std::vector<long>& indices, int threads);

}  // namespace musclesim
