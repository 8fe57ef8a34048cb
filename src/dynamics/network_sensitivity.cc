// Forward sensitivities' partials on a line (docs/model.md section 10): an element's length
// and tension along a state direction, a node's velocity along it, and where a change of an
// element's tension enters the right-hand side (network_sensitivity.h; in 2 or 3 dimensions
// space_sensitivity.cc).
#include "dynamics/network_sensitivity.h"

#include "dynamics/element_tension.h"
#include "dynamics/network_evaluation.h"
#include "dynamics/network_junction.h"

namespace musclesim::network {

ElementPartials Along(const NetworkModel& m, int e, double t, const double* y, const double* s) {
  if (m.space.dimensions > 1) return SpaceAlong(m, e, t, y, s);
  const Link& link = m.links[e];
  const End& a = m.ends[link.from];
  const End& b = m.ends[link.to];
  // only free nodes' positions and velocities are states; the others do not move with y
  const auto along = [&](int state) { return state >= 0 ? s[state] : 0.0; };
  const double dl = along(b.state) - along(a.state);
  const double dldot =
      NodeVelocityAlong(m, link.to, t, y, s) - NodeVelocityAlong(m, link.from, t, y, s);
  const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
  const double ldot = VelocityOf(m, b, t, y) - VelocityOf(m, a, t, y);
  const Tension tension = TensionOf(m, e, t, l, ldot, y);
  const double du = link.activation >= 0 ? s[link.activation] : 0.0;
  ElementPartials out;
  out.length = dl;
  out.total = tension.by_length * dl + tension.by_rate * dldot + tension.by_activation * du;
  if (m.elements[e].kind == ElementKind::kActuator) {
    // the passive part's own derivatives (fiber damping moves it with the rate, v = -ldot)
    const TensionSample passive = m.elements[e].model->Passive(l, -ldot);
    out.passive = passive.d_length * dl - passive.d_velocity * dldot;
    out.active = out.total - out.passive;
  }
  return out;
}

double NodeVelocityAlong(const NetworkModel& m, int node, double t, const double* y,
                         const double* s) {
  const End& end = m.ends[node];
  if (end.junction >= 0) return JunctionVelocityAlong(m, end.junction, t, y, s);
  return end.rate >= 0 ? s[end.rate] : 0.0;
}

void AddTension(const NetworkModel& m, int e, double t, const double* y, double tension,
                double* ydot) {
  if (m.space.dimensions > 1) return AddSpaceTension(m, e, t, y, tension, ydot);
  const Link& link = m.links[e];
  const End& a = m.ends[link.from];
  const End& b = m.ends[link.to];
  // as RightHandSide: +T pulls `from`, -T pulls `to`, each over its node's mass
  if (a.rate >= 0) ydot[a.rate] += tension * m.free_nodes[a.free].inverse_mass;
  if (b.rate >= 0) ydot[b.rate] -= tension * m.free_nodes[b.free].inverse_mass;
}

}  // namespace musclesim::network
