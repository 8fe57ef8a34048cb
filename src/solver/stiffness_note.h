// Private: what made the system too stiff for CVODE, for the message of a run that fails with
// a convergence or error-test failure at a tiny step: the node with the fastest rate in the
// Jacobian and the element whose tension makes it.
#pragma once

#include <string>

#include "musclesim/dynamics/network.h"

namespace musclesim {

// "; the stiffest part at t = ...: ..." or "" when no free node has a velocity rate.
// `step` is the last step CVODE tried [s].
std::string StiffnessNote(const NetworkSystem& system, double t, const double* y, double step);

}  // namespace musclesim
