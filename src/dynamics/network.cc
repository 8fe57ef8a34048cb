// A network evaluated: its initial state, right-hand side, Jacobian, kinks, inputs' breaks
// and observations on a line (network_evaluation.h; the plane and space in network_space.cc,
// space_jacobian.cc).
#include "dynamics/network_evaluation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "dynamics/element_tension.h"
#include "dynamics/network_control.h"
#include "dynamics/network_junction.h"
#include "dynamics/network_space.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "dynamics/network_skeleton.h"

namespace musclesim::network {

void InitialState(const NetworkModel& m, double t_start, double* y) {
  const int d = m.space.dimensions;
  for (const FreeNode& f : m.free_nodes) {
    const int s = m.ends[f.node].state;
    const Coordinates position = m.nodes[f.node].PositionCoordinates();
    const Coordinates velocity = m.nodes[f.node].VelocityCoordinates();
    for (int c = 0; c < d; ++c) {
      y[s + c] = position[c];
      if (!f.massless) y[s + d + c] = velocity[c];
    }
  }
  for (const Activation& a : m.activations) {
    y[a.state] = m.elements[a.element].excitation->InitialActivation(t_start);
  }
  if (m.skeleton) {
    const int n = m.skeleton->coordinate_count();
    m.skeleton->InitialState(y + m.skeleton_state, y + m.skeleton_state + n);
  }
}

void CheckInitialState(const NetworkModel& m, double t, const double* y) {
  if (m.space.dimensions > 1) CheckInitialPaths(m, t, y);
  for (std::size_t e = 0; e < m.elements.size() && m.space.dimensions == 1; ++e) {
    const double l = Length(m, static_cast<int>(e), t, y);
    if (!(l > 0.0)) {
      const Element& element = m.elements[e];
      throw ParameterError("elements[" + std::to_string(e) + "]", element.name,
                           "must be longer than 0 at the start: its length x(" + element.to +
                               ") - x(" + element.from + ") is " + FormatNumber(l) + " m");
    }
  }
  for (std::size_t k = 0; k < m.junctions.size(); ++k) {
    const std::string failure = JunctionFailure(m, static_cast<int>(k), t, y);
    if (!failure.empty()) {
      const int node = m.free_nodes[m.junctions[k].free].node;
      throw ParameterError("nodes[" + std::to_string(node) + "]", m.nodes[node].name,
                           "at the start, " + failure);
    }
  }
  ElementSample sample;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    ObserveElement(m, static_cast<int>(e), t, y, sample);
    if (!std::isfinite(sample.tension)) {
      const Element& element = m.elements[e];
      throw ParameterError("elements[" + std::to_string(e) + "]", element.name,
                           "its tension at the start is " + FormatNumber(sample.tension) +
                               " N (length " + FormatNumber(sample.length) +
                               " m): its law overflows there; an exponential's alpha times its "
                               "stretch must stay below about 700");
    }
  }
}

double PositionOf(const NetworkModel& m, const End& end, double t, const double* y) {
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state];
    case NodeKind::kFixed: return end.position;
    case NodeKind::kPrescribed: return m.nodes[end.node].motion.Evaluate(t);
    case NodeKind::kOnBody: break;  // never on a line: bodies need 2 or 3 dimensions
  }
  return 0.0;
}

double VelocityOf(const NetworkModel& m, const End& end, double t, const double* y) {
  switch (end.kind) {
    case NodeKind::kFree:
      return end.junction >= 0 ? JunctionVelocity(m, end.junction, t, y) : y[end.rate];
    case NodeKind::kFixed: return 0.0;
    case NodeKind::kPrescribed: return m.nodes[end.node].motion.Slope(t);
    case NodeKind::kOnBody: break;  // never on a line
  }
  return 0.0;
}

double Length(const NetworkModel& m, int e, double t, const double* y) {
  if (m.space.dimensions > 1) return SegmentLength(m, e, -1, t, y);
  const Link& link = m.links[e];
  return PositionOf(m, m.ends[link.to], t, y) - PositionOf(m, m.ends[link.from], t, y);
}

double LengtheningRate(const NetworkModel& m, int e, double t, const double* y) {
  if (m.space.dimensions > 1) return SpaceLengtheningRate(m, e, t, y);
  const Link& link = m.links[e];
  return VelocityOf(m, m.ends[link.to], t, y) - VelocityOf(m, m.ends[link.from], t, y);
}

double KinkValue(const NetworkModel& m, const Kink& kink, double t, const double* y) {
  switch (kink.kind) {
    case Kink::kLength: return Length(m, kink.element, t, y) - kink.level;
    case Kink::kLengtheningRate: return LengtheningRate(m, kink.element, t, y) - kink.level;
    case Kink::kExcitation:
      return ExcitationOf(m, kink.element, t, y) - y[m.links[kink.element].activation];
    case Kink::kCommand: {
      const int loop = m.links[kink.element].loop;
      return UnclampedOutput(m, kink.element, CommandOf(m, loop, t, y), t) - kink.level;
    }
  }
  return 0.0;
}

void SingleNodeRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot) {
  const FreeNode& f = m.free_nodes.front();
  const int s = m.ends[f.node].state;
  const double x = y[s], v = y[s + 1];
  ydot[s] = v;
  double force = f.loads.Force(t, x);
  for (const Anchored& a : m.anchored) {
    // as RightHandSide: l = x_to - x_from, ldot = v_to - v_from (a fixed end's velocity 0)
    if (a.sign > 0) {
      force -= TensionOf(m, a.element, t, x - a.position, v - 0.0, y).value;
    } else {
      force += TensionOf(m, a.element, t, a.position - x, 0.0 - v, y).value;
    }
  }
  ydot[s + 1] = force * f.inverse_mass;
}

void RightHandSide(const NetworkModel& m, double t, const double* y, double* ydot,
                   NetworkScratch& scratch) {
  if (m.single_node) return SingleNodeRightHandSide(m, t, y, ydot);
  if (m.space.dimensions > 1) return SpaceRightHandSide(m, t, y, ydot);
  const double* w = JunctionVelocities(m, t, y, scratch.junction_velocities);
  for (const FreeNode& f : m.free_nodes) {
    const End& end = m.ends[f.node];
    if (f.massless) {
      ydot[end.state] = w[end.junction];
      continue;
    }
    ydot[end.state] = y[end.rate];
    ydot[end.rate] = f.loads.Force(t, y[end.state]);
  }
  for (const int e : m.active_links) {
    const End& a = m.ends[m.links[e].from];
    const End& b = m.ends[m.links[e].to];
    const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
    const double ldot = RateOf(m, b, t, y, w) - RateOf(m, a, t, y, w);
    const double tension = TensionOf(m, e, t, l, ldot, y).value;
    // +T pulls `from` towards `to`, -T pulls `to` back
    if (a.rate >= 0) ydot[a.rate] += tension;
    if (b.rate >= 0) ydot[b.rate] -= tension;
  }
  for (const FreeNode& f : m.free_nodes) {
    if (!f.massless) ydot[m.ends[f.node].rate] *= f.inverse_mass;
  }
  for (const Activation& a : m.activations) {
    const ExcitationInput& input = *m.elements[a.element].excitation;
    ydot[a.state] =
        EvaluateActivationRate(input.dynamics, ExcitationOf(m, a.element, t, y), y[a.state]).value;
  }
  ControlRightHandSide(m, t, y, ydot);
}

void Jacobian(const NetworkModel& m, double t, const double* y, double* values,
              NetworkScratch& scratch) {
  if (m.skeleton) return SkeletonJacobian(m, t, y, values, scratch);
  if (m.space.dimensions > 1) return SpaceJacobian(m, t, y, values);
  std::fill(values, values + m.pattern.entries(), 0.0);
  for (const FreeNode& f : m.free_nodes) {
    if (f.massless) continue;  // JunctionJacobian's
    values[f.slot_rate[0]] = 1.0;
    values[f.slot_position[0]] = f.loads.ForceSlope();
  }
  const double* w = JunctionVelocities(m, t, y, scratch.junction_velocities);
  for (const int e : m.active_links) {
    const Link& link = m.links[e];
    const End& a = m.ends[link.from];
    const End& b = m.ends[link.to];
    const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
    const double ldot = RateOf(m, b, t, y, w) - RateOf(m, a, t, y, w);
    const Tension tension = TensionOf(m, e, t, l, ldot, y);
    // d(force on from)/d(x_from, v_from, x_to, v_to) = (-dT/dl, -dT/dldot, dT/dl, dT/dldot);
    // the force on `to` is the opposite
    const double by_state[4] = {-tension.by_length, -tension.by_rate, tension.by_length,
                                tension.by_rate};
    for (int c = 0; c < 4; ++c) {
      if (link.slot[0][c] >= 0) values[link.slot[0][c]] += by_state[c];
      if (link.slot[1][c] >= 0) values[link.slot[1][c]] -= by_state[c];
    }
    // +T on `from`, -T on `to`: d/du of each is +-dT/du
    if (link.slot_activation[0] >= 0) values[link.slot_activation[0]] += tension.by_activation;
    if (link.slot_activation[1] >= 0) values[link.slot_activation[1]] -= tension.by_activation;
  }
  for (const Activation& a : m.activations) {
    const ExcitationInput& input = *m.elements[a.element].excitation;
    values[a.slot] +=
        EvaluateActivationRate(input.dynamics, ExcitationOf(m, a.element, t, y), y[a.state])
            .by_activation;
  }
  ControlJacobian(m, t, y, values);
  for (int k = 0; k < m.pattern.entries(); ++k) {
    if (m.row_scale[k] >= 0) values[k] *= m.free_nodes[m.row_scale[k]].inverse_mass;
  }
  if (w != nullptr) JunctionJacobian(m, t, y, w, values, scratch.junction_rate_slopes);
}

std::vector<double> Breakpoints(const NetworkModel& m, double t0, double t1) {
  std::vector<double> times;
  const auto add = [&](const std::vector<double>& more) {
    times.insert(times.end(), more.begin(), more.end());
  };
  for (const Element& e : m.elements) {
    if (e.kind != ElementKind::kActuator || e.controlled) continue;
    add(e.excitation ? e.excitation->signal.Breakpoints(t0, t1) : e.activation.Breakpoints(t0, t1));
  }
  for (const Controller& c : m.controllers) {
    add(c.reference.Breakpoints(t0, t1));
    add(c.feedforward.Breakpoints(t0, t1));
    if (c.co_contraction) add(c.co_contraction->level.Breakpoints(t0, t1));
  }
  for (const Node& n : m.nodes) {
    if (n.kind == NodeKind::kPrescribed) add(n.motion.Breakpoints(t0, t1));
  }
  for (const FreeNode& f : m.free_nodes) add(f.loads.Breakpoints(t0, t1));
  SortUnique(times);
  return times;
}

void ObserveElement(const NetworkModel& m, int e, double t, const double* y, ElementSample& out) {
  const Link& link = m.links[e];
  if (m.space.dimensions > 1) {
    PathState path;  // measured once for both
    MeasureLink(m, e, t, y, path);
    out.length = path.geometry.length;
    out.lengthening_rate = path.length_rate;
  } else {
    out.length = PositionOf(m, m.ends[link.to], t, y) - PositionOf(m, m.ends[link.from], t, y);
    out.lengthening_rate =
        VelocityOf(m, m.ends[link.to], t, y) - VelocityOf(m, m.ends[link.from], t, y);
  }
  const Element& element = m.elements[e];
  if (element.kind == ElementKind::kActuator) {
    if (element.excitation) {
      out.activation = y[link.activation];
      out.excitation = ExcitationOf(m, e, t, y);
    } else {
      out.activation = out.excitation =
          link.loop >= 0 ? ControlOutput(m, e, t, y) : element.activation.Evaluate(t);
    }
    out.parts = element.model->Evaluate(out.length, -out.lengthening_rate, out.activation);
    out.tension = out.parts.total;
  } else {
    out.activation = out.excitation = 0.0;
    out.parts = TensionSample{};
    out.tension = TensionOf(m, e, t, out.length, out.lengthening_rate, y).value;
  }
}

double LoadOn(const NetworkModel& m, int i, double t, const double* y) {
  // m.free_nodes are in node order (AddFreeNodes): a binary search, so that a row of a large
  // network's load columns costs n log n, not n^2
  const auto f = std::lower_bound(m.free_nodes.begin(), m.free_nodes.end(), i,
                                  [](const FreeNode& free, int node) { return free.node < node; });
  if (f == m.free_nodes.end() || f->node != i) return 0.0;
  if (m.space.dimensions > 1) {
    const Coordinates load = DirectedLoad(m, *f, t, y);
    return std::sqrt(load[0] * load[0] + load[1] * load[1] + load[2] * load[2]);
  }
  return f->loads.Force(t, PositionOf(m, m.ends[i], t, y));
}

void Observe(const NetworkModel& m, double t, const double* y, NetworkSample& sample) {
  if (m.space.dimensions > 1) return ObserveSpace(m, t, y, sample);
  sample.position.resize(m.nodes.size());
  sample.velocity.resize(m.nodes.size());
  sample.load.assign(m.nodes.size(), 0.0);
  sample.elements.resize(m.elements.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    sample.position[i] = PositionOf(m, m.ends[i], t, y);
    sample.velocity[i] = VelocityOf(m, m.ends[i], t, y);
  }
  for (const FreeNode& f : m.free_nodes) {
    sample.load[f.node] = f.loads.Force(t, sample.position[f.node]);
  }
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    ObserveElement(m, static_cast<int>(e), t, y, sample.elements[e]);
  }
  ObserveControllers(m, t, y, sample);
}

}  // namespace musclesim::network
