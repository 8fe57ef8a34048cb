#include "dynamics/element_path.h"

#include <algorithm>
#include <limits>

namespace musclesim {

double PathGeometry::shortest_segment() const {
  return segment_length.empty() ? std::numeric_limits<double>::infinity()
                                : *std::min_element(segment_length.begin(), segment_length.end());
}

double PathGeometry::length_rate(std::span<const Point> velocities) const {
  double rate = 0.0;
  for (std::size_t j = 0; j < gradient.size(); ++j) rate += gradient[j].dot(velocities[j]);
  return rate;
}

Eigen::Matrix3d PathGeometry::hessian(std::size_t j, std::size_t k) const {
  // segment s joins points s and s + 1; its block P_s / L_s, P_s = I - e_s e_s^T, enters
  // with + on the diagonal of both its points and - between them
  const auto block = [&](std::size_t s) -> Eigen::Matrix3d {
    return (Eigen::Matrix3d::Identity() - direction[s] * direction[s].transpose()) /
           segment_length[s];
  };
  const std::size_t segments = segment_length.size();
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
  const std::size_t segments = points.size() - 1;
  path.segment_length.resize(segments);
  path.direction.resize(segments);
  path.gradient.assign(points.size(), Point::Zero());
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

PathForceJacobian ForceJacobian(const PathGeometry& path, std::span<const Point> velocities,
                                const PathTension& tension) {
  const std::size_t n = path.points();
  PathForceJacobian jacobian;
  jacobian.points = n;
  jacobian.d_position.assign(n * n, Eigen::Matrix3d::Zero());
  jacobian.d_velocity.assign(n * n, Eigen::Matrix3d::Zero());
  // d ldot / dq_k = sum_i qdot_i^T H_ik (H is symmetric: H_ik = H_ki^T)
  std::vector<Point> rate_gradient(n, Point::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t i = (k == 0 ? 0 : k - 1); i <= std::min(k + 1, n - 1); ++i) {
      rate_gradient[k] += path.hessian(i, k).transpose() * velocities[i];
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Matrix3d outer = path.gradient[j] * path.gradient[k].transpose();
      jacobian.d_position[j * n + k] =
          -tension.d_length * outer -
          tension.d_rate * path.gradient[j] * rate_gradient[k].transpose() -
          tension.tension * path.hessian(j, k);
      jacobian.d_velocity[j * n + k] = -tension.d_rate * outer;
    }
  }
  return jacobian;
}

}  // namespace musclesim
