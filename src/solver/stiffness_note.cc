#include "stiffness_note.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

// The Jacobian entry at (row, column), 0 where the pattern has none.
double Entry(const JacobianPattern& pattern, const std::vector<double>& values, int row,
             int column) {
  for (int k = pattern.column_starts[column]; k < pattern.column_starts[column + 1]; ++k) {
    if (pattern.rows[k] == row) return values[static_cast<std::size_t>(k)];
  }
  return 0.0;
}

}  // namespace

std::string StiffnessNote(const NetworkSystem& system, double t, const double* y, double step) {
  const JacobianPattern& pattern = system.jacobian_pattern();
  std::vector<double> values(static_cast<std::size_t>(pattern.entries()));
  system.Jacobian(t, y, values.data());
  // a node's rate: its acceleration's derivative in its own velocity (a damping over the
  // mass), or the square root of that in its position (a stiffness over the mass)
  int fastest = -1;
  double rate = 0.0;
  for (std::size_t i = 0; i < system.nodes().size(); ++i) {
    const int x = system.StateIndex(static_cast<int>(i));
    // its first velocity and its acceleration's row (a massless junction has neither)
    const int v = system.VelocityStateIndex(static_cast<int>(i));
    if (x < 0 || v < 0) continue;
    const double by_velocity = std::abs(Entry(pattern, values, v, v));
    const double by_position = std::sqrt(std::abs(Entry(pattern, values, v, x)));
    const double node_rate = std::max(by_velocity, by_position);
    if (std::isfinite(node_rate) && node_rate > rate)
      fastest = static_cast<int>(i), rate = node_rate;
  }
  if (fastest < 0) return "";
  // a time scale far above the step the integrator was cut to: stiffness does not explain it
  constexpr double kExplainingRatio = 1e3;
  if (!(1.0 / rate < kExplainingRatio * std::abs(step))) {
    return "; no rate of the system explains steps this short (the fastest: node " +
           system.nodes()[static_cast<std::size_t>(fastest)].name + ", a time scale of " +
           FormatNumber(1.0 / rate) + " s, against CVODE's last step of " + FormatNumber(step) +
           " s): a kink in a law's slope near this state (a slack length, where a passive or "
           "tendon stiffness starts) or a discontinuity the integrator cannot step over";
  }
  // the element attached to it whose tension changes most with its velocity
  const Node& node = system.nodes()[static_cast<std::size_t>(fastest)];
  const int v = system.VelocityStateIndex(fastest);
  std::vector<double> moved(y, y + pattern.size);
  const double dv = 1e-7 * std::max(std::abs(y[v]), 1e-9);
  moved[static_cast<std::size_t>(v)] += dv;
  int steepest = -1;
  double slope = 0.0;
  ElementSample before, after;
  for (std::size_t e = 0; e < system.elements().size(); ++e) {
    const Element& element = system.elements()[e];
    if (element.from != node.name && element.to != node.name) continue;
    system.ObserveElement(static_cast<int>(e), t, y, before);
    system.ObserveElement(static_cast<int>(e), t, moved.data(), after);
    const double d = std::abs((after.tension - before.tension) / dv);
    if (std::isfinite(d) && d >= slope) steepest = static_cast<int>(e), slope = d;
  }
  std::string note = "; the stiffest part at t = " + FormatNumber(t) + " s: node " + node.name +
                     ", rate " + FormatNumber(rate) + " 1/s (a time scale of " +
                     FormatNumber(1.0 / rate) + " s against CVODE's last step of " +
                     FormatNumber(step) + " s)";
  if (steepest < 0 || slope == 0.0) return note;
  const Element& element = system.elements()[static_cast<std::size_t>(steepest)];
  system.ObserveElement(steepest, t, y, before);
  note += ", from " + element.name + ", whose tension changes by " + FormatNumber(slope) +
          " N per m/s at a lengthening rate of " + FormatNumber(before.lengthening_rate) + " m/s";
  if (element.kind == ElementKind::kActuator) {
    note +=
        " (its tension-velocity curve this steep: a velocity.epsilon small for its n makes "
        "it nearly a step at v = 0; a larger epsilon or mass smooths it)";
  }
  return note;
}

}  // namespace musclesim
