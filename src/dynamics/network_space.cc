// Networks in the plane and in space (docs/model.md 12): element paths over via points, how
// they are resolved and checked, the right-hand side and what Observe records. The Jacobian
// is space_jacobian.cc's.
#include "dynamics/network_space.h"

#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "dynamics/element_tension.h"
#include "dynamics/network_build.h"
#include "dynamics/network_control.h"
#include "dynamics/network_evaluation.h"
#include "dynamics/network_skeleton.h"
#include "dynamics/wrap_cylinder.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "part_paths.h"

namespace musclesim::network {

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

void AddPath(NetworkModel& m, std::size_t e) {
  const Element& element = m.elements[e];
  Link& link = m.links[e];
  std::size_t points = element.via.size() + 2;
  for (const ViaPoint& via : element.via) points += via.wrap.empty() ? 0 : 1;  // two on it
  if (points > kMaxPathPoints) {
    throw ParameterError(Entry("elements", e, "via"),
                         std::to_string(element.via.size()) + " points",
                         "must hold at most " + std::to_string(kMaxPathPoints - 2) +
                             " points (a wrap surface counts twice)");
  }
  const auto on_path = [&](int node) {
    for (std::size_t p = static_cast<std::size_t>(link.path_begin); p < m.path_points.size(); ++p) {
      if (m.path_points[p].node == node) return true;
    }
    return false;
  };
  link.path_begin = static_cast<int>(m.path_points.size());
  m.path_points.push_back({link.from, {}});
  for (std::size_t v = 0; v < element.via.size(); ++v) {
    const ViaPoint& via = element.via[v];
    const std::string path = ViaEntry(e, v);
    if (!via.wrap.empty()) {
      const int wrap = m.skeleton ? m.skeleton->FindWrap(via.wrap) : -1;
      if (wrap < 0) {
        throw ParameterError(path + ".wrap", via.wrap,
                             m.skeleton ? "names no wrap surface (wraps:)"
                                        : "names a wrap surface, and the network has no bodies");
      }
      if (m.path_points.back().wrap >= 0) {
        throw ParameterError(path + ".wrap", via.wrap,
                             "must follow a point, not another wrap surface: a path wraps over "
                             "one surface between two points");
      }
      m.path_points.push_back({-1, {}, wrap});
      continue;
    }
    if (via.node.empty()) {
      Coordinates position{};
      for (int c = 0; c < m.space.dimensions; ++c) position[c] = via.position[c];
      const PathPoint& before = m.path_points.back().wrap >= 0
                                    ? m.path_points[m.path_points.size() - 2]
                                    : m.path_points.back();
      if (before.node < 0 && before.wrap < 0 && before.position == position) {
        throw ParameterError(path, Describe(position, m.space.dimensions),
                             "must differ from the via point before it: a segment of length 0 "
                             "has no direction");
      }
      m.path_points.push_back({-1, position});
      continue;
    }
    const int node = NodeNamed(m, via.node, path);
    if (on_path(node) || node == link.to) {
      throw ParameterError(path, via.node,
                           "must not be on the element's path twice (as an end or a via point)");
    }
    m.path_points.push_back({node, {}});
  }
  m.path_points.push_back({link.to, {}});
  link.path_end = static_cast<int>(m.path_points.size());
  bool wrapped = false;
  for (int p = link.path_begin; p < link.path_end; ++p) wrapped |= m.path_points[p].wrap >= 0;
  m.wrapped_links.resize(m.elements.size(), false);
  m.wrapped_links[e] = wrapped;
}

void ResolveSpace(NetworkModel& m) {
  for (std::size_t l = 0; l < m.loads.size(); ++l) {
    Coordinates n = m.loads[l].direction;
    for (int c = m.space.dimensions; c < 3; ++c) n[c] = 0.0;
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw ParameterError(Entry("loads", l, "direction"), Describe(n, m.space.dimensions),
                           "must be a finite vector other than zero: the load acts along it");
    }
    for (double& c : n) c /= norm;
    const int node = FindNode(m, m.loads[l].node);  // LoadsByNode resolved it
    for (FreeNode& f : m.free_nodes) {
      if (f.node == node) f.directed.push_back({n, LoadSet({m.loads[l].load})});
    }
  }
}

int SegmentCount(const NetworkModel& m, int e) {
  if (m.space.dimensions == 1) return 1;
  int points = 0;  // a wrap surface's entry is no point of the segments
  for (int p = m.links[e].path_begin; p < m.links[e].path_end; ++p) {
    points += m.path_points[p].wrap < 0 ? 1 : 0;
  }
  return points - 1;
}

double NodeCoordinate(const NetworkModel& m, int i, int c, double t, const double* y) {
  if (c >= m.space.dimensions) return 0.0;
  const End& end = m.ends[i];
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state + c];
    case NodeKind::kFixed: return m.space.dimensions == 1 ? end.position : end.point[c];
    case NodeKind::kPrescribed: {
      const Node& node = m.nodes[end.node];
      return (c == 0 ? node.motion : node.motion_yz[c - 1]).Evaluate(t);
    }
    case NodeKind::kOnBody: return BodyPointCoordinate(m, i, c, y);
  }
  return 0.0;
}

double NodeCoordinateRate(const NetworkModel& m, int i, int c, double t, const double* y) {
  if (c >= m.space.dimensions) return 0.0;
  const End& end = m.ends[i];
  switch (end.kind) {
    case NodeKind::kFree: return y[end.state + m.space.dimensions + c];
    case NodeKind::kFixed: return 0.0;
    case NodeKind::kPrescribed: {
      const Node& node = m.nodes[end.node];
      return (c == 0 ? node.motion : node.motion_yz[c - 1]).Slope(t);
    }
    case NodeKind::kOnBody: return BodyPointRate(m, i, c, y);
  }
  return 0.0;
}

namespace {

// Where path point `point` is and how it moves.
void MeasurePoint(const NetworkModel& m, const PathPoint& point, double t, const double* y,
                  PathState& state, std::size_t j) {
  state.wrap_body[j] = -2;
  state.node[j] = point.node;
  if (point.node < 0) {
    state.position[j] = Point(point.position[0], point.position[1], point.position[2]);
    state.velocity[j].setZero();
    state.state[j] = -1;
    return;
  }
  state.state[j] = m.ends[point.node].state;
  for (int c = 0; c < 3; ++c) {
    state.position[j][c] = NodeCoordinate(m, point.node, c, t, y);
    state.velocity[j][c] = NodeCoordinateRate(m, point.node, c, t, y);
  }
}

// The path of a link with wrap surfaces: its points, each surface adding the two where the
// path touches and leaves it when the straight segment would cross it (docs/model.md 15.3).
void MeasureWrappedLink(const NetworkModel& m, int e, double t, const double* y, PathState& state) {
  const Link& link = m.links[e];
  const Skeleton& skeleton = *m.skeleton;
  const SkeletonWorkspace& ws = SkeletonAt(m, y);
  std::size_t n = 0;
  // the chords' and arcs' lengths of the segments on surfaces, by the index of their first point
  std::array<double, kMaxPathPoints> arc{};
  std::array<bool, kMaxPathPoints> on_surface{};
  bool inside = false;  // a point entered a surface: the run stops, naming the element
  for (int p = link.path_begin; p < link.path_end; ++p) {
    const PathPoint& point = m.path_points[static_cast<std::size_t>(p)];
    if (point.wrap < 0) {
      MeasurePoint(m, point, t, y, state, n++);
      continue;
    }
    // the points before and after it (the one after is measured now, overwritten next)
    MeasurePoint(m, m.path_points[static_cast<std::size_t>(p + 1)], t, y, state, n);
    const int body = skeleton.WrapBody(point.wrap);
    const WrapCylinder& surface = skeleton.wraps()[static_cast<std::size_t>(point.wrap)];
    const PlacedWrap& placed = m.wraps[static_cast<std::size_t>(point.wrap)];
    const auto world = [](const Coordinates& c) { return Point(c[0], c[1], c[2]); };
    PlacedCylinder cylinder{world(skeleton.PointPosition(body, surface.center, ws)),
                            world(skeleton.DirectionInWorld(body, placed.x, ws)),
                            world(skeleton.DirectionInWorld(body, placed.axis, ws)), surface.radius,
                            surface.side};
    const CylinderWrap wrap = WrapOverCylinder(state.position[n - 1], state.position[n], cylinder);
    inside = inside || wrap.inside;
    if (!wrap.wraps) continue;
    for (const Point& tangent : {wrap.t1, wrap.t2}) {
      const Coordinates at{tangent[0], tangent[1], tangent[2]};
      state.position[n] = tangent;
      state.wrap_point[n] = skeleton.PointInBody(body, at, ws);
      state.wrap_body[n] = body;
      const Coordinates v = skeleton.PointVelocity(body, state.wrap_point[n], ws);
      state.velocity[n] = Point(v[0], v[1], v[2]);
      state.state[n] = -1;
      state.node[n] = -1;
      ++n;
    }
    on_surface[n - 2] = true;
    arc[n - 2] = wrap.arc;
  }
  const std::span<const Point> points(state.position.data(), n);
  PathGeometry& g = state.geometry;
  g = MeasurePath(points);
  // on a surface the segment is its arc, and by the envelope theorem the length changes to
  // first order only with the points off it: the chord's part of the gradient goes
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!on_surface[k]) continue;
    g.length += arc[k] - g.segment_length[k];
    g.segment_length[k] = arc[k];
    g.gradient[k] += g.direction[k];
    g.gradient[k + 1] -= g.direction[k];
  }
  // a point inside a surface it wraps over has no path: a length that is not a number stops
  // the run there, NonFiniteCause naming the element, rather than a path through the surface
  if (inside) g.length = std::numeric_limits<double>::quiet_NaN();
  state.length_rate = g.length_rate(std::span<const Point>(state.velocity.data(), n));
}

}  // namespace

void MeasureLink(const NetworkModel& m, int e, double t, const double* y, PathState& state) {
  if (!m.wrapped_links.empty() && m.wrapped_links[static_cast<std::size_t>(e)]) {
    return MeasureWrappedLink(m, e, t, y, state);
  }
  const Link& link = m.links[e];
  const std::size_t n = static_cast<std::size_t>(link.path_end - link.path_begin);
  for (std::size_t j = 0; j < n; ++j) {
    MeasurePoint(m, m.path_points[static_cast<std::size_t>(link.path_begin) + j], t, y, state, j);
  }
  state.geometry = MeasurePath(std::span<const Point>(state.position.data(), n));
  state.length_rate = state.geometry.length_rate(std::span<const Point>(state.velocity.data(), n));
}

double SegmentLength(const NetworkModel& m, int e, int k, double t, const double* y) {
  if (m.space.dimensions == 1) {
    const Link& link = m.links[e];
    return PositionOf(m, m.ends[link.to], t, y) - PositionOf(m, m.ends[link.from], t, y);
  }
  PathState state;
  MeasureLink(m, e, t, y, state);
  if (k < 0) return state.geometry.length;
  if (!m.wrapped_links.empty() && m.wrapped_links[static_cast<std::size_t>(e)]) {
    // segment k between the path's points as given: straight, over a surface or not
    std::vector<int> real;
    for (int p = m.links[e].path_begin; p < m.links[e].path_end; ++p) {
      if (m.path_points[static_cast<std::size_t>(p)].wrap < 0) real.push_back(p);
    }
    PathState ends;
    MeasurePoint(m, m.path_points[static_cast<std::size_t>(real[static_cast<std::size_t>(k)])], t,
                 y, ends, 0);
    MeasurePoint(m, m.path_points[static_cast<std::size_t>(real[static_cast<std::size_t>(k) + 1])],
                 t, y, ends, 1);
    return (ends.position[1] - ends.position[0]).norm();
  }
  return state.geometry.segment_length[static_cast<std::size_t>(k)];
}

double SpaceLengtheningRate(const NetworkModel& m, int e, double t, const double* y) {
  PathState state;
  MeasureLink(m, e, t, y, state);
  return state.length_rate;
}

Coordinates DirectedLoad(const NetworkModel& m, const FreeNode& f, double t, const double* y) {
  Coordinates load{};
  const int s = m.ends[f.node].state;
  for (const DirectedLoads& directed : f.directed) {
    const Coordinates& n = directed.direction;
    double along = 0.0;  // the node's position along the direction
    for (int c = 0; c < m.space.dimensions; ++c) along += n[c] * y[s + c];
    const double force = directed.loads.Force(t, along);
    for (int c = 0; c < 3; ++c) load[c] += force * n[c];
  }
  return load;
}

namespace {

// A path over wrap surfaces at the start: its points apart, and the points on either side of
// each surface outside it (inside it the path has no tangent to leave by).
void CheckWrappedPath(const NetworkModel& m, int e, double t, const double* y) {
  const Link& link = m.links[e];
  const std::size_t element = static_cast<std::size_t>(e);
  for (int k = 0; k < SegmentCount(m, e); ++k) {
    const double length = SegmentLength(m, e, k, t, y);
    if (length > kMinSegmentLength) continue;
    throw ParameterError("elements[" + std::to_string(e) + "]", m.elements[element].name,
                         "its segment " + std::to_string(k) + " is " + FormatNumber(length) +
                             " m long at the start: a segment must be longer than " +
                             FormatNumber(kMinSegmentLength) + " m");
  }
  const Skeleton& skeleton = *m.skeleton;
  const SkeletonWorkspace& ws = SkeletonAt(m, y);
  std::size_t via = 0;
  for (int p = link.path_begin + 1; p + 1 < link.path_end; ++p, ++via) {
    const PathPoint& point = m.path_points[static_cast<std::size_t>(p)];
    if (point.wrap < 0) continue;
    const WrapCylinder& surface = skeleton.wraps()[static_cast<std::size_t>(point.wrap)];
    const int body = skeleton.WrapBody(point.wrap);
    const PlacedWrap& placed = m.wraps[static_cast<std::size_t>(point.wrap)];
    const auto world = [](const Coordinates& c) { return Point(c[0], c[1], c[2]); };
    const PlacedCylinder cylinder{world(skeleton.PointPosition(body, surface.center, ws)),
                                  world(skeleton.DirectionInWorld(body, placed.x, ws)),
                                  world(skeleton.DirectionInWorld(body, placed.axis, ws)),
                                  surface.radius, surface.side};
    for (const int neighbour : {p - 1, p + 1}) {
      PathState state;
      MeasurePoint(m, m.path_points[static_cast<std::size_t>(neighbour)], t, y, state, 0);
      const double distance = DistanceFromAxis(state.position[0], cylinder);
      if (distance > surface.radius) continue;
      throw ParameterError(ViaEntry(element, via) + ".wrap", surface.name,
                           "the path's point " + std::string(neighbour < p ? "before" : "after") +
                               " it is " + FormatNumber(distance) +
                               " m from the cylinder's axis at the start, inside its radius " +
                               FormatNumber(surface.radius) +
                               " m: a path's points lie outside the surfaces it wraps over");
    }
  }
}

}  // namespace

void CheckInitialPaths(const NetworkModel& m, double t, const double* y) {
  const int d = m.space.dimensions;
  const auto name = [&](const PathPoint& p) {
    return p.node >= 0 ? m.nodes[p.node].name : "the via point " + Describe(p.position, d);
  };
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Link& link = m.links[e];
    if (!m.wrapped_links.empty() && m.wrapped_links[e]) {
      CheckWrappedPath(m, static_cast<int>(e), t, y);
      continue;
    }
    for (int k = 0; k + 1 < link.path_end - link.path_begin; ++k) {
      const double length = SegmentLength(m, static_cast<int>(e), k, t, y);
      if (length > kMinSegmentLength) continue;
      const PathPoint& a = m.path_points[static_cast<std::size_t>(link.path_begin + k)];
      const PathPoint& b = m.path_points[static_cast<std::size_t>(link.path_begin + k + 1)];
      // blame the via point of the segment (the later one), or the element if it has none
      const bool via_b = k + 2 < link.path_end - link.path_begin;
      const std::string path = via_b   ? ViaEntry(e, static_cast<std::size_t>(k))
                               : k > 0 ? ViaEntry(e, static_cast<std::size_t>(k - 1))
                                       : "elements[" + std::to_string(e) + "]";
      throw ParameterError(path, m.elements[e].name,
                           "its segment from " + name(a) + " to " + name(b) + " is " +
                               FormatNumber(length) + " m long at the start: a segment must be " +
                               "longer than " + FormatNumber(kMinSegmentLength) +
                               " m, or its direction is undefined");
    }
  }
}

void SpaceRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot) {
  const int d = m.space.dimensions;
  SkeletonWorkspace* bodies = m.skeleton ? &SkeletonAt(m, y) : nullptr;
  if (bodies != nullptr) m.skeleton->ClearForces(*bodies);
  for (const FreeNode& f : m.free_nodes) {
    const int s = m.ends[f.node].state;
    const Coordinates load = DirectedLoad(m, f, t, y);
    const double mass = m.nodes[f.node].mass;
    for (int c = 0; c < d; ++c) {
      ydot[s + c] = y[s + d + c];
      ydot[s + d + c] = load[c] + mass * m.space.gravity[c];
    }
  }
  PathState path;
  for (const int e : m.active_links) {
    MeasureLink(m, e, t, y, path);
    const double tension = TensionOf(m, e, t, path.geometry.length, path.length_rate, y).value;
    // F_j = -T G_j on every point of the path (a fixed one absorbs it)
    for (std::size_t j = 0; j < path.geometry.points(); ++j) {
      if (path.state[j] < 0) {
        if (bodies != nullptr) AddPathForce(m, path, j, tension, *bodies);
        continue;
      }
      for (int c = 0; c < d; ++c)
        ydot[path.state[j] + d + c] -= tension * path.geometry.gradient[j][c];
    }
  }
  for (const FreeNode& f : m.free_nodes) {
    const int s = m.ends[f.node].state;
    for (int c = 0; c < d; ++c) ydot[s + d + c] *= f.inverse_mass;
  }
  for (const Activation& a : m.activations) {
    const ExcitationInput& input = *m.elements[a.element].excitation;
    ydot[a.state] =
        EvaluateActivationRate(input.dynamics, ExcitationOf(m, a.element, t, y), y[a.state]).value;
  }
  if (bodies != nullptr) SkeletonRates(m, y, *bodies, ydot);
  ControlRightHandSide(m, t, y, ydot);
}

void ObserveSpace(const NetworkModel& m, double t, const double* y, NetworkSample& sample) {
  const int d = m.space.dimensions;
  const std::size_t values = m.nodes.size() * static_cast<std::size_t>(d);
  sample.position.resize(values);
  sample.velocity.resize(values);
  sample.load.assign(values, 0.0);
  sample.elements.resize(m.elements.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    for (int c = 0; c < d; ++c) {
      sample.position[i * d + c] = NodeCoordinate(m, static_cast<int>(i), c, t, y);
      sample.velocity[i * d + c] = NodeCoordinateRate(m, static_cast<int>(i), c, t, y);
    }
  }
  for (const FreeNode& f : m.free_nodes) {
    const Coordinates load = DirectedLoad(m, f, t, y);
    for (int c = 0; c < d; ++c) sample.load[static_cast<std::size_t>(f.node) * d + c] = load[c];
  }
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    ObserveElement(m, static_cast<int>(e), t, y, sample.elements[e]);
  }
  if (m.skeleton) ObserveSkeleton(m, t, y, sample);
  ObserveControllers(m, t, y, sample);
}

}  // namespace musclesim::network
