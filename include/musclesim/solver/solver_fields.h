// The `solver:` block described once (core/part_fields.h): its tolerances and step guards as
// numbers with their ranges, its method, Jacobian and linear solver as names. The reader, the
// `solver.*` parameter handles, Validate(SolverOptions) and the reference table derive from it.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// One variant, `solver` (CVODES), as the readers and the reference table take a part.
const std::vector<PartVariant<SolverOptions>>& SolverBlock();

}  // namespace musclesim
