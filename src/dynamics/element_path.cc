#include "dynamics/element_path.h"

#include <algorithm>
#include <limits>

namespace musclesim {

double PathGeometry::shortest_segment() const {
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < segments(); ++k) shortest = std::min(shortest, segment_length[k]);
  return shortest;
}

double PathGeometry::length_rate(std::span<const Point> velocities) const {
  double rate = 0.0;
  for (std::size_t j = 0; j < count; ++j) rate += gradient[j].dot(velocities[j]);
  return rate;
}

Eigen::Matrix3d PathGeometry::hessian(std::size_t j, std::size_t k) const {
  // segment s joins points s and s + 1; its block P_s / L_s, P_s = I - e_s e_s^T, enters
  // with + on the diagonal of both its points and - between them
  const auto block = [&](std::size_t s) -> Eigen::Matrix3d {
    return (Eigen::Matrix3d::Identity() - direction[s] * direction[s].transpose()) /
           segment_length[s];
  };
  const std::size_t segments = this->segments();
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  if (j == k) {
    if (j > 0) h += block(j - 1);
    if (j < segments) h += block(j);
  } else if (k == j + 1) {
    h -= block(j);
  } else if (j == k + 1) {
    h -= block(k);
  }
  return h;
}

PathGeometry MeasurePath(std::span<const Point> points) {
  PathGeometry path;
  path.count = points.size();
  const std::size_t segments = points.size() - 1;
  for (std::size_t j = 0; j < path.count; ++j) path.gradient[j].setZero();
  for (std::size_t k = 0; k < segments; ++k) {
    const Point s = points[k + 1] - points[k];
    path.segment_length[k] = s.norm();
    path.direction[k] = s / path.segment_length[k];
    path.length += path.segment_length[k];
    // G_0 = -e_0, G_(m+1) = e_m, G_j = e_(j-1) - e_j inside
    path.gradient[k] -= path.direction[k];
    path.gradient[k + 1] += path.direction[k];
  }
  return path;
}

std::array<Point, kMaxPathPoints> RateGradient(const PathGeometry& path,
                                               std::span<const Point> velocities) {
  // H is symmetric (H_ik = H_ki^T) and nonzero for |i - k| <= 1 only
  const std::size_t n = path.points();
  std::array<Point, kMaxPathPoints> rate_gradient;
  for (std::size_t k = 0; k < n; ++k) {
    rate_gradient[k].setZero();
    for (std::size_t i = (k == 0 ? 0 : k - 1); i <= std::min(k + 1, n - 1); ++i) {
      rate_gradient[k] += path.hessian(i, k).transpose() * velocities[i];
    }
  }
  return rate_gradient;
}

Eigen::Matrix3d PositionBlock(const PathGeometry& path, std::span<const Point> rate_gradient,
                              const PathTension& tension, std::size_t j, std::size_t k) {
  return -tension.d_length * path.gradient[j] * path.gradient[k].transpose() -
         tension.d_rate * path.gradient[j] * rate_gradient[k].transpose() -
         tension.tension * path.hessian(j, k);
}

Eigen::Matrix3d VelocityBlock(const PathGeometry& path, const PathTension& tension, std::size_t j,
                              std::size_t k) {
  return -tension.d_rate * path.gradient[j] * path.gradient[k].transpose();
}

PathForceJacobian ForceJacobian(const PathGeometry& path, std::span<const Point> velocities,
                                const PathTension& tension) {
  const std::size_t n = path.points();
  PathForceJacobian jacobian;
  jacobian.points = n;
  const std::array<Point, kMaxPathPoints> rate_gradient = RateGradient(path, velocities);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t k = 0; k < n; ++k) {
      jacobian.d_position.push_back(
          PositionBlock(path, std::span(rate_gradient.data(), n), tension, j, k));
      jacobian.d_velocity.push_back(VelocityBlock(path, tension, j, k));
    }
  }
  return jacobian;
}

}  // namespace musclesim
