// The report of a muscle converted to family degroote2016 (docs/model.md 14.5): the
// converted parameters set, and one line per curve on how far it moved.
#pragma once

#include "musclesim/io/import/muscle_import.h"
#include "musclesim/model/degroote_conversion.h"

namespace musclesim {

// A muscle converted to family degroote2016 (docs/model.md 14.5): its curves' conversion,
// one line per curve into `muscle.conversion` (the tendon's when `compliant`), and the
// De Groote parameters it sets.
void ApplyConversion(const DeGrooteConversion& converted, bool compliant, ImportedMuscle& muscle);

}  // namespace musclesim
