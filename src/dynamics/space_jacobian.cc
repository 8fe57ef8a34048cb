// The Jacobian of a network in the plane or in space (docs/model.md 12.4): its sparsity
// pattern, where each element's blocks go, and their values. An element couples every free
// node on its path: d x d blocks of its forces in their positions and velocities, with the
// geometric stiffness T H_jk of the segments' turning directions.
#include <algorithm>
#include <span>

#include "dynamics/element_tension.h"
#include "dynamics/network_space.h"

namespace musclesim {

namespace {

// Calls visit(state) for every point of a path that is a free node, in path order.
template <typename Visit>
void ForFreePoints(const std::vector<int>& states, Visit visit) {
  for (const int s : states) {
    if (s >= 0) visit(s);
  }
}

}  // namespace

void NetworkSystem::PathStates(const Link& link, std::vector<int>& states) const {
  states.clear();
  for (int p = link.path_begin; p < link.path_end; ++p) {
    const int node = path_points_[static_cast<std::size_t>(p)].node;
    states.push_back(node < 0 ? -1 : ends_[node].state);
  }
}

void NetworkSystem::AddSpacePattern(std::vector<std::pair<int, int>>& pairs) const {
  const int d = space_.dimensions;
  std::vector<int> states;
  for (const Link& link : links_) {
    PathStates(link, states);
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

void NetworkSystem::FindSpaceSlots(const std::function<int(int, int)>& slot) {
  const int d = space_.dimensions;
  std::vector<int> states;
  for (Link& link : links_) {
    link.slot_begin = static_cast<int>(path_slots_.size());
    PathStates(link, states);
    // the order SpaceJacobian reads them in: (j, k) blocks row by row, position then velocity
    // column of each entry; then the activation column of each free point's rows
    ForFreePoints(states, [&](int row) {
      ForFreePoints(states, [&](int column) {
        for (int r = 0; r < d; ++r) {
          for (int c = 0; c < d; ++c) {
            path_slots_.push_back(slot(row + d + r, column + c));
            path_slots_.push_back(slot(row + d + r, column + d + c));
          }
        }
      });
    });
    if (link.activation >= 0) {
      ForFreePoints(states, [&](int row) {
        for (int r = 0; r < d; ++r) path_slots_.push_back(slot(row + d + r, link.activation));
      });
    }
  }
}

void NetworkSystem::SpaceJacobian(double t, const double* y, double* values) const {
  const int d = space_.dimensions;
  std::fill(values, values + pattern_.entries(), 0.0);
  for (const FreeNode& f : free_nodes_) {
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
  for (const int e : active_links_) {
    MeasureLink(e, t, y, path);
    const PathGeometry& g = path.geometry;
    const Tension tension = TensionOf(e, t, g.length, path.length_rate, y);
    const PathTension law{tension.value, tension.by_length, tension.by_rate};
    const std::array<Point, kMaxPathPoints> rate_gradient =
        RateGradient(g, std::span<const Point>(path.velocity.data(), g.points()));
    const std::span<const Point> rates(rate_gradient.data(), g.points());
    const int* slot = path_slots_.data() + links_[e].slot_begin;
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
    if (links_[e].activation < 0) continue;
    // F_j = -T G_j: dF_j/du = -(dT/du) G_j
    for (std::size_t j = 0; j < g.points(); ++j) {
      if (path.state[j] < 0) continue;
      for (int r = 0; r < d; ++r) values[*slot++] -= tension.by_activation * g.gradient[j][r];
    }
  }
  for (const Activation& a : activations_) {
    const ExcitationInput& input = *elements_[a.element].excitation;
    values[a.slot] +=
        EvaluateActivationRate(input.dynamics, ExcitationOf(a.element, t, y), y[a.state])
            .by_activation;
  }
  SpaceControlJacobian(t, y, values);
  for (int k = 0; k < pattern_.entries(); ++k) {
    if (row_scale_[k] >= 0) values[k] *= free_nodes_[row_scale_[k]].inverse_mass;
  }
}

}  // namespace musclesim
