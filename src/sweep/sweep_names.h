// Private to sweep/: the names of a sweep's modes and trajectory policies, as files write
// them (core/enum_names.h): ToString and the sweep file's description read the same table.
#pragma once

#include "musclesim/core/enum_names.h"
#include "musclesim/sweep/sweep.h"

namespace musclesim {

inline constexpr EnumName<SweepMode> kSweepModeNames[] = {
    {SweepMode::kGrid, "grid"},
    {SweepMode::kZip, "zip"},
    {SweepMode::kRandom, "random"},
};

inline constexpr EnumName<TrajectoryPolicy> kTrajectoryPolicyNames[] = {
    {TrajectoryPolicy::kNone, "none"},
    {TrajectoryPolicy::kAll, "all"},
    {TrajectoryPolicy::kFailed, "failed"},
};

}  // namespace musclesim
