// Private: the geometry of an element's path in the plane or in space (docs/model.md 12.1,
// 12.2, 12.4): the ordered points q_0 = p_a, q_1 .. q_m (via points), q_(m+1) = p_b, joined
// by straight segments. Its length, the gradient G_j = dl/dq_j that turns the tension into
// forces F_j = -T G_j on the points, and the Jacobian of those forces with its geometric
// stiffness (the term that makes a taut cable resist sideways motion).
//
// Points are 3-vectors whatever the network's dimension: a planar network has z = 0
// throughout, so every quantity's z part is zero and its x-y block is the planar one.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace musclesim {

using Point = Eigen::Vector3d;

// The most points a path may have: its two ends and up to 14 via points. A fixed capacity,
// so that measuring a path allocates nothing in the right-hand side.
constexpr std::size_t kMaxPathPoints = 16;

// The segments of one path at one instant.
struct PathGeometry {
  std::size_t count = 0;                                  // points, at most kMaxPathPoints
  double length = 0.0;                                    // l = sum_k L_k [m]
  std::array<double, kMaxPathPoints - 1> segment_length;  // L_k = |q_(k+1) - q_k| [m]
  std::array<Point, kMaxPathPoints - 1> direction;        // e_k, the unit vector of segment k
  std::array<Point, kMaxPathPoints> gradient;             // G_j = dl/dq_j, one per point [-]

  std::size_t points() const { return count; }
  std::size_t segments() const { return count - 1; }
  // The shortest segment: a path whose segment reaches zero length has no direction there.
  double shortest_segment() const;
  // ldot = sum_j G_j . qdot_j [m/s] for the points' velocities.
  double length_rate(std::span<const Point> velocities) const;
  // H_jk = dG_j/dq_k [1/m], the Hessian of l: nonzero for |j - k| <= 1 only.
  Eigen::Matrix3d hessian(std::size_t j, std::size_t k) const;
};

// The geometry of the path through `points` (two to kMaxPathPoints; every segment of nonzero
// length, which the caller ensures: the run stops at a root before a segment closes).
PathGeometry MeasurePath(std::span<const Point> points);

// d ldot / dq_k = sum_i qdot_i^T H_ik for every point k: how the lengthening rate changes
// as the points move (the directions turn).
std::array<Point, kMaxPathPoints> RateGradient(const PathGeometry& path,
                                               std::span<const Point> velocities);

struct PathTension;
// Blocks (j, k) of the Jacobian below, one at a time (no allocation), with `rate_gradient`
// RateGradient's.
Eigen::Matrix3d PositionBlock(const PathGeometry& path, std::span<const Point> rate_gradient,
                              const PathTension& tension, std::size_t j, std::size_t k);
Eigen::Matrix3d VelocityBlock(const PathGeometry& path, const PathTension& tension, std::size_t j,
                              std::size_t k);

// The Jacobian of the forces F_j = -T G_j on the path's points, for a tension T(l, ldot) with
// partial derivatives dT/dl and dT/dldot (docs/model.md 12.4):
//   dF_j/dq_k    = -(dT/dl) G_j G_k^T - (dT/dldot) G_j (sum_i qdot_i^T H_ik) - T H_jk
//   dF_j/dqdot_k = -(dT/dldot) G_j G_k^T
// An element couples all its path points: blocks for every (j, k), row-major.
struct PathForceJacobian {
  std::size_t points = 0;
  std::vector<Eigen::Matrix3d> d_position;  // [N/m], block (j, k) at j * points + k
  std::vector<Eigen::Matrix3d> d_velocity;  // [N s/m]

  const Eigen::Matrix3d& position_block(std::size_t j, std::size_t k) const {
    return d_position[j * points + k];
  }
  const Eigen::Matrix3d& velocity_block(std::size_t j, std::size_t k) const {
    return d_velocity[j * points + k];
  }
};

struct PathTension {
  double tension = 0.0;   // T [N]
  double d_length = 0.0;  // dT/dl [N/m]
  double d_rate = 0.0;    // dT/dldot [N s/m] (the rate of lengthening, -v)
};

// Every block at once (for tests and diagnostics: it allocates).
PathForceJacobian ForceJacobian(const PathGeometry& path, std::span<const Point> velocities,
                                const PathTension& tension);

}  // namespace musclesim
