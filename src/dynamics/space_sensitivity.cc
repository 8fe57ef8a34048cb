// What forward sensitivities (docs/model.md 10) need of a network in the plane or in space
// (section 12): an element's length, rate and tension differentiated along a state direction,
// and a change of its tension carried into its path's free points as forces -T G_j.
#include "dynamics/network_sensitivity.h"

#include <array>
#include <span>

#include "dynamics/element_tension.h"
#include "dynamics/network_space.h"

namespace musclesim::network {

ElementPartials SpaceAlong(const NetworkModel& m, int e, double t, const double* y,
                           const double* s) {
  const int d = m.space.dimensions;
  PathState path;
  MeasureLink(m, e, t, y, path);
  const PathGeometry& g = path.geometry;
  // ldot = sum_j G_j . qdot_j, so along s = (s_q, s_qdot): dl = sum_j G_j . s_q,
  // dldot = sum_j (G_j . s_qdot + (d ldot/dq_j) . s_q); only free nodes move with y
  const std::array<Point, kMaxPathPoints> rate_gradient =
      RateGradient(g, std::span<const Point>(path.velocity.data(), g.points()));
  double dl = 0.0, dldot = 0.0;
  for (std::size_t j = 0; j < g.points(); ++j) {
    const int state = path.state[j];
    if (state < 0) continue;
    for (int c = 0; c < d; ++c) {
      const double position = s[state + c], velocity = s[state + d + c];
      dl += g.gradient[j][c] * position;
      dldot += g.gradient[j][c] * velocity + rate_gradient[j][c] * position;
    }
  }
  const Link& link = m.links[e];
  const Tension tension = TensionOf(m, e, t, g.length, path.length_rate, y);
  const double du = link.activation >= 0 ? s[link.activation] : 0.0;
  ElementPartials out;
  out.length = dl;
  out.total = tension.by_length * dl + tension.by_rate * dldot + tension.by_activation * du;
  if (m.elements[e].kind == ElementKind::kActuator) {
    const TensionSample passive = m.elements[e].model->Passive(g.length, -path.length_rate);
    out.passive = passive.d_length * dl - passive.d_velocity * dldot;
    out.active = out.total - out.passive;
  }
  return out;
}

void AddSpaceTension(const NetworkModel& m, int e, double t, const double* y, double tension,
                     double* ydot) {
  const int d = m.space.dimensions;
  PathState path;
  MeasureLink(m, e, t, y, path);
  // as SpaceRightHandSide: F_j = -T G_j on every free point, over its node's mass (free node
  // k holds the states 2dk .. 2dk + 2d - 1, its velocities the last d)
  for (std::size_t j = 0; j < path.geometry.points(); ++j) {
    const int state = path.state[j];
    if (state < 0) continue;
    const double inverse_mass =
        m.free_nodes[static_cast<std::size_t>(state / (2 * d))].inverse_mass;
    for (int c = 0; c < d; ++c) {
      ydot[state + d + c] -= tension * path.geometry.gradient[j][c] * inverse_mass;
    }
  }
}

}  // namespace musclesim::network
