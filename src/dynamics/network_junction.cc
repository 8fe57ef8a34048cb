// Massless junctions on a line (docs/model.md 14.4): a free node of mass 0 whose velocity w is
// the root of its force balance R(w) = its loads + the forces of its elements = 0, found to
// machine precision in every evaluation, with dw/dy = -(dR/dw)^-1 dR/dy for the Jacobian.
#include "dynamics/network_junction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dynamics/element_tension.h"
#include "dynamics/network_evaluation.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "part_paths.h"

namespace musclesim::network {

namespace {

// Whether an element's tension is a function of its length alone (w leaves it unchanged).
bool Elastic(const Element& element) {
  return element.kind == ElementKind::kSpring || element.kind == ElementKind::kTendon;
}

// Whether an element's tension depends on its lengthening rate at zero activation: what makes
// a junction's balance fix its velocity.
bool RateDependentAtRest(const Element& element) {
  switch (element.kind) {
    case ElementKind::kDamper: return element.damping > 0.0;
    case ElementKind::kActuator: return element.model->PassiveDependsOnRate();
    case ElementKind::kSpring:
    case ElementKind::kTendon: return false;
  }
  return false;
}

std::string Described(const Element& element) {
  return element.name + " (" + std::string(ToString(element.kind)) + ")";
}

}  // namespace

void ResolveJunctions(NetworkModel& m) {
  for (std::size_t f = 0; f < m.free_nodes.size(); ++f) {
    if (!m.free_nodes[f].massless) continue;
    m.ends[m.free_nodes[f].node].junction = static_cast<int>(m.junctions.size());
    m.junctions.push_back(
        {static_cast<int>(f), m.ends[m.free_nodes[f].node].state, {}, {}, {}, {}, {}, -1});
  }
  for (Junction& junction : m.junctions) {
    const int node = m.free_nodes[junction.free].node;
    const std::string name = m.nodes[node].name;
    if (!m.controllers.empty()) {
      throw ParameterError(Entry("nodes", static_cast<std::size_t>(node), "mass"), "0",
                           "a massless junction and controllers in one network are not "
                           "supported yet (controllers[0] is " +
                               m.controllers.front().name + "): give node " + name + " a mass");
    }
    bool fixes_velocity = false;
    std::string attached;  // every element at the node, for the refusal's message
    for (std::size_t e = 0; e < m.links.size(); ++e) {
      if (m.links[e].from != node && m.links[e].to != node) continue;
      const Element& element = m.elements[e];
      const bool inert = element.kind == ElementKind::kDamper && element.damping == 0.0;
      attached +=
          (attached.empty() ? "" : ", ") + Described(element) + (inert ? " with damping 0" : "");
    }
    for (const int e : m.active_links) {
      const Link& link = m.links[e];
      if (link.from != node && link.to != node) continue;
      const int other = link.from == node ? link.to : link.from;
      if (m.ends[other].junction >= 0) {
        throw ParameterError(
            Entry("elements", static_cast<std::size_t>(e), "name"), m.elements[e].name,
            "joins two massless junctions (" + name + " and " + m.nodes[other].name +
                "), whose balances would couple; give one of them a mass");
      }
      junction.links.push_back(e);
      fixes_velocity = fixes_velocity || RateDependentAtRest(m.elements[e]);
    }
    if (!fixes_velocity) {
      throw ParameterError(
          Entry("nodes", static_cast<std::size_t>(node), "mass"), "0",
          "a massless junction's velocity must follow from its force balance, which needs an "
          "element at it whose tension depends on its lengthening rate at zero activation (a "
          "damper with damping > 0, or a degroote2016 actuator with fiber_damping > 0); node " +
              name + " has " + (attached.empty() ? std::string("no element") : attached));
    }
    // the states w depends on: its own position, each neighbour's position and velocity, each
    // element's activation
    std::vector<int>& columns = junction.columns;
    columns.push_back(junction.state);
    for (const int e : junction.links) {
      const Link& link = m.links[e];
      const End& other = m.ends[link.from == node ? link.to : link.from];
      for (const int state : {other.state, other.rate, link.activation}) {
        if (state >= 0) columns.push_back(state);
      }
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    const auto position = [&](int state) {
      if (state < 0) return -1;
      return static_cast<int>(std::lower_bound(columns.begin(), columns.end(), state) -
                              columns.begin());
    };
    junction.own_column = position(junction.state);
    for (const int e : junction.links) {
      const Link& link = m.links[e];
      const End& other = m.ends[link.from == node ? link.to : link.from];
      junction.link_columns.push_back(
          {position(other.state), position(other.rate), position(link.activation)});
    }
  }
}

void AddJunctionPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  for (const Junction& junction : m.junctions) {
    const int node = m.free_nodes[junction.free].node;
    for (const int c : junction.columns) pairs.emplace_back(c, junction.state);
    // a neighbour's acceleration depends on w, so on every state w depends on
    for (const int e : junction.links) {
      const int row = m.ends[m.links[e].from == node ? m.links[e].to : m.links[e].from].rate;
      if (row < 0) continue;
      for (const int c : junction.columns) pairs.emplace_back(c, row);
    }
  }
}

void FindJunctionSlots(NetworkModel& m, const std::function<int(int, int)>& slot) {
  for (Junction& junction : m.junctions) {
    const int node = m.free_nodes[junction.free].node;
    for (const int c : junction.columns) junction.row_slots.push_back(slot(junction.state, c));
    for (const int e : junction.links) {
      const int row = m.ends[m.links[e].from == node ? m.links[e].to : m.links[e].from].rate;
      for (const int c : junction.columns) {
        junction.neighbour_slots.push_back(row >= 0 ? slot(row, c) : -1);
      }
    }
  }
}

Balance JunctionBalance(const NetworkModel& m, const Junction& junction, double t, const double* y,
                        double w, bool elastic) {
  const FreeNode& f = m.free_nodes[junction.free];
  Balance balance{0.0, 0.0, 0.0};
  if (elastic) {
    const double load = f.loads.Force(t, y[junction.state]);
    balance = {load, 0.0, std::abs(load)};
  }
  for (const int e : junction.links) {
    if (Elastic(m.elements[e]) != elastic) continue;
    const Link& link = m.links[e];
    const End& a = m.ends[link.from];
    const End& b = m.ends[link.to];
    const bool from = link.from == f.node;
    const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
    const double ldot = from ? VelocityOf(m, b, t, y) - w : w - VelocityOf(m, a, t, y);
    const Tension tension = TensionOf(m, e, t, l, ldot, y);
    // +T on `from`, -T on `to`; either way the force falls as w rises, by dT/d(ldot)
    balance.residual += from ? tension.value : -tension.value;
    balance.by_velocity -= tension.by_rate;
    balance.magnitude += std::abs(tension.value);
  }
  return balance;
}

double JunctionVelocity(const NetworkModel& m, int k, double t, const double* y) {
  const Junction& junction = m.junctions[k];
  const int node = m.free_nodes[junction.free].node;
  // the first guess: the mean velocity of the neighbours across elastic elements (a tendon's
  // far end: a stiff tendon carries its end's motion to the junction), else of all neighbours
  double w = 0.0, across_elastic = 0.0;
  int elastic_links = 0;
  for (const int e : junction.links) {
    const double v =
        VelocityOf(m, m.ends[m.links[e].from == node ? m.links[e].to : m.links[e].from], t, y);
    w += v;
    if (Elastic(m.elements[e])) {
      across_elastic += v;
      ++elastic_links;
    }
  }
  w = elastic_links > 0 ? across_elastic / elastic_links
                        : w / static_cast<double>(junction.links.size());
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // Newton's iteration, safeguarded: R falls as w rises, so each evaluation narrows the
  // bracket [low, high] that holds the root (open while one side is unknown). A Newton step
  // leaving it is replaced by bisection, or, while a side is open, by a step doubled towards it.
  double low = -kInfinity, high = kInfinity;
  double reach = 1e-3 * (1.0 + std::abs(w));  // an open side's trial step [m/s]
  // the last two steps: Newton's steps that do not halve in two iterations are crawling (a
  // steep bend of R between flat stretches), and bisection takes over (as in rtsafe)
  double last_step = kInfinity, step_before = kInfinity;
  // the loads and the elastic elements, once: only the other elements' tensions move with w
  const Balance elastic = JunctionBalance(m, junction, t, y, w, true);
  for (int iteration = 0; iteration < 400; ++iteration) {
    Balance balance = JunctionBalance(m, junction, t, y, w, false);
    balance.residual += elastic.residual;
    balance.magnitude += elastic.magnitude;
    if (!std::isfinite(balance.residual)) return kNaN;
    if (balance.residual == 0.0) return w;
    (balance.residual > 0.0 ? low : high) = w;
    double next = balance.by_velocity < 0.0 ? w - balance.residual / balance.by_velocity : kNaN;
    // R at its rounding level: its Newton step is the last correction it can give
    const bool balanced = std::abs(balance.residual) <= 4.0 * kEpsilon * balance.magnitude;
    if (balanced && std::isfinite(next)) return next;
    const bool bracketed = std::isfinite(low) && std::isfinite(high);
    const bool crawling = bracketed && std::abs(next - w) > 0.5 * step_before;
    if (!(next > low && next < high) || crawling) {
      if (bracketed) {
        next = 0.5 * (low + high);
      } else {
        next = balance.residual > 0.0 ? w + reach : w - reach;
        reach *= 2.0;
      }
    }
    const double tolerance = 2.0 * kEpsilon * std::max(std::abs(next), 1e-12);
    if (std::abs(next - w) <= tolerance || high - low <= tolerance) return next;
    step_before = last_step;
    last_step = std::abs(next - w);
    w = next;
  }
  return kNaN;  // no root within reach: the run fails, and NonFiniteCause names the junction
}

std::string JunctionFailure(const NetworkModel& m, int k, double t, const double* y) {
  if (std::isfinite(JunctionVelocity(m, k, t, y))) return "";
  const Junction& junction = m.junctions[k];
  const int node = m.free_nodes[junction.free].node;
  for (const int e : junction.links) {
    if (!Elastic(m.elements[e])) continue;
    // an elastic element's tension depends on its length alone: the junction's velocity
    // cannot mend it
    const double l = Length(m, e, t, y);
    const double tension = TensionOf(m, e, t, l, 0.0, y).value;
    if (!std::isfinite(tension)) {
      return "elements[" + std::to_string(e) + "] (" + m.elements[e].name + ")'s tension is " +
             FormatNumber(tension) + " N at length " + FormatNumber(l) +
             " m: its law overflows there, and massless junction " + m.nodes[node].name +
             " cannot balance it";
    }
  }
  return "the force balance of massless junction " + m.nodes[node].name +
         " at x = " + FormatNumber(y[junction.state]) +
         " m has no finite root: no velocity of it balances the forces of its elements";
}

const double* JunctionVelocities(const NetworkModel& m, double t, const double* y,
                                 std::vector<double>& velocities) {
  if (m.junctions.empty()) return nullptr;
  velocities.resize(m.junctions.size());
  for (std::size_t k = 0; k < m.junctions.size(); ++k) {
    velocities[k] = JunctionVelocity(m, static_cast<int>(k), t, y);
  }
  return velocities.data();
}

double JunctionVelocityAlong(const NetworkModel& m, int k, double t, const double* y,
                             const double* s) {
  const Junction& junction = m.junctions[k];
  const FreeNode& f = m.free_nodes[junction.free];
  const double w = JunctionVelocity(m, k, t, y);
  const auto along = [&](int state) { return state >= 0 ? s[state] : 0.0; };
  const double own = s[junction.state];
  // dR/dy s, term by term as JunctionJacobian's row, and dR/dw
  double by_state = f.loads.ForceSlope() * own, by_velocity = 0.0;
  for (const int e : junction.links) {
    const Link& link = m.links[e];
    const bool from = link.from == f.node;
    const End& other = m.ends[from ? link.to : link.from];
    const double l = PositionOf(m, m.ends[link.to], t, y) - PositionOf(m, m.ends[link.from], t, y);
    const double ldot = from ? VelocityOf(m, other, t, y) - w : w - VelocityOf(m, other, t, y);
    const Tension tension = TensionOf(m, e, t, l, ldot, y);
    by_state +=
        tension.by_length * (along(other.state) - own) + tension.by_rate * along(other.rate);
    if (link.activation >= 0) {
      by_state += (from ? tension.by_activation : -tension.by_activation) * s[link.activation];
    }
    by_velocity -= tension.by_rate;
  }
  return -by_state / by_velocity;
}

void JunctionJacobian(const NetworkModel& m, double t, const double* y, const double* w,
                      double* values, std::vector<double>& by_rate) {
  for (std::size_t k = 0; k < m.junctions.size(); ++k) {
    const Junction& junction = m.junctions[k];
    const FreeNode& f = m.free_nodes[junction.free];
    const std::vector<int>& slots = junction.row_slots;
    // dR/dy in the junction's row first, then scaled into dw/dy
    double by_velocity = 0.0;
    values[slots[junction.own_column]] += f.loads.ForceSlope();
    by_rate.resize(junction.links.size());
    for (std::size_t i = 0; i < junction.links.size(); ++i) {
      const int e = junction.links[i];
      const Link& link = m.links[e];
      const End& a = m.ends[link.from];
      const End& b = m.ends[link.to];
      const bool from = link.from == f.node;
      const double l = PositionOf(m, b, t, y) - PositionOf(m, a, t, y);
      const double ldot = from ? VelocityOf(m, b, t, y) - w[k] : w[k] - VelocityOf(m, a, t, y);
      const Tension tension = TensionOf(m, e, t, l, ldot, y);
      // the force on the junction, +T as `from`, -T as `to`, with l = x_to - x_from: it
      // falls with the junction's position and rises with the other end's, either way
      const std::array<int, 3>& columns = junction.link_columns[i];
      values[slots[junction.own_column]] -= tension.by_length;
      if (columns[0] >= 0) values[slots[columns[0]]] += tension.by_length;
      if (columns[1] >= 0) values[slots[columns[1]]] += tension.by_rate;
      if (columns[2] >= 0) {
        values[slots[columns[2]]] += from ? tension.by_activation : -tension.by_activation;
      }
      by_velocity -= tension.by_rate;
      by_rate[i] = tension.by_rate;
    }
    // dw/dy = -(dR/dw)^-1 dR/dy
    const std::size_t n = junction.columns.size();
    for (std::size_t c = 0; c < n; ++c) values[slots[c]] /= -by_velocity;
    // a neighbour with a mass: the element's force on it rises with w by dT/d(ldot), either
    // end, so its acceleration gains dT/d(ldot) / m dw/dy
    for (std::size_t i = 0; i < junction.links.size(); ++i) {
      const int e = junction.links[i];
      const int other = m.links[e].from == f.node ? m.links[e].to : m.links[e].from;
      if (m.ends[other].rate < 0) continue;
      const double gain = by_rate[i] * m.free_nodes[m.ends[other].free].inverse_mass;
      for (std::size_t c = 0; c < n; ++c) {
        values[junction.neighbour_slots[i * n + c]] += gain * values[slots[c]];
      }
    }
  }
}

}  // namespace musclesim::network
