// A network built: its parts validated, resolved into the right-hand side's ends, links,
// free nodes and kinks, and its Jacobian's pattern and slots found (network.h).
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

namespace {

// ParameterError of a part, its path put under the part's list entry.
template <typename Part>
void ValidateEntry(const Part& part, const char* list, std::size_t i) {
  try {
    Validate(part);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string(list) + "[" + std::to_string(i) + "]." + e.path(), e.value(),
                         e.rule());
  }
}

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

NetworkSystem::NetworkSystem(std::vector<Node> nodes, std::vector<Element> elements,
                             std::vector<NodeLoad> loads, std::vector<Controller> controllers,
                             Space space)
    : nodes_(std::move(nodes)),
      elements_(std::move(elements)),
      loads_(std::move(loads)),
      controllers_(std::move(controllers)),
      space_(space) {
  Validate(space_);
  for (std::size_t i = 0; i < nodes_.size(); ++i) ValidateEntry(nodes_[i], "nodes", i);
  for (std::size_t i = 0; i < elements_.size(); ++i) ValidateEntry(elements_[i], "elements", i);
  for (std::size_t i = 0; i < controllers_.size(); ++i) {
    ValidateEntry(controllers_[i], "controllers", i);
  }
  node_index_ = IndexByName(nodes_, "nodes");
  element_index_ = IndexByName(elements_, "elements");
  controller_index_ = IndexByName(controllers_, "controllers");
  Resolve();
  BuildPattern();
}

namespace {

int Find(const std::unordered_map<std::string, int>& index, std::string_view name) {
  const auto it = index.find(std::string(name));
  return it == index.end() ? -1 : it->second;
}

}  // namespace

int NetworkSystem::FindNode(std::string_view name) const { return Find(node_index_, name); }

int NetworkSystem::FindElement(std::string_view name) const { return Find(element_index_, name); }

int NetworkSystem::FindController(std::string_view name) const {
  return Find(controller_index_, name);
}

void NetworkSystem::Resolve() {
  int states = NumberEnds();
  for (std::size_t e = 0; e < elements_.size(); ++e) AddLink(e, states);
  Components joined(nodes_.size());
  for (const Link& link : links_) {
    joined.Join(static_cast<std::size_t>(link.from), static_cast<std::size_t>(link.to));
    // a via node is on the path: the element's tension acts on it too
    for (int p = link.path_begin; p < link.path_end; ++p) {
      if (path_points_[p].node >= 0) {
        joined.Join(static_cast<std::size_t>(link.from),
                    static_cast<std::size_t>(path_points_[p].node));
      }
    }
  }
  std::vector<std::vector<Load>> node_loads = LoadsByNode();
  AddFreeNodes(std::move(node_loads), AnchoredNodes(nodes_, joined));
  if (space_.dimensions > 1) ResolveSpace();
  ResolveControllers(states);
  ResolveJunctions();
  FindSingleNode();
}

int NetworkSystem::NodeNamed(const std::string& name, const std::string& path) const {
  const int i = FindNode(name);
  if (i < 0) {
    throw ParameterError(path, name, "names no node; the nodes are: " + KnownNames(nodes_));
  }
  return i;
}

int NetworkSystem::NumberEnds() {
  int states = 0, free = 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& node = nodes_[i];
    End end{node.kind, -1, node.position, static_cast<int>(ends_.size()),
            node.PositionCoordinates()};
    if (node.kind == NodeKind::kFree) {
      end.state = states;
      end.free = free++;
      if (node.mass > 0.0) {
        end.rate = states + space_.dimensions;
        states += 2 * space_.dimensions;  // d coordinates, d velocities
      } else if (space_.dimensions > 1) {
        throw ParameterError(Entry("nodes", i, "mass"), "0",
                             "a massless junction (mass 0) needs dimensions 1: in the plane "
                             "and in space every free node needs a mass > 0");
      } else {
        states += 1;  // a junction's position; its velocity solves its balance
      }
    }
    ends_.push_back(end);
  }
  node_states_ = states;
  return states;
}

void NetworkSystem::AddLink(std::size_t e, int& states) {
  const Element& element = elements_[e];
  Link link{NodeNamed(element.from, Entry("elements", e, "from")),
            NodeNamed(element.to, Entry("elements", e, "to")),
            {},
            -1,
            {-1, -1}};
  if (link.from == link.to) {
    throw ParameterError(Entry("elements", e, "to"), element.to,
                         "must differ from `from`: an element joins two nodes");
  }
  if (space_.dimensions == 1 && !element.via.empty()) {
    throw ParameterError(Entry("elements", e, "via"),
                         std::to_string(element.via.size()) + " points",
                         "via points need dimensions 2 or 3: on a line an element is straight");
  }
  if (element.kind == ElementKind::kActuator && element.excitation) {
    // after every node's states (the nodes were numbered first)
    link.activation = states++;
    activations_.push_back({static_cast<int>(e), link.activation, -1});
    if (HasExcitationKink(element.excitation->dynamics)) {
      kinks_.push_back({Kink::kExcitation, static_cast<int>(e), 0.0});
    }
  }
  links_.push_back(link);
  if (space_.dimensions > 1) AddPath(e);
  const bool inert = (element.kind == ElementKind::kDamper && element.damping == 0.0) ||
                     (element.kind == ElementKind::kSpring && element.stiffness == 0.0);
  if (!inert) active_links_.push_back(static_cast<int>(e));
  if (element.kind == ElementKind::kTendon && !element.pushes_below_slack) {
    kinks_.push_back({Kink::kLength, static_cast<int>(e), element.slack_length});
  } else if (element.kind == ElementKind::kActuator) {
    if (const std::optional<double> kink = element.model->LengthKink()) {
      kinks_.push_back({Kink::kLength, static_cast<int>(e), *kink});
    }
  }
  if (element.kind == ElementKind::kActuator && element.model->HasVelocityKink()) {
    kinks_.push_back({Kink::kLengtheningRate, static_cast<int>(e), 0.0});  // v = 0
  }
}

std::vector<std::vector<Load>> NetworkSystem::LoadsByNode() const {
  std::vector<std::vector<Load>> node_loads(nodes_.size());
  for (std::size_t l = 0; l < loads_.size(); ++l) {
    const int node = NodeNamed(loads_[l].node, Entry("loads", l, "node"));
    if (nodes_[node].kind != NodeKind::kFree) {
      throw ParameterError(Entry("loads", l, "node"), loads_[l].node,
                           "must name a free node (one with a mass); it is " +
                               std::string(ToString(nodes_[node].kind)));
    }
    try {
      Validate(loads_[l].load);
    } catch (const ParameterError& e) {
      throw ParameterError("loads[" + std::to_string(l) + "]." + e.path(), e.value(), e.rule());
    }
    if (nodes_[node].mass == 0.0 && loads_[l].load.kind == LoadKind::kMass) {
      throw ParameterError(Entry("loads", l, "type"), "mass",
                           "a massless junction (node " + loads_[l].node +
                               ", mass 0) carries no mass load: give the node the load's mass "
                               "instead");
    }
    node_loads[node].push_back(loads_[l].load);
  }
  return node_loads;
}

void NetworkSystem::AddFreeNodes(std::vector<std::vector<Load>> node_loads,
                                 const std::vector<bool>& anchored) {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].kind != NodeKind::kFree) continue;
    if (!anchored[i]) {
      throw ParameterError(Entry("nodes", i, "name"), nodes_[i].name,
                           "floats: no chain of elements joins this free node to a fixed or "
                           "prescribed node");
    }
    LoadSet set(std::move(node_loads[i]));
    const bool massless = nodes_[i].mass == 0.0;  // (LoadsByNode refused its mass loads)
    const double inverse_mass = massless ? 0.0 : 1.0 / (nodes_[i].mass + set.AddedMass());
    free_nodes_.push_back(
        {static_cast<int>(i), std::move(set), inverse_mass, {}, {}, {}, massless});
  }
  // without a free node the activations can still be the state: a muscle whose length is
  // prescribed (a rigid tendon, an isokinetic stretch) under its activation dynamics
  if (free_nodes_.empty() && activations_.empty()) {
    throw ParameterError("nodes", std::to_string(nodes_.size()) + " nodes",
                         "need at least one free node (one with a mass) or an actuator with "
                         "activation dynamics: the state is their positions and activations");
  }
}

void NetworkSystem::FindSingleNode() {
  if (space_.dimensions > 1 || free_nodes_.size() != 1 || !activations_.empty() ||
      !controllers_.empty() || !junctions_.empty())
    return;
  const int free = free_nodes_.front().node;
  for (const int e : active_links_) {
    const Link& link = links_[e];
    const int other = link.to == free ? link.from : link.to;
    if (ends_[other].kind != NodeKind::kFixed) return;
    anchored_.push_back({e, ends_[other].position, link.to == free ? 1 : -1});
  }
  single_node_ = true;
}

void NetworkSystem::AddLinePattern(std::vector<std::pair<int, int>>& pairs) const {
  for (const Link& link : links_) {
    // rows: the ends' accelerations; columns: their positions and velocities (a junction
    // has neither row nor velocity column: AddJunctionPattern adds what goes through w)
    for (int row_end : {link.from, link.to}) {
      for (int col_end : {link.from, link.to}) {
        const int r = ends_[row_end].rate;
        if (r < 0) continue;
        if (ends_[col_end].state >= 0) pairs.emplace_back(ends_[col_end].state, r);
        if (ends_[col_end].rate >= 0) pairs.emplace_back(ends_[col_end].rate, r);
      }
    }
    // the tension's u: in both ends' acceleration rows
    for (int row_end : {link.from, link.to}) {
      const int r = ends_[row_end].rate;
      if (link.activation >= 0 && r >= 0) pairs.emplace_back(link.activation, r);
    }
  }
}

void NetworkSystem::FindLineSlots(const std::function<int(int, int)>& slot) {
  for (Link& link : links_) {
    const int ends[2] = {link.from, link.to};
    for (int r = 0; r < 2; ++r) {
      const int row = ends_[ends[r]].rate;
      for (int c = 0; c < 2; ++c) {
        const int position = ends_[ends[c]].state, rate = ends_[ends[c]].rate;
        link.slot[r][2 * c] = row >= 0 && position >= 0 ? slot(row, position) : -1;
        link.slot[r][2 * c + 1] = row >= 0 && rate >= 0 ? slot(row, rate) : -1;
      }
      link.slot_activation[r] = link.activation >= 0 && row >= 0 ? slot(row, link.activation) : -1;
    }
  }
}

void NetworkSystem::BuildPattern() {
  // every (row, column) pair that can be nonzero, then compressed-column order
  std::vector<std::pair<int, int>> pairs;  // (column, row)
  const int d = space_.dimensions;
  for (const FreeNode& f : free_nodes_) {
    const int s = ends_[f.node].state;
    const int n = f.massless ? 1 : 2 * d;  // a junction: its position alone
    for (int r = s; r < s + n; ++r) {
      for (int c = s; c < s + n; ++c) pairs.emplace_back(c, r);
    }
  }
  if (d > 1) {
    AddSpacePattern(pairs);
  } else {
    AddLinePattern(pairs);
  }
  AddJunctionPattern(pairs);
  // udot depends on u alone (and t), or on a controller's columns too
  for (const Activation& a : activations_) pairs.emplace_back(a.state, a.state);
  AddControlPattern(pairs);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  pattern_.size = state_size();
  pattern_.column_starts.assign(static_cast<std::size_t>(pattern_.size) + 1, 0);
  for (const auto& [c, r] : pairs) {
    pattern_.rows.push_back(r);
    ++pattern_.column_starts[static_cast<std::size_t>(c) + 1];
    pattern_.lower_bandwidth = std::max(pattern_.lower_bandwidth, r - c);
    pattern_.upper_bandwidth = std::max(pattern_.upper_bandwidth, c - r);
  }
  std::partial_sum(pattern_.column_starts.begin(), pattern_.column_starts.end(),
                   pattern_.column_starts.begin());
  const auto slot = [&](int r, int c) {
    const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(c, r));
    return static_cast<int>(it - pairs.begin());
  };

  for (FreeNode& node : free_nodes_) {
    if (node.massless) continue;
    const int s = ends_[node.node].state;
    for (int r = 0; r < d; ++r) {
      node.slot_rate[r] = slot(s + r, s + d + r);
      for (int c = 0; c < d; ++c) node.slot_position[3 * r + c] = slot(s + d + r, s + c);
    }
  }
  // an entry in a velocity row (free node f's last d states, after its d positions) is
  // scaled by 1/m_f; a junction's position row and the activation rows are not
  std::vector<int> row_owner(static_cast<std::size_t>(state_size()), -1);
  for (std::size_t f = 0; f < free_nodes_.size(); ++f) {
    const int rate = ends_[free_nodes_[f].node].rate;
    for (int c = 0; c < d && rate >= 0; ++c) row_owner[rate + c] = static_cast<int>(f);
  }
  row_scale_.assign(pairs.size(), -1);
  for (std::size_t k = 0; k < pairs.size(); ++k) row_scale_[k] = row_owner[pattern_.rows[k]];
  for (Activation& a : activations_) a.slot = slot(a.state, a.state);
  if (d > 1) {
    FindSpaceSlots(slot);
  } else {
    FindLineSlots(slot);
  }
  FindJunctionSlots(slot);
  FindControlSlots(pairs);
}

}  // namespace musclesim
