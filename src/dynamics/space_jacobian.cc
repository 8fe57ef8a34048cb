// The Jacobian of a network in the plane or in space (docs/model.md 12.4): its sparsity
// pattern, where each element's blocks go, and their values. An element couples every free
// node on its path: d x d blocks of its forces in their positions and velocities, with the
// geometric stiffness T H_jk of the segments' turning directions.
#include "dynamics/network_space.h"

#include <algorithm>
#include <span>

#include "dynamics/element_tension.h"
#include "dynamics/network_control.h"

namespace musclesim::network {

namespace {

// Calls visit(state) for every point of a path that is a free node, in path order.
template <typename Visit>
void ForFreePoints(const std::vector<int>& states, Visit visit) {
  for (const int s : states) {
    if (s >= 0) visit(s);
  }
}

}  // namespace

void PathStates(const NetworkModel& m, const Link& link, std::vector<int>& states) {
  states.clear();
  for (int p = link.path_begin; p < link.path_end; ++p) {
    const int node = m.path_points[static_cast<std::size_t>(p)].node;
    states.push_back(node < 0 ? -1 : m.ends[node].state);
  }
}

void AddSpacePattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  const int d = m.space.dimensions;
  std::vector<int> states;
  for (const Link& link : m.links) {
    PathStates(m, link, states);
    ForFreePoints(states, [&](int row) {
      ForFreePoints(states, [&](int column) {
        for (int r = 0; r < d; ++r) {
          for (int c = 0; c < 2 * d; ++c) pairs.emplace_back(column + c, row + d + r);
        }
      });
      if (link.activation >= 0) {
        for (int r = 0; r < d; ++r) pairs.emplace_back(link.activation, row + d + r);
      }
    });
  }
}

void FindSpaceSlots(NetworkModel& m, const std::function<int(int, int)>& slot) {
  const int d = m.space.dimensions;
  std::vector<int> states;
  for (Link& link : m.links) {
    link.slot_begin = static_cast<int>(m.path_slots.size());
    PathStates(m, link, states);
    // the order SpaceJacobian reads them in: (j, k) blocks row by row, position then velocity
    // column of each entry; then the activation column of each free point's rows
    ForFreePoints(states, [&](int row) {
      ForFreePoints(states, [&](int column) {
        for (int r = 0; r < d; ++r) {
          for (int c = 0; c < d; ++c) {
            m.path_slots.push_back(slot(row + d + r, column + c));
            m.path_slots.push_back(slot(row + d + r, column + d + c));
          }
        }
      });
    });
    if (link.activation >= 0) {
      ForFreePoints(states, [&](int row) {
        for (int r = 0; r < d; ++r) m.path_slots.push_back(slot(row + d + r, link.activation));
      });
    }
  }
}

void SpaceJacobian(const NetworkModel& m, double t, const double* y, double* values) {
  const int d = m.space.dimensions;
  std::fill(values, values + m.pattern.entries(), 0.0);
  for (const FreeNode& f : m.free_nodes) {
    for (int r = 0; r < d; ++r) values[f.slot_rate[r]] = 1.0;
    // a load along n: F = n f(n . p), dF/dp = f' n n^T
    for (const DirectedLoads& directed : f.directed) {
      const double slope = directed.loads.ForceSlope();
      for (int r = 0; r < d; ++r) {
        for (int c = 0; c < d; ++c) {
          values[f.slot_position[3 * r + c]] +=
              slope * directed.direction[r] * directed.direction[c];
        }
      }
    }
  }
  PathState path;
  for (const int e : m.active_links) {
    MeasureLink(m, e, t, y, path);
    const PathGeometry& g = path.geometry;
    const Tension tension = TensionOf(m, e, t, g.length, path.length_rate, y);
    const PathTension law{tension.value, tension.by_length, tension.by_rate};
    const std::array<Point, kMaxPathPoints> rate_gradient =
        RateGradient(g, std::span<const Point>(path.velocity.data(), g.points()));
    const std::span<const Point> rates(rate_gradient.data(), g.points());
    const int* slot = m.path_slots.data() + m.links[e].slot_begin;
    for (std::size_t j = 0; j < g.points(); ++j) {
      if (path.state[j] < 0) continue;
      for (std::size_t k = 0; k < g.points(); ++k) {
        if (path.state[k] < 0) continue;
        const Eigen::Matrix3d by_position = PositionBlock(g, rates, law, j, k);
        const Eigen::Matrix3d by_velocity = VelocityBlock(g, law, j, k);
        for (int r = 0; r < d; ++r) {
          for (int c = 0; c < d; ++c) {
            values[*slot++] += by_position(r, c);
            values[*slot++] += by_velocity(r, c);
          }
        }
      }
    }
    if (m.links[e].activation < 0) continue;
    // F_j = -T G_j: dF_j/du = -(dT/du) G_j
    for (std::size_t j = 0; j < g.points(); ++j) {
      if (path.state[j] < 0) continue;
      for (int r = 0; r < d; ++r) values[*slot++] -= tension.by_activation * g.gradient[j][r];
    }
  }
  for (const Activation& a : m.activations) {
    const ExcitationInput& input = *m.elements[a.element].excitation;
    values[a.slot] +=
        EvaluateActivationRate(input.dynamics, ExcitationOf(m, a.element, t, y), y[a.state])
            .by_activation;
  }
  SpaceControlJacobian(m, t, y, values);
  for (int k = 0; k < m.pattern.entries(); ++k) {
    if (m.row_scale[k] >= 0) values[k] *= m.free_nodes[m.row_scale[k]].inverse_mass;
  }
}

}  // namespace musclesim::network
