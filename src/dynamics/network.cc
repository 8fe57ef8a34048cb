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
  if (d > 1) AddSpacePattern(pairs);
  for (const Link& link : links_) {
    if (d > 1) break;  // AddSpacePattern's
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
  if (d > 1) FindSpaceSlots(slot);
  for (Link& link : links_) {
    if (d > 1) break;  // FindSpaceSlots'

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
  FindJunctionSlots(slot);
  FindControlSlots(pairs);
}

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
