// The functions of the state a run watches for sign changes: the system's kinks (the
// integrator restarts there), the user's length limits (the run ends), and zero lengths
// (the run fails).
#pragma once

#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// A kink of the system (its KinkValue), or g = length(element) - level, or in 2 or 3
// dimensions g = length(segment of element) - level (docs/model.md 12.5).
struct Root {
  enum Kind { kKink, kMinLength, kMaxLength, kZeroLength, kShortSegment };
  Kind kind;
  int element;       // kink: its index in system.kinks(); otherwise an element's index
  double level;      // [m]
  int segment = -1;  // kShortSegment: the segment's index along the element's path
};

// The roots of a run from state `y` at request.t_start: every kink, the limits, one
// zero-length root per pair of nodes joined (in 2 or 3 dimensions, one per segment of every
// path, at NetworkSystem::kMinSegmentLength). Throws ParameterError for a limit naming no
// element or not bracketing the element's initial length.
std::vector<Root> RootsOf(const NetworkSystem& system, const NetworkRunRequest& request,
                          const double* y);

// The value of `root` at (t, y).
inline double RootValue(const NetworkSystem& system, const Root& root, double t, const double* y) {
  switch (root.kind) {
    case Root::kKink: return system.KinkValue(system.kinks()[root.element], t, y);
    case Root::kShortSegment:
      return system.SegmentLength(root.element, root.segment, t, y) - root.level;
    default: return system.Length(root.element, t, y) - root.level;
  }
}

}  // namespace musclesim
