// A network built: its parts validated, resolved into the right-hand side's ends, links,
// free nodes and kinks, and its Jacobian's pattern and slots found (network_build.h).
#include "dynamics/network_build.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "dynamics/network_control.h"
#include "dynamics/network_junction.h"
#include "dynamics/network_skeleton.h"
#include "dynamics/network_space.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "part_paths.h"

namespace musclesim::network {

namespace {

// Each part's index by its name, throwing ParameterError for an empty or repeated name (in
// time linear in the parts: a network of a million nodes is checked as fast as it is read).
template <typename Part>
std::unordered_map<std::string, int> IndexByName(const std::vector<Part>& parts, const char* list) {
  std::unordered_map<std::string, int> index;
  index.reserve(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].name.empty())
      throw ParameterError(Entry(list, i, "name"), "", "must not be empty");
    const auto [at, added] = index.emplace(parts[i].name, static_cast<int>(i));
    if (!added) {
      throw ParameterError(Entry(list, i, "name"), parts[i].name,
                           "must be unique: " + std::string(list) + "[" +
                               std::to_string(at->second) + "] has it too");
    }
  }
  return index;
}

// A union-find over node indices: which nodes the elements join.
class Components {
 public:
  explicit Components(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t Find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void Join(std::size_t a, std::size_t b) { parent_[Find(a)] = Find(b); }

 private:
  std::vector<std::size_t> parent_;
};

// Whether each node is joined, through elements, to a fixed or prescribed node.
std::vector<bool> AnchoredNodes(const std::vector<Node>& nodes, Components& joined) {
  std::vector<bool> anchored_root(nodes.size(), false);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].kind != NodeKind::kFree) anchored_root[joined.Find(i)] = true;
  }
  std::vector<bool> anchored(nodes.size(), false);
  for (std::size_t i = 0; i < nodes.size(); ++i) anchored[i] = anchored_root[joined.Find(i)];
  return anchored;
}

}  // namespace

void Build(NetworkModel& m) {
  Validate(m.space);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) ValidateEntry(m.nodes[i], "nodes", i);
  for (std::size_t i = 0; i < m.elements.size(); ++i) ValidateEntry(m.elements[i], "elements", i);
  for (std::size_t i = 0; i < m.controllers.size(); ++i) {
    ValidateEntry(m.controllers[i], "controllers", i);
  }
  m.node_index = IndexByName(m.nodes, "nodes");
  m.element_index = IndexByName(m.elements, "elements");
  m.controller_index = IndexByName(m.controllers, "controllers");
  Resolve(m);
  BuildPattern(m);
}

namespace {

int Find(const std::unordered_map<std::string, int>& index, std::string_view name) {
  const auto it = index.find(std::string(name));
  return it == index.end() ? -1 : it->second;
}

}  // namespace

int FindNode(const NetworkModel& m, std::string_view name) { return Find(m.node_index, name); }

int FindElement(const NetworkModel& m, std::string_view name) {
  return Find(m.element_index, name);
}

int FindController(const NetworkModel& m, std::string_view name) {
  return Find(m.controller_index, name);
}

void Resolve(NetworkModel& m) {
  int states = NumberEnds(m);
  for (std::size_t e = 0; e < m.elements.size(); ++e) AddLink(m, e, states);
  Components joined(m.nodes.size());
  for (const Link& link : m.links) {
    joined.Join(static_cast<std::size_t>(link.from), static_cast<std::size_t>(link.to));
    // a via node is on the path: the element's tension acts on it too
    for (int p = link.path_begin; p < link.path_end; ++p) {
      if (m.path_points[p].node >= 0) {
        joined.Join(static_cast<std::size_t>(link.from),
                    static_cast<std::size_t>(m.path_points[p].node));
      }
    }
  }
  std::vector<std::vector<Load>> node_loads = LoadsByNode(m);
  AddFreeNodes(m, std::move(node_loads), AnchoredNodes(m.nodes, joined));
  if (m.space.dimensions > 1) ResolveSpace(m);
  ResolveControllers(m, states);
  ResolveJunctions(m);
  FindSingleNode(m);
}

int NodeNamed(const NetworkModel& m, const std::string& name, const std::string& path) {
  const int i = FindNode(m, name);
  if (i < 0) {
    throw ParameterError(path, name, "names no node; the nodes are: " + KnownNames(m.nodes));
  }
  return i;
}

int BodyNamed(const NetworkModel& m, const std::string& name, std::size_t node) {
  const std::string path = Entry("nodes", node, "body");
  if (!m.skeleton) {
    throw ParameterError(path, name, "names a body, and the network has none (no bodies:)");
  }
  const int body = m.skeleton->FindBody(name);
  if (body == -1) {
    throw ParameterError(path, name, "must name a body: a point of the ground is a fixed node");
  }
  if (body < 0) {
    throw ParameterError(path, name,
                         "names no body; the bodies are: " + KnownNames(m.skeleton->bodies()));
  }
  return body;
}

int NumberEnds(NetworkModel& m) {
  int states = 0, free = 0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const Node& node = m.nodes[i];
    End end{node.kind, -1, node.position, static_cast<int>(m.ends.size()),
            node.PositionCoordinates()};
    if (node.kind == NodeKind::kFree) {
      end.state = states;
      end.free = free++;
      if (node.mass > 0.0) {
        end.rate = states + m.space.dimensions;
        states += 2 * m.space.dimensions;  // d coordinates, d velocities
      } else if (m.space.dimensions > 1) {
        throw ParameterError(Entry("nodes", i, "mass"), "0",
                             "a massless junction (mass 0) needs dimensions 1: in the plane "
                             "and in space every free node needs a mass > 0");
      } else {
        states += 1;  // a junction's position; its velocity solves its balance
      }
    }
    if (node.kind == NodeKind::kOnBody) end.body = BodyNamed(m, node.body, i);
    m.ends.push_back(end);
  }
  m.node_states = states;
  if (m.skeleton) {
    if (m.space.dimensions == 1) {
      throw ParameterError("dimensions", "1",
                           "must be 2 or 3 with bodies: a skeleton moves in the plane or in space");
    }
    if (m.skeleton->gravity() != m.space.gravity) {
      throw ParameterError("gravity", "the skeleton's",
                           "must be the network's: the bodies and the free nodes fall alike");
    }
    CheckPlanarSkeleton(m);
    PlaceWraps(m);
    m.skeleton_state = states;
    states += 2 * m.skeleton->coordinate_count();  // q, then u
  }
  return states;
}

void AddLink(NetworkModel& m, std::size_t e, int& states) {
  const Element& element = m.elements[e];
  Link link{NodeNamed(m, element.from, Entry("elements", e, "from")),
            NodeNamed(m, element.to, Entry("elements", e, "to")),
            {},
            -1,
            {-1, -1}};
  if (link.from == link.to) {
    throw ParameterError(Entry("elements", e, "to"), element.to,
                         "must differ from `from`: an element joins two nodes");
  }
  if (m.space.dimensions == 1 && !element.via.empty()) {
    throw ParameterError(Entry("elements", e, "via"),
                         std::to_string(element.via.size()) + " points",
                         "via points need dimensions 2 or 3: on a line an element is straight");
  }
  if (element.kind == ElementKind::kActuator && element.excitation) {
    // after every node's states (the nodes were numbered first)
    link.activation = states++;
    m.activations.push_back({static_cast<int>(e), link.activation, -1});
    if (HasExcitationKink(element.excitation->dynamics)) {
      m.kinks.push_back({Kink::kExcitation, static_cast<int>(e), 0.0});
    }
  }
  m.links.push_back(link);
  if (m.space.dimensions > 1) AddPath(m, e);
  const bool inert = (element.kind == ElementKind::kDamper && element.damping == 0.0) ||
                     (element.kind == ElementKind::kSpring && element.stiffness == 0.0);
  if (!inert) m.active_links.push_back(static_cast<int>(e));
  if (element.kind == ElementKind::kTendon && !element.pushes_below_slack) {
    m.kinks.push_back({Kink::kLength, static_cast<int>(e), element.slack_length});
  } else if (element.kind == ElementKind::kActuator) {
    if (const std::optional<double> kink = element.model->LengthKink()) {
      m.kinks.push_back({Kink::kLength, static_cast<int>(e), *kink});
    }
  }
  if (element.kind == ElementKind::kActuator && element.model->HasVelocityKink()) {
    m.kinks.push_back({Kink::kLengtheningRate, static_cast<int>(e), 0.0});  // v = 0
  }
}

std::vector<std::vector<Load>> LoadsByNode(const NetworkModel& m) {
  std::vector<std::vector<Load>> node_loads(m.nodes.size());
  for (std::size_t l = 0; l < m.loads.size(); ++l) {
    const int node = NodeNamed(m, m.loads[l].node, Entry("loads", l, "node"));
    if (m.nodes[node].kind != NodeKind::kFree) {
      throw ParameterError(Entry("loads", l, "node"), m.loads[l].node,
                           "must name a free node (one with a mass); it is " +
                               std::string(ToString(m.nodes[node].kind)));
    }
    try {
      Validate(m.loads[l].load);
    } catch (const ParameterError& e) {
      throw ParameterError("loads[" + std::to_string(l) + "]." + e.path(), e.value(), e.rule());
    }
    if (m.nodes[node].mass == 0.0 && m.loads[l].load.kind == LoadKind::kMass) {
      throw ParameterError(Entry("loads", l, "type"), "mass",
                           "a massless junction (node " + m.loads[l].node +
                               ", mass 0) carries no mass load: give the node the load's mass "
                               "instead");
    }
    node_loads[node].push_back(m.loads[l].load);
  }
  return node_loads;
}

void AddFreeNodes(NetworkModel& m, std::vector<std::vector<Load>> node_loads,
                  const std::vector<bool>& anchored) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (m.nodes[i].kind != NodeKind::kFree) continue;
    if (!anchored[i]) {
      throw ParameterError(Entry("nodes", i, "name"), m.nodes[i].name,
                           "floats: no chain of elements joins this free node to a fixed or "
                           "prescribed node");
    }
    LoadSet set(std::move(node_loads[i]));
    const bool massless = m.nodes[i].mass == 0.0;  // (LoadsByNode refused its mass loads)
    const double inverse_mass = massless ? 0.0 : 1.0 / (m.nodes[i].mass + set.AddedMass());
    m.free_nodes.push_back(
        {static_cast<int>(i), std::move(set), inverse_mass, {}, {}, {}, massless});
  }
  // without a free node the activations can still be the state: a muscle whose length is
  // prescribed (a rigid tendon, an isokinetic stretch) under its activation dynamics
  if (m.free_nodes.empty() && m.activations.empty() && !m.skeleton) {
    throw ParameterError("nodes", std::to_string(m.nodes.size()) + " nodes",
                         "need at least one free node (one with a mass) or an actuator with "
                         "activation dynamics: the state is their positions and activations");
  }
}

void FindSingleNode(NetworkModel& m) {
  if (m.space.dimensions > 1 || m.free_nodes.size() != 1 || !m.activations.empty() ||
      !m.controllers.empty() || !m.junctions.empty())
    return;
  const int free = m.free_nodes.front().node;
  for (const int e : m.active_links) {
    const Link& link = m.links[e];
    const int other = link.to == free ? link.from : link.to;
    if (m.ends[other].kind != NodeKind::kFixed) return;
    m.anchored.push_back({e, m.ends[other].position, link.to == free ? 1 : -1});
  }
  m.single_node = true;
}

void AddLinePattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  for (const Link& link : m.links) {
    // rows: the ends' accelerations; columns: their positions and velocities (a junction
    // has neither row nor velocity column: AddJunctionPattern adds what goes through w)
    for (int row_end : {link.from, link.to}) {
      for (int col_end : {link.from, link.to}) {
        const int r = m.ends[row_end].rate;
        if (r < 0) continue;
        if (m.ends[col_end].state >= 0) pairs.emplace_back(m.ends[col_end].state, r);
        if (m.ends[col_end].rate >= 0) pairs.emplace_back(m.ends[col_end].rate, r);
      }
    }
    // the tension's u: in both ends' acceleration rows
    for (int row_end : {link.from, link.to}) {
      const int r = m.ends[row_end].rate;
      if (link.activation >= 0 && r >= 0) pairs.emplace_back(link.activation, r);
    }
  }
}

void FindLineSlots(NetworkModel& m, const std::function<int(int, int)>& slot) {
  for (Link& link : m.links) {
    const int ends[2] = {link.from, link.to};
    for (int r = 0; r < 2; ++r) {
      const int row = m.ends[ends[r]].rate;
      for (int c = 0; c < 2; ++c) {
        const int position = m.ends[ends[c]].state, rate = m.ends[ends[c]].rate;
        link.slot[r][2 * c] = row >= 0 && position >= 0 ? slot(row, position) : -1;
        link.slot[r][2 * c + 1] = row >= 0 && rate >= 0 ? slot(row, rate) : -1;
      }
      link.slot_activation[r] = link.activation >= 0 && row >= 0 ? slot(row, link.activation) : -1;
    }
  }
}

void BuildPattern(NetworkModel& m) {
  // every (row, column) pair that can be nonzero, then compressed-column order
  std::vector<std::pair<int, int>> pairs;  // (column, row)
  const int d = m.space.dimensions;
  for (const FreeNode& f : m.free_nodes) {
    const int s = m.ends[f.node].state;
    const int n = f.massless ? 1 : 2 * d;  // a junction: its position alone
    for (int r = s; r < s + n; ++r) {
      for (int c = s; c < s + n; ++c) pairs.emplace_back(c, r);
    }
  }
  if (d > 1) {
    AddSpacePattern(m, pairs);
  } else {
    AddLinePattern(m, pairs);
  }
  AddJunctionPattern(m, pairs);
  if (m.skeleton) AddSkeletonPattern(m, pairs);
  // udot depends on u alone (and t), or on a controller's columns too
  for (const Activation& a : m.activations) pairs.emplace_back(a.state, a.state);
  AddControlPattern(m, pairs);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  m.pattern.size = StateSize(m);
  m.pattern.column_starts.assign(static_cast<std::size_t>(m.pattern.size) + 1, 0);
  for (const auto& [c, r] : pairs) {
    m.pattern.rows.push_back(r);
    ++m.pattern.column_starts[static_cast<std::size_t>(c) + 1];
    m.pattern.lower_bandwidth = std::max(m.pattern.lower_bandwidth, r - c);
    m.pattern.upper_bandwidth = std::max(m.pattern.upper_bandwidth, c - r);
  }
  std::partial_sum(m.pattern.column_starts.begin(), m.pattern.column_starts.end(),
                   m.pattern.column_starts.begin());
  const auto slot = [&](int r, int c) {
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(c, r));
    return static_cast<int>(it - pairs.begin());
  };

  for (FreeNode& node : m.free_nodes) {
    if (node.massless) continue;
    const int s = m.ends[node.node].state;
    for (int r = 0; r < d; ++r) {
      node.slot_rate[r] = slot(s + r, s + d + r);
      for (int c = 0; c < d; ++c) node.slot_position[3 * r + c] = slot(s + d + r, s + c);
    }
  }
  // an entry in a velocity row (free node f's last d states, after its d positions) is
  // scaled by 1/m_f; a junction's position row and the activation rows are not
  std::vector<int> row_owner(static_cast<std::size_t>(StateSize(m)), -1);
  for (std::size_t f = 0; f < m.free_nodes.size(); ++f) {
    const int rate = m.ends[m.free_nodes[f].node].rate;
    for (int c = 0; c < d && rate >= 0; ++c) row_owner[rate + c] = static_cast<int>(f);
  }
  m.row_scale.assign(pairs.size(), -1);
  for (std::size_t k = 0; k < pairs.size(); ++k) m.row_scale[k] = row_owner[m.pattern.rows[k]];
  for (Activation& a : m.activations) a.slot = slot(a.state, a.state);
  if (d > 1) {
    FindSpaceSlots(m, slot);
  } else {
    FindLineSlots(m, slot);
  }
  FindJunctionSlots(m, slot);
  FindControlSlots(m, pairs);
}

}  // namespace musclesim::network
