// A fitted active length curve's `fit` block described once (core/part_fields.h): its count,
// target, preset name and optimal length, nonnegative flag. The reader, the parameter handles
// of active_length.fit (a change refits the model) and the table in docs/guide/model.md derive
// from it. Its points, widths and centers (lists whose lengths the target and count set) and
// the rules between keys (a target's points, a preset's name and length) are its reader's and
// Validate(FitSpec)'s.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/model/gaussian_fit.h"

namespace musclesim {

// One variant, `fit`.
const std::vector<PartVariant<FitSpec>>& FitBlock();

}  // namespace musclesim
