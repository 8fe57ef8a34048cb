// Feedback control of a network in the plane or in space (docs/model.md 11 and 12): what a
// controller measures there (an element's path length or tension, one coordinate of a free
// node), its columns, and its terms in the Jacobian and the pattern. The law itself, the
// clamps and the integral's fade are network_control.cc's, as on a line.
#include "dynamics/network_control.h"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "dynamics/element_tension.h"
#include "dynamics/network_space.h"

namespace musclesim::network {

namespace {

// The most columns a controller's command depends on: every free point of a path (d
// positions and d velocities each), an activation state and the integral.
constexpr int kMaxSpaceLoopColumns = 2 * 3 * static_cast<int>(kMaxPathPoints) + 2;

}  // namespace

void PlaceSpaceLoopColumns(NetworkModel& m, std::size_t k) {
  Loop& loop = m.loops[k];
  const int d = m.space.dimensions;
  loop.column_begin = static_cast<int>(m.loop_columns.size());
  if (loop.node >= 0) {
    // the node's coordinate, then its rate
    const int s = m.ends[loop.node].state, c = m.controllers[k].measure.coordinate;
    m.loop_columns.push_back(s + c);
    m.loop_columns.push_back(s + d + c);
  } else {
    // every free point of the path: its positions, then its velocities
    std::vector<int> states;
    PathStates(m, m.links[loop.element], states);
    for (const int s : states) {
      if (s < 0) continue;
      for (int c = 0; c < 2 * d; ++c) m.loop_columns.push_back(s + c);
    }
    const int activation = m.links[loop.element].activation;
    if (m.controllers[k].measure.quantity == MeasuredQuantity::kTension && activation >= 0) {
      m.loop_columns.push_back(activation);
    }
  }
  if (loop.integral >= 0) m.loop_columns.push_back(loop.integral);  // the last column
  loop.column_end = static_cast<int>(m.loop_columns.size());
}

void DrivenRows(const NetworkModel& m, int e, std::vector<int>& rows) {
  rows.clear();
  const Link& link = m.links[e];
  if (link.activation >= 0) {
    rows.push_back(link.activation);
    return;
  }
  // T acts on every free point of the path: its d acceleration rows
  const int d = m.space.dimensions;
  std::vector<int> states;
  PathStates(m, link, states);
  for (const int s : states) {
    if (s < 0) continue;
    for (int r = 0; r < d; ++r) rows.push_back(s + d + r);
  }
}

void AddSpaceControlPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  std::vector<int> rows;
  for (const Loop& loop : m.loops) {
    const auto add_row = [&](int row) {
      for (int c = loop.column_begin; c < loop.column_end; ++c) {
        pairs.emplace_back(m.loop_columns[static_cast<std::size_t>(c)], row);
      }
    };
    for (const int e : loop.driven) {
      if (e < 0) continue;
      DrivenRows(m, e, rows);
      for (const int row : rows) add_row(row);
    }
    if (loop.integral >= 0) add_row(loop.integral);
  }
}

void FindSpaceControlSlots(NetworkModel& m, const std::vector<std::pair<int, int>>& pairs) {
  const auto slot = [&](int row, int column) {
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(column, row));
    return static_cast<int>(it - pairs.begin());
  };
  std::vector<int> rows;
  for (Loop& loop : m.loops) {
    // the order SpaceControlJacobian reads them in: each driven actuator's rows, then the
    // integral's, each row along the loop's columns
    loop.slot_begin = static_cast<int>(m.loop_slots.size());
    const auto add_row = [&](int row) {
      for (int c = loop.column_begin; c < loop.column_end; ++c) {
        m.loop_slots.push_back(slot(row, m.loop_columns[static_cast<std::size_t>(c)]));
      }
    };
    for (const int e : loop.driven) {
      if (e < 0) continue;
      DrivenRows(m, e, rows);
      for (const int row : rows) add_row(row);
    }
    if (loop.integral >= 0) add_row(loop.integral);
  }
}

double MeasureInSpace(const NetworkModel& m, int k, double t, const double* y, double& rate,
                      double* measured_by, double* rate_by) {
  const Loop& loop = m.loops[k];
  const int d = m.space.dimensions;
  if (measured_by != nullptr) {
    std::fill(measured_by, measured_by + (loop.column_end - loop.column_begin), 0.0);
    std::fill(rate_by, rate_by + (loop.column_end - loop.column_begin), 0.0);
  }
  if (loop.node >= 0) {
    const int c = m.controllers[k].measure.coordinate;
    rate = NodeCoordinateRate(m, loop.node, c, t, y);
    if (measured_by != nullptr) {
      measured_by[0] = 1.0;
      rate_by[1] = 1.0;
    }
    return NodeCoordinate(m, loop.node, c, t, y);
  }
  PathState path;
  MeasureLink(m, loop.element, t, y, path);
  const PathGeometry& g = path.geometry;
  const bool tension = m.controllers[k].measure.quantity == MeasuredQuantity::kTension;
  Tension law{};
  if (tension) {
    law = TensionOf(m, loop.element, t, g.length, path.length_rate, y);
    rate = 0.0;  // unused: a tension takes no derivative gain
  } else {
    rate = path.length_rate;
  }
  if (measured_by != nullptr) {
    // dl/dq_j = G_j; d ldot/dq_j = RateGradient_j, d ldot/dqdot_j = G_j; T(l, ldot, u)
    const std::array<Point, kMaxPathPoints> rate_gradient =
        RateGradient(g, std::span<const Point>(path.velocity.data(), g.points()));
    int column = 0;
    for (std::size_t j = 0; j < g.points(); ++j) {
      if (path.state[j] < 0) continue;
      for (int r = 0; r < d; ++r) {
        const double along = g.gradient[j][r], rate_along = rate_gradient[j][r];
        if (tension) {
          measured_by[column + r] = law.by_length * along + law.by_rate * rate_along;
          measured_by[column + d + r] = law.by_rate * along;
        } else {
          measured_by[column + r] = along;
          rate_by[column + r] = rate_along;
          rate_by[column + d + r] = along;
        }
      }
      column += 2 * d;
    }
    if (tension && m.links[loop.element].activation >= 0) measured_by[column] = law.by_activation;
  }
  return tension ? law.value : g.length;
}

void SpaceControlJacobian(const NetworkModel& m, double t, const double* y, double* values) {
  std::array<double, kMaxSpaceLoopColumns> measured_by, rate_by, by_state, error_by, integral_by;
  PathState path;
  for (std::size_t k = 0; k < m.loops.size(); ++k) {
    const Loop& loop = m.loops[k];
    const PidGains& gains = m.controllers[k].gains;
    const int columns = loop.column_end - loop.column_begin;
    const Command command = CommandOf(m, static_cast<int>(k), t, y);
    double rate = 0.0;
    MeasureInSpace(m, static_cast<int>(k), t, y, rate, measured_by.data(), rate_by.data());
    // dc/dy and d(err)/dy along the columns; the integral, when there is one, the last
    for (int i = 0; i < columns; ++i) {
      error_by[i] = -measured_by[i];
      by_state[i] = -gains.kp * measured_by[i] - gains.kd * rate_by[i];
    }
    if (loop.integral >= 0) by_state[columns - 1] = gains.ki;
    const int* slot = m.loop_slots.data() + loop.slot_begin;
    const auto add_row = [&](double factor, const double* by) {
      for (int i = 0; i < columns; ++i) values[slot[i]] += factor * by[i];
      slot += columns;
    };
    for (int i = 0; i < 2; ++i) {
      const int e = loop.driven[i];
      if (e < 0) continue;
      const Link& link = m.links[e];
      const double unclamped = UnclampedOutput(m, e, command, t);
      const bool feedback = unclamped > 0.0 && unclamped < 1.0;  // clamped: none
      if (link.activation >= 0) {
        // the output is the excitation of udot
        const ExcitationInput& input = *m.elements[e].excitation;
        const double rate_by_excitation =
            feedback ? EvaluateActivationRate(input.dynamics, unclamped, y[link.activation])
                           .by_excitation
                     : 0.0;
        add_row(rate_by_excitation * link.side, by_state.data());
        continue;
      }
      // the output is the activation: F_j = -T G_j on every free point of the path
      MeasureLink(m, e, t, y, path);
      const PathGeometry& g = path.geometry;
      const double by_output =
          feedback ? TensionOf(m, e, t, g.length, path.length_rate, y).by_activation * link.side
                   : 0.0;
      for (std::size_t j = 0; j < g.points(); ++j) {
        if (path.state[j] < 0) continue;
        for (int r = 0; r < m.space.dimensions; ++r) {
          add_row(-by_output * g.gradient[j][r], by_state.data());
        }
      }
    }
    if (loop.integral >= 0) {
      const IntegralFade fade = FadeOf(command, gains.ki);
      for (int i = 0; i < columns; ++i) {
        integral_by[i] = fade.weight * error_by[i] + command.error * fade.by_value * by_state[i];
      }
      add_row(1.0, integral_by.data());
    }
  }
}

}  // namespace musclesim::network
