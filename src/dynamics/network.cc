// A network evaluated: its initial state, right-hand side, Jacobian, kinks, inputs' breaks,
// observations and sensitivities' partials on a line (network.h; the plane and space in
// network_space.cc, space_jacobian.cc).
#include "musclesim/dynamics/network.h"

#include "dynamics/element_tension.h"
#include "dynamics/network_space.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "part_paths.h"

namespace musclesim {

void NetworkSystem::InitialState(double t_start, double* y) const {
  const int d = space_.dimensions;
  for (const FreeNode& f : free_nodes_) {
    const int s = ends_[f.node].state;
    const Coordinates position = nodes_[f.node].PositionCoordinates();
    const Coordinates velocity = nodes_[f.node].VelocityCoordinates();
    for (int c = 0; c < d; ++c) {
      y[s + c] = position[c];
      if (!f.massless) y[s + d + c] = velocity[c];
    }
  }
  for (const Activation& a : activations_) {
    y[a.state] = elements_[a.element].excitation->InitialActivation(t_start);
  }
}

void NetworkSystem::CheckInitialState(double t, const double* y) const {
  if (space_.dimensions > 1) CheckInitialPaths(t, y);
  for (std::size_t e = 0; e < elements_.size() && space_.dimensions == 1; ++e) {
    const double l = Length(static_cast<int>(e), t, y);
    if (!(l > 0.0)) {
      const Element& element = elements_[e];
      throw ParameterError("elements[" + std::to_string(e) + "]", element.name,
                           "must be longer than 0 at the start: its length x(" + element.to +
                               ") - x(" + element.from + ") is " + FormatNumber(l) + " m");
    }
  }
  for (std::size_t k = 0; k < junctions_.size(); ++k) {
    const std::string failure = JunctionFailure(static_cast<int>(k), t, y);
    if (!failure.empty()) {
      const int node = free_nodes_[junctions_[k].free].node;
      throw ParameterError("nodes[" + std::to_string(node) + "]", nodes_[node].name,
                           "at the start, " + failure);
    }
  }
  ElementSample sample;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    ObserveElement(static_cast<int>(e), t, y, sample);
    if (!std::isfinite(sample.tension)) {
      const Element& element = elements_[e];
      throw ParameterError("elements[" + std::to_string(e) + "]", element.name,
                           "its tension at the start is " + FormatNumber(sample.tension) +
                               " N (length " + FormatNumber(sample.length) +
                               " m): its law overflows there; an exponential's alpha times its "
                               "stretch must stay below about 700");
    }
  }
}

double NetworkSystem::PositionOf(const End& end, double t, const double* y) const {
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state];
    case NodeKind::kFixed: return end.position;
    case NodeKind::kPrescribed: return nodes_[end.node].motion.Evaluate(t);
  }
  return 0.0;
}

double NetworkSystem::VelocityOf(const End& end, double t, const double* y) const {
  switch (end.kind) {
    case NodeKind::kFree:
      return end.junction >= 0 ? JunctionVelocity(end.junction, t, y) : y[end.rate];
    case NodeKind::kFixed: return 0.0;
    case NodeKind::kPrescribed: return nodes_[end.node].motion.Slope(t);
  }
  return 0.0;
}

double NetworkSystem::Length(int e, double t, const double* y) const {
  if (space_.dimensions > 1) return SegmentLength(e, -1, t, y);
  const Link& link = links_[e];
  return PositionOf(ends_[link.to], t, y) - PositionOf(ends_[link.from], t, y);
}

double NetworkSystem::LengtheningRate(int e, double t, const double* y) const {
  if (space_.dimensions > 1) return SpaceLengtheningRate(e, t, y);
  const Link& link = links_[e];
  return VelocityOf(ends_[link.to], t, y) - VelocityOf(ends_[link.from], t, y);
}

double NetworkSystem::KinkValue(const Kink& kink, double t, const double* y) const {
  switch (kink.kind) {
    case Kink::kLength: return Length(kink.element, t, y) - kink.level;
    case Kink::kLengtheningRate: return LengtheningRate(kink.element, t, y) - kink.level;
    case Kink::kExcitation:
      return ExcitationOf(kink.element, t, y) - y[links_[kink.element].activation];
    case Kink::kCommand: {
      const int loop = links_[kink.element].loop;
      return UnclampedOutput(kink.element, CommandOf(loop, t, y), t) - kink.level;
    }
  }
  return 0.0;
}

void NetworkSystem::SingleNodeRightHandSide(double t, const double* y, double* ydot) const {
  const FreeNode& f = free_nodes_.front();
  const int s = ends_[f.node].state;
  const double x = y[s], v = y[s + 1];
  ydot[s] = v;
  double force = f.loads.Force(t, x);
  for (const Anchored& a : anchored_) {
    // as RightHandSide: l = x_to - x_from, ldot = v_to - v_from (a fixed end's velocity 0)
    if (a.sign > 0) {
      force -= TensionOf(a.element, t, x - a.position, v - 0.0, y).value;
    } else {
      force += TensionOf(a.element, t, a.position - x, 0.0 - v, y).value;
    }
  }
  ydot[s + 1] = force * f.inverse_mass;
}

void NetworkSystem::RightHandSide(double t, const double* y, double* ydot,
                                  NetworkScratch& scratch) const {
  if (single_node_) return SingleNodeRightHandSide(t, y, ydot);
  if (space_.dimensions > 1) return SpaceRightHandSide(t, y, ydot);
  const double* w = JunctionVelocities(t, y, scratch.junction_velocities);
  for (const FreeNode& f : free_nodes_) {
    const End& end = ends_[f.node];
    if (f.massless) {
      ydot[end.state] = w[end.junction];
      continue;
    }
    ydot[end.state] = y[end.rate];
    ydot[end.rate] = f.loads.Force(t, y[end.state]);
  }
  for (const int e : active_links_) {
    const End& a = ends_[links_[e].from];
    const End& b = ends_[links_[e].to];
    const double l = PositionOf(b, t, y) - PositionOf(a, t, y);
    const double ldot = RateOf(b, t, y, w) - RateOf(a, t, y, w);
    const double tension = TensionOf(e, t, l, ldot, y).value;
    // +T pulls `from` towards `to`, -T pulls `to` back
    if (a.rate >= 0) ydot[a.rate] += tension;
    if (b.rate >= 0) ydot[b.rate] -= tension;
  }
  for (const FreeNode& f : free_nodes_) {
    if (!f.massless) ydot[ends_[f.node].rate] *= f.inverse_mass;
  }
  for (const Activation& a : activations_) {
    const ExcitationInput& input = *elements_[a.element].excitation;
    ydot[a.state] =
        EvaluateActivationRate(input.dynamics, ExcitationOf(a.element, t, y), y[a.state]).value;
  }
  ControlRightHandSide(t, y, ydot);
}

void NetworkSystem::Jacobian(double t, const double* y, double* values,
                             NetworkScratch& scratch) const {
  if (space_.dimensions > 1) return SpaceJacobian(t, y, values);
  std::fill(values, values + pattern_.entries(), 0.0);
  for (const FreeNode& f : free_nodes_) {
    if (f.massless) continue;  // JunctionJacobian's
    values[f.slot_rate[0]] = 1.0;
    values[f.slot_position[0]] = f.loads.ForceSlope();
  }
  const double* w = JunctionVelocities(t, y, scratch.junction_velocities);
  for (const int e : active_links_) {
    const Link& link = links_[e];
    const End& a = ends_[link.from];
    const End& b = ends_[link.to];
    const double l = PositionOf(b, t, y) - PositionOf(a, t, y);
    const double ldot = RateOf(b, t, y, w) - RateOf(a, t, y, w);
    const Tension tension = TensionOf(e, t, l, ldot, y);
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
  for (const Activation& a : activations_) {
    const ExcitationInput& input = *elements_[a.element].excitation;
    values[a.slot] +=
        EvaluateActivationRate(input.dynamics, ExcitationOf(a.element, t, y), y[a.state])
            .by_activation;
  }
  ControlJacobian(t, y, values);
  for (int k = 0; k < pattern_.entries(); ++k) {
    if (row_scale_[k] >= 0) values[k] *= free_nodes_[row_scale_[k]].inverse_mass;
  }
  if (w != nullptr) JunctionJacobian(t, y, w, values, scratch.junction_rate_slopes);
}

std::vector<double> NetworkSystem::Breakpoints(double t0, double t1) const {
  std::vector<double> times;
  const auto add = [&](const std::vector<double>& more) {
    times.insert(times.end(), more.begin(), more.end());
  };
  for (const Element& e : elements_) {
    if (e.kind != ElementKind::kActuator || e.controlled) continue;
    add(e.excitation ? e.excitation->signal.Breakpoints(t0, t1) : e.activation.Breakpoints(t0, t1));
  }
  for (const Controller& c : controllers_) {
    add(c.reference.Breakpoints(t0, t1));
    add(c.feedforward.Breakpoints(t0, t1));
    if (c.co_contraction) add(c.co_contraction->level.Breakpoints(t0, t1));
  }
  for (const Node& n : nodes_) {
    if (n.kind == NodeKind::kPrescribed) add(n.motion.Breakpoints(t0, t1));
  }
  for (const FreeNode& f : free_nodes_) add(f.loads.Breakpoints(t0, t1));
  SortUnique(times);
  return times;
}

void NetworkSystem::ObserveElement(int e, double t, const double* y, ElementSample& out) const {
  const Link& link = links_[e];
  if (space_.dimensions > 1) {
    PathState path;  // measured once for both
    MeasureLink(e, t, y, path);
    out.length = path.geometry.length;
    out.lengthening_rate = path.length_rate;
  } else {
    out.length = PositionOf(ends_[link.to], t, y) - PositionOf(ends_[link.from], t, y);
    out.lengthening_rate = VelocityOf(ends_[link.to], t, y) - VelocityOf(ends_[link.from], t, y);
  }
  const Element& element = elements_[e];
  if (element.kind == ElementKind::kActuator) {
    if (element.excitation) {
      out.activation = y[link.activation];
      out.excitation = ExcitationOf(e, t, y);
    } else {
      out.activation = out.excitation =
          link.loop >= 0 ? ControlOutput(e, t, y) : element.activation.Evaluate(t);
    }
    out.parts = element.model->Evaluate(out.length, -out.lengthening_rate, out.activation);
    out.tension = out.parts.total;
  } else {
    out.activation = out.excitation = 0.0;
    out.parts = TensionSample{};
    out.tension = TensionOf(e, t, out.length, out.lengthening_rate, y).value;
  }
}

double NetworkSystem::LoadOn(int i, double t, const double* y) const {
  // free_nodes_ are in node order (AddFreeNodes): a binary search, so that a row of a large
  // network's load columns costs n log n, not n^2
  const auto f = std::lower_bound(free_nodes_.begin(), free_nodes_.end(), i,
                                  [](const FreeNode& free, int node) { return free.node < node; });
  if (f == free_nodes_.end() || f->node != i) return 0.0;
  if (space_.dimensions > 1) {
    const Coordinates load = DirectedLoad(*f, t, y);
    return std::sqrt(load[0] * load[0] + load[1] * load[1] + load[2] * load[2]);
  }
  return f->loads.Force(t, PositionOf(ends_[i], t, y));
}

void NetworkSystem::Observe(double t, const double* y, NetworkSample& sample) const {
  if (space_.dimensions > 1) return ObserveSpace(t, y, sample);
  sample.position.resize(nodes_.size());
  sample.velocity.resize(nodes_.size());
  sample.load.assign(nodes_.size(), 0.0);
  sample.elements.resize(elements_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    sample.position[i] = PositionOf(ends_[i], t, y);
    sample.velocity[i] = VelocityOf(ends_[i], t, y);
  }
  for (const FreeNode& f : free_nodes_) {
    sample.load[f.node] = f.loads.Force(t, sample.position[f.node]);
  }
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    ObserveElement(static_cast<int>(e), t, y, sample.elements[e]);
  }
  ObserveControllers(t, y, sample);
}

NetworkSystem::ElementPartials NetworkSystem::Along(int e, double t, const double* y,
                                                    const double* s) const {
  if (space_.dimensions > 1) return SpaceAlong(e, t, y, s);
  const Link& link = links_[e];
  const End& a = ends_[link.from];
  const End& b = ends_[link.to];
  // only free nodes' positions and velocities are states; the others do not move with y
  const auto along = [&](int state) { return state >= 0 ? s[state] : 0.0; };
  const double dl = along(b.state) - along(a.state);
  const double dldot = NodeVelocityAlong(link.to, t, y, s) - NodeVelocityAlong(link.from, t, y, s);
  const double l = PositionOf(b, t, y) - PositionOf(a, t, y);
  const double ldot = VelocityOf(b, t, y) - VelocityOf(a, t, y);
  const Tension tension = TensionOf(e, t, l, ldot, y);
  const double du = link.activation >= 0 ? s[link.activation] : 0.0;
  ElementPartials out;
  out.length = dl;
  out.total = tension.by_length * dl + tension.by_rate * dldot + tension.by_activation * du;
  if (elements_[e].kind == ElementKind::kActuator) {
    // the passive part's own derivatives (fiber damping moves it with the rate, v = -ldot)
    const TensionSample passive = elements_[e].model->Passive(l, -ldot);
    out.passive = passive.d_length * dl - passive.d_velocity * dldot;
    out.active = out.total - out.passive;
  }
  return out;
}

double NetworkSystem::NodeVelocityAlong(int node, double t, const double* y,
                                        const double* s) const {
  const End& end = ends_[node];
  if (end.junction >= 0) return JunctionVelocityAlong(end.junction, t, y, s);
  return end.rate >= 0 ? s[end.rate] : 0.0;
}

void NetworkSystem::AddTension(int e, double t, const double* y, double tension,
                               double* ydot) const {
  if (space_.dimensions > 1) return AddSpaceTension(e, t, y, tension, ydot);
  const Link& link = links_[e];
  const End& a = ends_[link.from];
  const End& b = ends_[link.to];
  // as RightHandSide: +T pulls `from`, -T pulls `to`, each over its node's mass
  if (a.rate >= 0) ydot[a.rate] += tension * free_nodes_[a.free].inverse_mass;
  if (b.rate >= 0) ydot[b.rate] -= tension * free_nodes_[b.free].inverse_mass;
}

}  // namespace musclesim
