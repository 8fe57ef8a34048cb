// What forward sensitivities (docs/model.md 10) need of a network in the plane or in space
// (section 12): an element's length, rate and tension differentiated along a state direction,
// and a change of its tension carried into its path's free points as forces -T G_j.
#include <array>
#include <span>

#include "dynamics/element_tension.h"
#include "dynamics/network_space.h"

namespace musclesim {

NetworkSystem::ElementPartials NetworkSystem::SpaceAlong(int e, double t, const double* y,
                                                         const double* s) const {
  const int d = space_.dimensions;
  PathState path;
  MeasureLink(e, t, y, path);
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
  const Link& link = links_[e];
  const Tension tension = TensionOf(e, t, g.length, path.length_rate, y);
  const double du = link.activation >= 0 ? s[link.activation] : 0.0;
  ElementPartials out;
  out.length = dl;
  out.total = tension.by_length * dl + tension.by_rate * dldot + tension.by_activation * du;
  if (elements_[e].kind == ElementKind::kActuator) {
    const TensionSample passive = elements_[e].model->Passive(g.length, -path.length_rate);
    out.passive = passive.d_length * dl - passive.d_velocity * dldot;
    out.active = out.total - out.passive;
  }
  return out;
}

void NetworkSystem::AddSpaceTension(int e, double t, const double* y, double tension,
                                    double* ydot) const {
  const int d = space_.dimensions;
  PathState path;
  MeasureLink(e, t, y, path);
  // as SpaceRightHandSide: F_j = -T G_j on every free point, over its node's mass (free node
  // k holds the states 2dk .. 2dk + 2d - 1, its velocities the last d)
  for (std::size_t j = 0; j < path.geometry.points(); ++j) {
    const int state = path.state[j];
    if (state < 0) continue;
    const double inverse_mass = free_nodes_[static_cast<std::size_t>(state / (2 * d))].inverse_mass;
    for (int c = 0; c < d; ++c) {
      ydot[state + d + c] -= tension * path.geometry.gradient[j][c] * inverse_mass;
    }
  }
}

}  // namespace musclesim
