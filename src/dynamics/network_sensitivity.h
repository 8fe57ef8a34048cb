// Private: forward sensitivities' partials (docs/model.md section 10) over a network's model:
// NetworkSystem's methods of the same names (network.h) say what each computes. On a line in
// network_sensitivity.cc, in 2 or 3 dimensions in space_sensitivity.cc.
#pragma once

#include "musclesim/dynamics/network_model.h"

namespace musclesim::network {

ElementPartials Along(const NetworkModel& m, int e, double t, const double* y, const double* s);
double NodeVelocityAlong(const NetworkModel& m, int node, double t, const double* y,
                         const double* s);
void AddTension(const NetworkModel& m, int e, double t, const double* y, double tension,
                double* ydot);

// The same in 2 or 3 dimensions.
ElementPartials SpaceAlong(const NetworkModel& m, int e, double t, const double* y,
                           const double* s);
void AddSpaceTension(const NetworkModel& m, int e, double t, const double* y, double tension,
                     double* ydot);

}  // namespace musclesim::network
