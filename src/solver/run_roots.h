// The functions of the state a run watches for sign changes: the system's kinks (the
// integrator restarts there), the user's length limits (the run ends), and zero lengths
// (the run fails).
#pragma once

#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// A kink of the system (its KinkValue), or g = length(element) - level.
struct Root {
  enum Kind { kKink, kMinLength, kMaxLength, kZeroLength };
  Kind kind;
  int element;   // kink: its index in system.kinks(); otherwise an element's index
  double level;  // [m]
};

// The roots of a run from state `y` at request.t_start: every kink, the limits, one
// zero-length root per pair of nodes joined. Throws ParameterError for a limit naming no
// element or not bracketing the element's initial length.
std::vector<Root> RootsOf(const NetworkSystem& system, const NetworkRunRequest& request,
                          const double* y);

// The value of `root` at (t, y).
inline double RootValue(const NetworkSystem& system, const Root& root, double t, const double* y) {
  return root.kind == Root::kKink ? system.KinkValue(system.kinks()[root.element], t, y)
                                  : system.Length(root.element, t, y) - root.level;
}

}  // namespace musclesim
