// Feedback control of a network (docs/model.md section 11): the controllers' commands, their
// integral states, their terms in the Jacobian and their place in the pattern.
#include "dynamics/network_control.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "dynamics/element_tension.h"
#include "dynamics/network_build.h"
#include "dynamics/network_evaluation.h"
#include "musclesim/core/errors.h"
#include "part_paths.h"

namespace musclesim::network {

namespace {

// Column positions in Loop::columns.
constexpr int kFromPosition = 0, kFromVelocity = 1, kToPosition = 2, kToVelocity = 3;
constexpr int kMeasuredActivation = 4, kIntegral = 5;

void RequireEveryControlledDriven(const std::vector<Element>& elements,
                                  const std::vector<int>& driver) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (elements[e].controlled && driver[e] < 0) {
      throw ParameterError(Entry("elements", e, "name"), elements[e].name,
                           "is a controlled actuator that no controller drives: give it a "
                           "controller or an activation of its own");
    }
  }
}

}  // namespace

void ResolveControllers(NetworkModel& m, int& states) {
  std::vector<int> driver(m.elements.size(), -1);
  for (std::size_t k = 0; k < m.controllers.size(); ++k) {
    Loop loop = MeasuredLoop(m, k);
    AttachDriven(m, k, loop, driver);
    if (m.controllers[k].gains.ki != 0.0) {
      loop.integral = states++;
      ++m.integral_count;
    }
    m.loops.push_back(loop);
  }
  RequireEveryControlledDriven(m.elements, driver);
  for (std::size_t k = 0; k < m.loops.size(); ++k) {
    RequireNoAlgebraicLoop(m, k, driver);
    PlaceLoopColumns(m, k);
  }
}

Loop MeasuredLoop(const NetworkModel& m, std::size_t k) {
  const Controller& c = m.controllers[k];
  Loop loop;
  std::fill(std::begin(loop.columns), std::end(loop.columns), -1);
  if (!c.measure.element.empty()) {
    loop.element = FindElement(m, c.measure.element);
    if (loop.element < 0) {
      throw ParameterError(Entry("controllers", k, "measure.element"), c.measure.element,
                           "names no element; the elements are: " + KnownNames(m.elements));
    }
  } else {
    loop.node = FindNode(m, c.measure.node);
    if (loop.node < 0) {
      throw ParameterError(Entry("controllers", k, "measure.node"), c.measure.node,
                           "names no node; the nodes are: " + KnownNames(m.nodes));
    }
    if (m.nodes[loop.node].kind != NodeKind::kFree) {
      throw ParameterError(Entry("controllers", k, "measure.node"), c.measure.node,
                           "must name a free node (one with a mass): it is " +
                               std::string(ToString(m.nodes[loop.node].kind)));
    }
    RequireCoordinate(m, k);
  }
  return loop;
}

void RequireCoordinate(const NetworkModel& m, std::size_t k) {
  const int c = m.controllers[k].measure.coordinate, d = m.space.dimensions;
  const std::string path = Entry("controllers", k, "measure.coordinate");
  if (c == Measurement::kNoCoordinate) {
    if (d == 1) return;  // on a line the position is x
    throw ParameterError(path, "none",
                         "is required in " + std::to_string(d) +
                             " dimensions: the coordinate of the node's position measured (" +
                             (d == 2 ? "x or y" : "x, y or z") + ")");
  }
  if (c >= d) {
    throw ParameterError(path, std::string(CoordinateName(c)),
                         std::string("is beyond the network's coordinates: ") +
                             (d == 1 ? "x, on a line" : "x and y, in the plane"));
  }
}

int DrivableActuator(const NetworkModel& m, std::size_t k, const char* key, const std::string& name,
                     const std::vector<int>& driver) {
  const int e = FindElement(m, name);
  if (e < 0) {
    throw ParameterError(Entry("controllers", k, key), name,
                         "names no element; the elements are: " + KnownNames(m.elements));
  }
  if (m.elements[e].kind != ElementKind::kActuator) {
    throw ParameterError(
        Entry("controllers", k, key), name,
        "must name an actuator; it is a " + std::string(ToString(m.elements[e].kind)));
  }
  if (!m.elements[e].controlled) {
    throw ParameterError(Entry("controllers", k, key), name,
                         "drives an actuator that has an activation of its own: a "
                         "controlled actuator has none (no `activation:` or `excitation:`)");
  }
  if (driver[e] >= 0) {
    throw ParameterError(Entry("controllers", k, key), name,
                         "is driven by controllers[" + std::to_string(driver[e]) +
                             "] already: an actuator takes one controller");
  }
  return e;
}

void AttachDriven(NetworkModel& m, std::size_t k, Loop& loop, std::vector<int>& driver) {
  const Controller& c = m.controllers[k];
  const bool pair = c.co_contraction.has_value();
  const std::string names[2] = {pair ? c.co_contraction->first : c.drives,
                                pair ? c.co_contraction->second : std::string()};
  const char* key = pair ? "co_contraction.actuators" : "drives";
  for (int i = 0; i < (pair ? 2 : 1); ++i) {
    const int e = DrivableActuator(m, k, key, names[i], driver);
    driver[e] = static_cast<int>(k);
    m.links[e].loop = static_cast<int>(k);
    m.links[e].side = i == 0 ? 1 : -1;
    loop.driven[i] = e;
    m.kinks.push_back({Kink::kCommand, e, 0.0});
    m.kinks.push_back({Kink::kCommand, e, 1.0});
  }
}

void RequireNoAlgebraicLoop(const NetworkModel& m, std::size_t k, const std::vector<int>& driver) {
  const int measured = m.loops[k].element;
  if (measured >= 0 && m.controllers[k].measure.quantity == MeasuredQuantity::kTension &&
      m.elements[measured].controlled && !m.elements[measured].excitation) {
    // its tension depends on a controller's output, computed from the state now: an
    // algebraic loop when it is this controller's, a chain of them otherwise
    throw ParameterError(
        Entry("controllers", k, "measure.element"), m.elements[measured].name,
        (driver[measured] == static_cast<int>(k)
             ? std::string("is the actuator this controller drives")
             : "is driven by controllers[" + std::to_string(driver[measured]) + "]") +
            ", without activation dynamics: its tension would be an algebraic function of "
            "a controller's output; give it activation_dynamics (docs/model.md 11)");
  }
}

void PlaceLoopColumns(NetworkModel& m, std::size_t k) {
  if (m.space.dimensions > 1) return PlaceSpaceLoopColumns(m, k);
  Loop& loop = m.loops[k];
  const int measured = loop.element;
  const auto place = [&](int node, int column) {
    const int state = m.ends[node].state;
    if (state < 0) return;
    loop.columns[column] = state;
    loop.columns[column + 1] = state + 1;
  };
  if (measured >= 0) {
    place(m.links[measured].from, kFromPosition);
    place(m.links[measured].to, kToPosition);
    if (m.controllers[k].measure.quantity == MeasuredQuantity::kTension) {
      loop.columns[kMeasuredActivation] = m.links[measured].activation;
    }
  } else {
    place(loop.node, kToPosition);
  }
  loop.columns[kIntegral] = loop.integral;
}

void AddControlPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  if (m.space.dimensions > 1) return AddSpaceControlPattern(m, pairs);
  for (const Loop& loop : m.loops) {
    const auto add_row = [&](int row) {
      if (row < 0) return;
      for (int column : loop.columns) {
        if (column >= 0) pairs.emplace_back(column, row);
      }
    };
    for (int e : loop.driven) {
      if (e < 0) continue;
      const Link& link = m.links[e];
      if (link.activation >= 0) {
        add_row(link.activation);
        continue;
      }
      for (int end : {link.from, link.to}) {
        if (m.ends[end].state >= 0) add_row(m.ends[end].state + 1);
      }
    }
    add_row(loop.integral);
  }
}

void FindControlSlots(NetworkModel& m, const std::vector<std::pair<int, int>>& pairs) {
  if (m.space.dimensions > 1) return FindSpaceControlSlots(m, pairs);
  const auto slot = [&](int row, int column) {
    if (row < 0 || column < 0) return -1;
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(column, row));
    return static_cast<int>(it - pairs.begin());
  };
  for (Loop& loop : m.loops) {
    for (int i = 0; i < 2; ++i) {
      const int e = loop.driven[i];
      int rows[2] = {-1, -1};
      if (e >= 0) {
        const Link& link = m.links[e];
        if (link.activation >= 0) {
          rows[0] = link.activation;
        } else {
          const int from = m.ends[link.from].state, to = m.ends[link.to].state;
          rows[0] = from >= 0 ? from + 1 : -1;
          rows[1] = to >= 0 ? to + 1 : -1;
        }
      }
      for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < kLoopColumns; ++c) {
          loop.slot_driven[i][r][c] = slot(rows[r], loop.columns[c]);
        }
      }
    }
    for (int c = 0; c < kLoopColumns; ++c) {
      loop.slot_integral[c] = slot(loop.integral, loop.columns[c]);
    }
  }
}

Command CommandOf(const NetworkModel& m, int k, double t, const double* y) {
  const Controller& c = m.controllers[k];
  const Loop& loop = m.loops[k];
  Command out{};
  // dy/dstate and d(ydot)/dstate along the columns, y the measured quantity
  double measured_by[kLoopColumns] = {};
  double rate_by[kLoopColumns] = {};
  double rate = 0.0;  // ydot
  if (m.space.dimensions > 1) {
    // its derivatives are SpaceControlJacobian's: measured_by and rate_by stay 0 here
    out.measured = MeasureInSpace(m, k, t, y, rate);
  } else if (loop.node >= 0) {
    const int s = m.ends[loop.node].state;
    out.measured = y[s];
    rate = y[s + 1];
    measured_by[kToPosition] = 1.0;
    rate_by[kToVelocity] = 1.0;
  } else {
    const Link& link = m.links[loop.element];
    const End& a = m.ends[link.from];
    const End& b = m.ends[link.to];
    const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
    const double ldot = VelocityOf(m, b, t, y) - VelocityOf(m, a, t, y);
    if (c.measure.quantity == MeasuredQuantity::kLength) {
      out.measured = l;
      rate = ldot;
      measured_by[kFromPosition] = -1.0;
      measured_by[kToPosition] = 1.0;
      rate_by[kFromVelocity] = -1.0;
      rate_by[kToVelocity] = 1.0;
    } else {
      const Tension tension = TensionOf(m, loop.element, t, l, ldot, y);
      out.measured = tension.value;
      measured_by[kFromPosition] = -tension.by_length;
      measured_by[kToPosition] = tension.by_length;
      measured_by[kFromVelocity] = -tension.by_rate;
      measured_by[kToVelocity] = tension.by_rate;
      measured_by[kMeasuredActivation] = tension.by_activation;
    }
  }
  out.reference = c.reference.Evaluate(t);
  out.error = out.reference - out.measured;
  const PidGains& g = c.gains;
  out.value = c.feedforward.Evaluate(t) + g.kp * out.error;
  if (g.kd != 0.0) out.value += g.kd * (c.reference.Slope(t) - rate);  // d(err)/dt
  if (loop.integral >= 0) out.value += g.ki * y[loop.integral];
  for (int i = 0; i < kLoopColumns; ++i) {
    out.error_by_state[i] = -measured_by[i];
    out.by_state[i] = -g.kp * measured_by[i] - g.kd * rate_by[i];
  }
  out.by_state[kIntegral] = g.ki;
  if (c.co_contraction) {
    // the pair has no authority left once both actuators sit at their bounds
    const double level = c.co_contraction->level.Evaluate(t);
    out.high = std::max(level, 1.0 - level);
    out.low = -out.high;
  } else {
    out.high = 1.0;
    out.low = 0.0;
  }
  return out;
}

double UnclampedOutput(const NetworkModel& m, int e, const Command& command, double t) {
  const Controller& c = m.controllers[m.links[e].loop];
  if (!c.co_contraction) return command.value;
  return c.co_contraction->level.Evaluate(t) + m.links[e].side * command.value;
}

double ControlOutput(const NetworkModel& m, int e, double t, const double* y) {
  return std::clamp(UnclampedOutput(m, e, CommandOf(m, m.links[e].loop, t, y), t), 0.0, 1.0);
}

double ExcitationOf(const NetworkModel& m, int e, double t, const double* y) {
  return m.links[e].loop >= 0 ? ControlOutput(m, e, t, y)
                              : m.elements[e].excitation->signal.Evaluate(t);
}

IntegralFade FadeOf(const Command& command, double ki) {
  // the integral moves c toward `high` when ki err > 0, toward `low` when ki err < 0; within
  // kIntegralFadeBand of that bound it fades out linearly, beyond it stops (no wind-up)
  const double push = ki * command.error;
  IntegralFade fade{1.0, 0.0};
  const double room = push > 0.0   ? command.high - command.value
                      : push < 0.0 ? command.value - command.low
                                   : std::numeric_limits<double>::infinity();
  if (room <= 0.0) {
    fade.weight = 0.0;
  } else if (room < kIntegralFadeBand) {
    fade.weight = room / kIntegralFadeBand;
    fade.by_value = (push > 0.0 ? -1.0 : 1.0) / kIntegralFadeBand;
  }
  return fade;
}

double IntegralRate(const Command& command, double ki, double* by_state) {
  const IntegralFade fade = FadeOf(command, ki);
  for (int i = 0; i < kLoopColumns; ++i) {
    by_state[i] = fade.weight * command.error_by_state[i] +
                  command.error * fade.by_value * command.by_state[i];
  }
  return fade.weight * command.error;
}

void ControlRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot) {
  double unused[kLoopColumns];
  for (std::size_t k = 0; k < m.loops.size(); ++k) {
    const int z = m.loops[k].integral;
    if (z < 0) continue;
    ydot[z] =
        IntegralRate(CommandOf(m, static_cast<int>(k), t, y), m.controllers[k].gains.ki, unused);
  }
}

void ControlJacobian(const NetworkModel& m, double t, const double* y, double* values) {
  const auto add = [&](const int* slots, double factor, const double* by_state) {
    for (int c = 0; c < kLoopColumns; ++c) {
      if (slots[c] >= 0) values[slots[c]] += factor * by_state[c];
    }
  };
  for (std::size_t k = 0; k < m.loops.size(); ++k) {
    const Loop& loop = m.loops[k];
    const Command command = CommandOf(m, static_cast<int>(k), t, y);
    for (int i = 0; i < 2; ++i) {
      const int e = loop.driven[i];
      if (e < 0) continue;
      const double unclamped = UnclampedOutput(m, e, command, t);
      if (unclamped <= 0.0 || unclamped >= 1.0) continue;  // clamped: no feedback
      const Link& link = m.links[e];
      if (link.activation >= 0) {
        // the output is the excitation of udot
        const ExcitationInput& input = *m.elements[e].excitation;
        const double rate_by_excitation =
            EvaluateActivationRate(input.dynamics, unclamped, y[link.activation]).by_excitation;
        add(loop.slot_driven[i][0], rate_by_excitation * link.side, command.by_state);
        continue;
      }
      // the output is the activation: +T on `from`, -T on `to`
      const End& a = m.ends[link.from];
      const End& b = m.ends[link.to];
      const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
      const double ldot = VelocityOf(m, b, t, y) - VelocityOf(m, a, t, y);
      const double by_output = TensionOf(m, e, t, l, ldot, y).by_activation * link.side;
      add(loop.slot_driven[i][0], by_output, command.by_state);
      add(loop.slot_driven[i][1], -by_output, command.by_state);
    }
    if (loop.integral >= 0) {
      double by_state[kLoopColumns];
      IntegralRate(command, m.controllers[k].gains.ki, by_state);
      add(loop.slot_integral, 1.0, by_state);
    }
  }
}

void ObserveControllers(const NetworkModel& m, double t, const double* y, NetworkSample& sample) {
  sample.controllers.resize(m.controllers.size());
  for (std::size_t k = 0; k < m.controllers.size(); ++k) {
    const Command command = CommandOf(m, static_cast<int>(k), t, y);
    ControllerSample& out = sample.controllers[k];
    out.reference = command.reference;
    out.measured = command.measured;
    out.error = command.error;
    out.output =
        m.controllers[k].co_contraction ? command.value : std::clamp(command.value, 0.0, 1.0);
  }
}

void HoldActivation(NetworkModel& m, int e, double value) {
  const std::string path = "elements[" + std::to_string(e) + "]";
  if (e < 0 || e >= static_cast<int>(m.elements.size())) {
    throw ParameterError("element", std::to_string(e), "names no element of this network");
  }
  Element& element = m.elements[e];
  if (element.kind != ElementKind::kActuator || element.controlled) {
    throw ParameterError(path, element.name,
                         "must be an actuator no controller drives: only such an actuator's "
                         "activation can be set from outside");
  }
  Require(std::isfinite(value) && value >= 0.0 && value <= 1.0, path + ".activation", value,
          "must be finite and in [0, 1]");
  if (element.excitation) {
    element.excitation->signal = Waveform::Constant(value);
  } else {
    element.activation = Waveform::Constant(value);
  }
}

}  // namespace musclesim::network
