#include "dynamics/network_skeleton.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

#include "dynamics/network_space.h"

namespace musclesim::network {

namespace {

struct KinematicsCache {
  std::uint64_t skeleton = 0;  // Skeleton::id() of the workspace, 0: none yet
  std::vector<double> state;   // the (q, u) of its last Update
  std::optional<SkeletonWorkspace> workspace;
  std::vector<double> tau;
};

KinematicsCache& Cache() {
  thread_local KinematicsCache cache;
  return cache;
}

}  // namespace

SkeletonWorkspace& SkeletonAt(const NetworkModel& m, const double* y) {
  KinematicsCache& cache = Cache();
  const Skeleton& skeleton = *m.skeleton;
  const int n = skeleton.coordinate_count();
  const double* qu = y + m.skeleton_state;
  if (cache.skeleton != skeleton.id()) {
    cache.workspace.emplace(skeleton.NewWorkspace());
    cache.skeleton = skeleton.id();
    cache.state.clear();
  } else if (std::equal(qu, qu + 2 * n, cache.state.begin(), cache.state.end())) {
    return *cache.workspace;
  }
  skeleton.Update(qu, qu + n, *cache.workspace);
  cache.state.assign(qu, qu + 2 * n);
  return *cache.workspace;
}

double BodyPointCoordinate(const NetworkModel& m, int i, int c, const double* y) {
  const SkeletonWorkspace& ws = SkeletonAt(m, y);
  return m.skeleton->PointPosition(m.ends[i].body, m.nodes[i].PositionCoordinates(), ws)[c];
}

double BodyPointRate(const NetworkModel& m, int i, int c, const double* y) {
  const SkeletonWorkspace& ws = SkeletonAt(m, y);
  return m.skeleton->PointVelocity(m.ends[i].body, m.nodes[i].PositionCoordinates(), ws)[c];
}

namespace {

// The body point j of a path is on, and where in the body's frame; false off the bodies.
bool BodyPointOf(const NetworkModel& m, const PathState& path, std::size_t j, int& body,
                 Coordinates& point) {
  if (path.wrap_body[j] >= -1) {
    body = path.wrap_body[j];
    point = path.wrap_point[j];
    return body >= 0;
  }
  const int node = path.node[j];
  if (node < 0 || m.ends[node].body < 0) return false;
  body = m.ends[node].body;
  point = m.nodes[node].PositionCoordinates();
  return true;
}

}  // namespace

void AddPathForce(const NetworkModel& m, const PathState& path, std::size_t j, double tension,
                  SkeletonWorkspace& ws) {
  int body = -1;
  Coordinates point{};
  if (!BodyPointOf(m, path, j, body, point)) return;
  const Point& g = path.geometry.gradient[j];
  m.skeleton->AddForce(body, point, {-tension * g[0], -tension * g[1], -tension * g[2]}, ws);
}

void SkeletonRates(const NetworkModel& m, const double* y, SkeletonWorkspace& ws, double* ydot) {
  const Skeleton& skeleton = *m.skeleton;
  const int n = skeleton.coordinate_count();
  const int s = m.skeleton_state;
  std::vector<double>& tau = Cache().tau;
  tau.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    ydot[s + k] = y[s + n + k];
    tau[k] = -skeleton.coordinate(k).damping * y[s + n + k];
  }
  skeleton.Accelerations(y + s, y + s + n, tau.data(), ws, ydot + s + n);
}

void AddSkeletonPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs) {
  const int n = StateSize(m);
  for (int c = 0; c < n; ++c) {
    for (int r = 0; r < n; ++r) pairs.emplace_back(c, r);
  }
}

void SkeletonJacobian(const NetworkModel& m, double t, const double* y, double* values,
                      NetworkScratch& scratch) {
  const int n = StateSize(m);
  std::vector<double>& shifted = scratch.shifted;
  std::vector<double>& plus = scratch.rate;
  std::vector<double>& minus = scratch.rate_minus;
  shifted.assign(y, y + n);
  plus.resize(static_cast<std::size_t>(n));
  minus.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    // the step of least total error of a central difference: eps^(1/3) relative
    const double h = 6e-6 * std::max(1.0, std::abs(y[j]));
    shifted[j] = y[j] + h;
    SpaceRightHandSide(m, t, shifted.data(), plus.data());
    shifted[j] = y[j] - h;
    SpaceRightHandSide(m, t, shifted.data(), minus.data());
    shifted[j] = y[j];
    const double width = (y[j] + h) - (y[j] - h);  // the step as represented
    for (int i = 0; i < n; ++i) values[j * n + i] = (plus[i] - minus[i]) / width;
  }
}

void PlaceWraps(NetworkModel& m) {
  for (const WrapCylinder& surface : m.skeleton->wraps()) {
    const Point axis = Point(surface.axis[0], surface.axis[1], surface.axis[2]).normalized();
    // the body's x across the axis, or its y where the axis is along x
    Point x = Point::UnitX() - axis.x() * axis;
    if (x.norm() < 1e-6) x = Point::UnitY() - axis.y() * axis;
    x.normalize();
    m.wraps.push_back({{axis[0], axis[1], axis[2]}, {x[0], x[1], x[2]}});
  }
}

void CheckPlanarSkeleton(const NetworkModel& m) {
  if (m.space.dimensions != 2) return;
  const std::vector<WrapCylinder>& wraps = m.skeleton->wraps();
  for (std::size_t w = 0; w < wraps.size(); ++w) {
    const Coordinates& a = wraps[w].axis;
    if (a[0] != 0.0 || a[1] != 0.0) {
      throw ParameterError(
          "wraps[" + std::to_string(w) + "].axis",
          "[" + FormatNumber(a[0]) + ", " + FormatNumber(a[1]) + ", " + FormatNumber(a[2]) + "]",
          "must be along z in 2 dimensions: a path in the x-y plane wraps "
          "over a cylinder across it");
    }
  }
  const std::vector<Joint>& joints = m.skeleton->joints();
  const auto describe = [](const double* v, int n) {
    std::string text = "[";
    for (int i = 0; i < n; ++i) text.append(i ? ", " : "").append(FormatNumber(v[i]));
    return text + "]";
  };
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& joint = joints[j];
    const std::string at = "joints[" + std::to_string(j) + "].";
    for (const auto& [key, frame] :
         {std::pair{"in_parent", &joint.in_parent}, std::pair{"in_child", &joint.in_child}}) {
      const auto& o = frame->orientation;
      if (o[1] != 0.0 || o[2] != 0.0) {
        throw ParameterError(at + key + ".orientation", describe(o.data(), 4),
                             "must turn about z alone in 2 dimensions (x and y 0): the skeleton "
                             "moves in the x-y plane");
      }
    }
    const Coordinates& a = joint.axis;
    const bool along_z = a[0] == 0.0 && a[1] == 0.0;
    if ((joint.kind == JointKind::kRevolute && !along_z) ||
        (joint.kind == JointKind::kPrismatic && a[2] != 0.0)) {
      throw ParameterError(at + "axis", describe(a.data(), 3),
                           joint.kind == JointKind::kRevolute
                               ? "must be along z in 2 dimensions: a revolute joint turns in the "
                                 "x-y plane"
                               : "must lie in the x-y plane in 2 dimensions (z 0)");
    }
  }
}

bool Spans(const NetworkModel& m, int e, int k) {
  const Link& link = m.links[e];
  bool moved = false, still = false;
  for (int p = link.path_begin; p < link.path_end; ++p) {
    const PathPoint& point = m.path_points[p];
    const int body = point.wrap >= 0   ? m.skeleton->WrapBody(point.wrap)
                     : point.node >= 0 ? m.ends[point.node].body
                                       : -1;
    (m.skeleton->Moves(body, k) ? moved : still) = true;
  }
  return moved && still;
}

void ObserveSkeleton(const NetworkModel& m, double t, const double* y, NetworkSample& sample) {
  const Skeleton& skeleton = *m.skeleton;
  const int n = skeleton.coordinate_count();
  const int s = m.skeleton_state;
  sample.coordinates.assign(y + s, y + s + n);
  sample.speeds.assign(y + s + n, y + s + 2 * n);
  sample.moment_arms.assign(m.elements.size() * static_cast<std::size_t>(n), 0.0);
  SkeletonWorkspace& ws = SkeletonAt(m, y);
  std::vector<double> jacobian(3 * static_cast<std::size_t>(n));
  PathState path;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    // r_k = -dl/dq_k = -sum_j G_j . dq_j/dq_k over the path's points on bodies (docs/model.md
    // 15.2)
    MeasureLink(m, static_cast<int>(e), t, y, path);
    for (std::size_t j = 0; j < path.geometry.points(); ++j) {
      int body = -1;
      Coordinates point{};
      if (!BodyPointOf(m, path, j, body, point)) continue;
      skeleton.PointJacobian(body, point, ws, jacobian.data());
      for (int k = 0; k < n; ++k) {
        double along = 0.0;
        for (int c = 0; c < 3; ++c) along += path.geometry.gradient[j][c] * jacobian[c * n + k];
        sample.moment_arms[e * n + k] -= along;
      }
    }
  }
}

}  // namespace musclesim::network
