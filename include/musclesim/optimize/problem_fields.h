// An optimal control problem file's keys described once (core/part_fields.h,
// docs/guide/optimize.md): the file's own (intervals, base; its lists and blocks), each entry
// of its lists (a control, a final value, a path bound, a tracking or terminal term, a free
// parameter) and its blocks (final_time, optimizer, output). The reader, its messages and the
// guide's table derive from these. The rules between keys stay the reader's: bounds lower <=
// upper, a final value's value or bounds, a tracking reference's points or csv, the outputs
// apart from the inputs, and each entry against the base scenario (CheckProblem).
#pragma once

#include <string>
#include <vector>

#include "musclesim/core/enum_names.h"
#include "musclesim/core/part_fields.h"
#include "musclesim/optimize/problem_file.h"

namespace musclesim {

inline constexpr EnumName<ShootingDerivatives> kShootingDerivativesNames[] = {
    {ShootingDerivatives::kSensitivities, "sensitivities"},
    {ShootingDerivatives::kDifferenceQuotients, "difference_quotients"},
};

// `problem`: the file's intervals and base; its lists and blocks are read by the entries'
// and blocks' descriptions below.
const std::vector<PartVariant<ProblemFile>>& ProblemKeys();

// The entries of its lists, each a variant named by its list ("controls[k]").
const std::vector<PartVariant<ControlSpec>>& ControlEntry();
const std::vector<PartVariant<FinalValue>>& FinalValueEntry();
const std::vector<PartVariant<PathBound>>& PathBoundEntry();
const std::vector<PartVariant<TrackingTerm>>& TrackingEntry();
const std::vector<PartVariant<TerminalTerm>>& TerminalEntry();
const std::vector<PartVariant<FreeParameter>>& ParameterEntry();

// Its blocks, each a variant whose type is its key.
const std::vector<PartVariant<FreeFinalTime>>& FinalTimeBlock();
const std::vector<PartVariant<OptimizeOptions>>& OptimizerBlock();
const std::vector<PartVariant<OptimizeOutputs>>& ProblemOutputBlock();

// The reference table of all of them, as docs/guide/optimize.md holds it.
std::string ProblemReference();

}  // namespace musclesim
