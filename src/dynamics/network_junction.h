// Private: massless junctions on a line (docs/model.md 14.4, network_junction.cc).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/dynamics/network_model.h"

namespace musclesim::network {

// Terms of a junction's balance R(w) and dR/dw at (t, y) with its velocity w, and the sum of
// their magnitudes (R's rounding scale).
struct Balance {
  double residual, by_velocity, magnitude;
};
// `elastic`: the loads and the springs' and tendons' terms alone, which w does not change;
// else the other elements' alone.
Balance JunctionBalance(const NetworkModel& m, const Junction& junction, double t, const double* y,
                        double w, bool elastic);
// w of junction k at (t, y), to machine precision by bracketed Newton (NaN if no bracket is
// found: the run then fails and NonFiniteCause names the junction).
double JunctionVelocity(const NetworkModel& m, int k, double t, const double* y);
// Why junction k has no finite velocity at (t, y), for messages: an elastic element's tension
// that overflows, or a balance without a finite root; "" when it has one.
std::string JunctionFailure(const NetworkModel& m, int k, double t, const double* y);
// dw/dy s of junction k at (t, y): -(dR/dy s) / (dR/dw).
double JunctionVelocityAlong(const NetworkModel& m, int k, double t, const double* y,
                             const double* s);
// Every junction's w at (t, y), in `velocities` (nullptr if none).
const double* JunctionVelocities(const NetworkModel& m, double t, const double* y,
                                 std::vector<double>& velocities);
// The build's step for junctions: each checked (on a line, with no controllers, no two
// adjacent, a rate-dependent element at it), its links and columns; the pattern's: their
// entries and slots; the Jacobian's: their rows and the neighbours' terms through w
// (`by_rate`: room for dT/d(ldot) of a junction's elements).
void ResolveJunctions(NetworkModel& m);
void AddJunctionPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
void FindJunctionSlots(NetworkModel& m, const std::function<int(int, int)>& slot);
void JunctionJacobian(const NetworkModel& m, double t, const double* y, const double* w,
                      double* values, std::vector<double>& by_rate);

}  // namespace musclesim::network
