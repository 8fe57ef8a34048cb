// Networks in the plane and in space (docs/model.md 12): element paths over via points, how
// they are resolved and checked, the right-hand side and what Observe records. The Jacobian
// is space_jacobian.cc's.
#include "dynamics/network_space.h"

#include <cmath>
#include <span>
#include <string>

#include "dynamics/element_tension.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "part_paths.h"

namespace musclesim {

namespace {

// "elements[2].via[1]", built by appending (GCC 12 warns falsely on "[" + std::to_string(i)).
std::string ViaEntry(std::size_t e, std::size_t v) {
  std::string path = Entry("elements", e, "via");
  path.append("[").append(std::to_string(v)).append("]");
  return path;
}

std::string Describe(const Coordinates& c, int dimensions) {
  std::string text = "(";
  for (int k = 0; k < dimensions; ++k) text.append(k ? ", " : "").append(FormatNumber(c[k]));
  return text + ")";
}

}  // namespace

void NetworkSystem::AddPath(std::size_t e) {
  const Element& element = elements_[e];
  Link& link = links_[e];
  if (element.via.size() + 2 > kMaxPathPoints) {
    throw ParameterError(Entry("elements", e, "via"),
                         std::to_string(element.via.size()) + " points",
                         "must hold at most " + std::to_string(kMaxPathPoints - 2) + " points");
  }
  const auto on_path = [&](int node) {
    for (std::size_t p = static_cast<std::size_t>(link.path_begin); p < path_points_.size(); ++p) {
      if (path_points_[p].node == node) return true;
    }
    return false;
  };
  link.path_begin = static_cast<int>(path_points_.size());
  path_points_.push_back({link.from, {}});
  for (std::size_t v = 0; v < element.via.size(); ++v) {
    const ViaPoint& via = element.via[v];
    const std::string path = ViaEntry(e, v);
    if (via.node.empty()) {
      Coordinates position{};
      for (int c = 0; c < space_.dimensions; ++c) position[c] = via.position[c];
      const PathPoint& before = path_points_.back();
      if (before.node < 0 && before.position == position) {
        throw ParameterError(path, Describe(position, space_.dimensions),
                             "must differ from the via point before it: a segment of length 0 "
                             "has no direction");
      }
      path_points_.push_back({-1, position});
      continue;
    }
    const int node = NodeNamed(via.node, path);
    if (on_path(node) || node == link.to) {
      throw ParameterError(path, via.node,
                           "must not be on the element's path twice (as an end or a via point)");
    }
    path_points_.push_back({node, {}});
  }
  path_points_.push_back({link.to, {}});
  link.path_end = static_cast<int>(path_points_.size());
}

void NetworkSystem::ResolveSpace() {
  for (std::size_t l = 0; l < loads_.size(); ++l) {
    Coordinates n = loads_[l].direction;
    for (int c = space_.dimensions; c < 3; ++c) n[c] = 0.0;
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw ParameterError(Entry("loads", l, "direction"), Describe(n, space_.dimensions),
                           "must be a finite vector other than zero: the load acts along it");
    }
    for (double& c : n) c /= norm;
    const int node = FindNode(loads_[l].node);  // LoadsByNode resolved it
    for (FreeNode& f : free_nodes_) {
      if (f.node == node) f.directed.push_back({n, LoadSet({loads_[l].load})});
    }
  }
}

int NetworkSystem::SegmentCount(int e) const {
  if (space_.dimensions == 1) return 1;
  return links_[e].path_end - links_[e].path_begin - 1;
}

double NetworkSystem::NodeCoordinate(int i, int c, double t, const double* y) const {
  if (c >= space_.dimensions) return 0.0;
  const End& end = ends_[i];
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state + c];
    case NodeKind::kFixed: return space_.dimensions == 1 ? end.position : end.point[c];
    case NodeKind::kPrescribed: {
      const Node& node = nodes_[end.node];
      return (c == 0 ? node.motion : node.motion_yz[c - 1]).Evaluate(t);
    }
  }
  return 0.0;
}

double NetworkSystem::NodeCoordinateRate(int i, int c, double t, const double* y) const {
  if (c >= space_.dimensions) return 0.0;
  const End& end = ends_[i];
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state + space_.dimensions + c];
    case NodeKind::kFixed: return 0.0;
    case NodeKind::kPrescribed: {
      const Node& node = nodes_[end.node];
      return (c == 0 ? node.motion : node.motion_yz[c - 1]).Slope(t);
    }
  }
  return 0.0;
}

void NetworkSystem::MeasureLink(int e, double t, const double* y, PathState& state) const {
  const Link& link = links_[e];
  const std::size_t n = static_cast<std::size_t>(link.path_end - link.path_begin);
  for (std::size_t j = 0; j < n; ++j) {
    const PathPoint& point = path_points_[static_cast<std::size_t>(link.path_begin) + j];
    if (point.node < 0) {
      state.position[j] = Point(point.position[0], point.position[1], point.position[2]);
      state.velocity[j].setZero();
      state.state[j] = -1;
      continue;
    }
    state.state[j] = ends_[point.node].state;
    for (int c = 0; c < 3; ++c) {
      state.position[j][c] = NodeCoordinate(point.node, c, t, y);
      state.velocity[j][c] = NodeCoordinateRate(point.node, c, t, y);
    }
  }
  state.geometry = MeasurePath(std::span<const Point>(state.position.data(), n));
  state.length_rate = state.geometry.length_rate(std::span<const Point>(state.velocity.data(), n));
}

double NetworkSystem::SegmentLength(int e, int k, double t, const double* y) const {
  if (space_.dimensions == 1) {
    const Link& link = links_[e];
    return PositionOf(ends_[link.to], t, y) - PositionOf(ends_[link.from], t, y);
  }
  PathState state;
  MeasureLink(e, t, y, state);
  return k < 0 ? state.geometry.length : state.geometry.segment_length[static_cast<std::size_t>(k)];
}

double NetworkSystem::SpaceLengtheningRate(int e, double t, const double* y) const {
  PathState state;
  MeasureLink(e, t, y, state);
  return state.length_rate;
}

Coordinates NetworkSystem::DirectedLoad(const FreeNode& f, double t, const double* y) const {
  Coordinates load{};
  const int s = ends_[f.node].state;
  for (const DirectedLoads& directed : f.directed) {
    const Coordinates& n = directed.direction;
    double along = 0.0;  // the node's position along the direction
    for (int c = 0; c < space_.dimensions; ++c) along += n[c] * y[s + c];
    const double force = directed.loads.Force(t, along);
    for (int c = 0; c < 3; ++c) load[c] += force * n[c];
  }
  return load;
}

void NetworkSystem::CheckInitialPaths(double t, const double* y) const {
  const int d = space_.dimensions;
  const auto name = [&](const PathPoint& p) {
    return p.node >= 0 ? nodes_[p.node].name : "the via point " + Describe(p.position, d);
  };
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Link& link = links_[e];
    for (int k = 0; k + 1 < link.path_end - link.path_begin; ++k) {
      const double length = SegmentLength(static_cast<int>(e), k, t, y);
      if (length > kMinSegmentLength) continue;
      const PathPoint& a = path_points_[static_cast<std::size_t>(link.path_begin + k)];
      const PathPoint& b = path_points_[static_cast<std::size_t>(link.path_begin + k + 1)];
      // blame the via point of the segment (the later one), or the element if it has none
      const bool via_b = k + 2 < link.path_end - link.path_begin;
      const std::string path = via_b   ? ViaEntry(e, static_cast<std::size_t>(k))
                               : k > 0 ? ViaEntry(e, static_cast<std::size_t>(k - 1))
                                       : "elements[" + std::to_string(e) + "]";
      throw ParameterError(path, elements_[e].name,
                           "its segment from " + name(a) + " to " + name(b) + " is " +
                               FormatNumber(length) + " m long at the start: a segment must be " +
                               "longer than " + FormatNumber(kMinSegmentLength) +
                               " m, or its direction is undefined");
    }
  }
}

void NetworkSystem::SpaceRightHandSide(double t, const double* y, double* ydot) const {
  const int d = space_.dimensions;
  for (const FreeNode& f : free_nodes_) {
    const int s = ends_[f.node].state;
    const Coordinates load = DirectedLoad(f, t, y);
    const double mass = nodes_[f.node].mass;
    for (int c = 0; c < d; ++c) {
      ydot[s + c] = y[s + d + c];
      ydot[s + d + c] = load[c] + mass * space_.gravity[c];
    }
  }
  PathState path;
  for (const int e : active_links_) {
    MeasureLink(e, t, y, path);
    const double tension = TensionOf(e, t, path.geometry.length, path.length_rate, y).value;
    // F_j = -T G_j on every point of the path (a fixed one absorbs it)
    for (std::size_t j = 0; j < path.geometry.points(); ++j) {
      if (path.state[j] < 0) continue;
      for (int c = 0; c < d; ++c)
        ydot[path.state[j] + d + c] -= tension * path.geometry.gradient[j][c];
    }
  }
  for (const FreeNode& f : free_nodes_) {
    const int s = ends_[f.node].state;
    for (int c = 0; c < d; ++c) ydot[s + d + c] *= f.inverse_mass;
  }
  for (const Activation& a : activations_) {
    const ExcitationInput& input = *elements_[a.element].excitation;
    ydot[a.state] =
        EvaluateActivationRate(input.dynamics, ExcitationOf(a.element, t, y), y[a.state]).value;
  }
  ControlRightHandSide(t, y, ydot);
}

void NetworkSystem::ObserveSpace(double t, const double* y, NetworkSample& sample) const {
  const int d = space_.dimensions;
  const std::size_t values = nodes_.size() * static_cast<std::size_t>(d);
  sample.position.resize(values);
  sample.velocity.resize(values);
  sample.load.assign(values, 0.0);
  sample.elements.resize(elements_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    for (int c = 0; c < d; ++c) {
      sample.position[i * d + c] = NodeCoordinate(static_cast<int>(i), c, t, y);
      sample.velocity[i * d + c] = NodeCoordinateRate(static_cast<int>(i), c, t, y);
    }
  }
  for (const FreeNode& f : free_nodes_) {
    const Coordinates load = DirectedLoad(f, t, y);
    for (int c = 0; c < d; ++c) sample.load[static_cast<std::size_t>(f.node) * d + c] = load[c];
  }
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    ObserveElement(static_cast<int>(e), t, y, sample.elements[e]);
  }
  ObserveControllers(t, y, sample);
}

}  // namespace musclesim
