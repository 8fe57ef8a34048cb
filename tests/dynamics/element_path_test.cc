// The geometry of an element's path (docs/model.md 12.1-12.4) against finite differences of
// its length and of its forces, and against the closed forms of a straight path: the 1-D
// element of section 7.1 and the lateral stiffness T (1/L_0 + 1/L_1) of a taut string.
#include "dynamics/element_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace musclesim {
namespace {

// A path in space from a to b over two via points, and the velocities of its points.
std::vector<Point> Points() {
  return {Point(0.0, 0.0, 0.0), Point(0.11, 0.04, -0.02), Point(0.19, -0.03, 0.05),
          Point(0.32, 0.02, 0.01)};
}
std::vector<Point> Velocities() {
  return {Point(0.1, -0.2, 0.05), Point(-0.3, 0.2, 0.1), Point(0.25, 0.15, -0.2),
          Point(0.05, -0.1, 0.3)};
}

double Length(const std::vector<Point>& q) { return MeasurePath(q).length; }

// The points moved by h along coordinate c of point j.
std::vector<Point> Moved(std::vector<Point> q, std::size_t j, int c, double h) {
  q[j][c] += h;
  return q;
}

TEST(ElementPath, GradientIsTheLengthsFiniteDifference) {
  const auto q = Points();
  const PathGeometry path = MeasurePath(q);
  const double h = 1e-6;
  for (std::size_t j = 0; j < q.size(); ++j) {
    for (int c = 0; c < 3; ++c) {
      const double fd = (Length(Moved(q, j, c, h)) - Length(Moved(q, j, c, -h))) / (2 * h);
      EXPECT_NEAR(path.gradient[j][c], fd, 1e-8) << "point " << j << " coordinate " << c;
    }
  }
}

TEST(ElementPath, HessianIsTheGradientsFiniteDifference) {
  const auto q = Points();
  const PathGeometry path = MeasurePath(q);
  const double h = 1e-6;
  for (std::size_t j = 0; j < q.size(); ++j) {
    for (std::size_t k = 0; k < q.size(); ++k) {
      for (int c = 0; c < 3; ++c) {
        const Point fd = (MeasurePath(Moved(q, k, c, h)).gradient[j] -
                          MeasurePath(Moved(q, k, c, -h)).gradient[j]) /
                         (2 * h);
        for (int r = 0; r < 3; ++r) {
          EXPECT_NEAR(path.hessian(j, k)(r, c), fd[r], 1e-6)
              << "block " << j << "," << k << " entry " << r << "," << c;
        }
      }
    }
  }
}

TEST(ElementPath, LengthRateIsTheLengthsDerivativeAlongTheMotion) {
  const auto q = Points(), qdot = Velocities();
  const double h = 1e-6;
  std::vector<Point> ahead = q, behind = q;
  for (std::size_t j = 0; j < q.size(); ++j) {
    ahead[j] += h * qdot[j];
    behind[j] -= h * qdot[j];
  }
  EXPECT_NEAR(MeasurePath(q).length_rate(qdot), (Length(ahead) - Length(behind)) / (2 * h), 1e-9);
}

// A tension law with every kind of dependence: stiff in l, viscous in ldot, and coupled.
PathTension Law(double l, double ldot) {
  const double l0 = 0.3;
  return {200.0 * (std::exp(8.0 * (l - l0)) - 1.0) + 15.0 * ldot + 40.0 * l * ldot,
          1600.0 * std::exp(8.0 * (l - l0)) + 40.0 * ldot, 15.0 + 40.0 * l};
}

// F_j = -T(l, ldot) G_j for every point.
std::vector<Point> Forces(const std::vector<Point>& q, const std::vector<Point>& qdot) {
  const PathGeometry path = MeasurePath(q);
  const double tension = Law(path.length, path.length_rate(qdot)).tension;
  std::vector<Point> forces;
  for (const Point& g : path.gradient) forces.push_back(-tension * g);
  return forces;
}

TEST(ElementPath, ForceJacobianIsTheForcesFiniteDifference) {
  const auto q = Points(), qdot = Velocities();
  const PathGeometry path = MeasurePath(q);
  const PathForceJacobian jacobian =
      ForceJacobian(path, qdot, Law(path.length, path.length_rate(qdot)));
  const double h = 1e-7;
  for (std::size_t k = 0; k < q.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      const auto ahead = Forces(Moved(q, k, c, h), qdot), behind = Forces(Moved(q, k, c, -h), qdot);
      const auto faster = Forces(q, Moved(qdot, k, c, h)),
                 slower = Forces(q, Moved(qdot, k, c, -h));
      for (std::size_t j = 0; j < q.size(); ++j) {
        const Point by_position = (ahead[j] - behind[j]) / (2 * h);
        const Point by_velocity = (faster[j] - slower[j]) / (2 * h);
        for (int r = 0; r < 3; ++r) {
          EXPECT_NEAR(jacobian.position_block(j, k)(r, c), by_position[r],
                      1e-5 * (1.0 + std::abs(by_position[r])))
              << "dF_" << j << "/dq_" << k << " entry " << r << "," << c;
          EXPECT_NEAR(jacobian.velocity_block(j, k)(r, c), by_velocity[r], 1e-6)
              << "dF_" << j << "/dqdot_" << k << " entry " << r << "," << c;
        }
      }
    }
  }
}

TEST(ElementPath, ForcesDoThePowerMinusTensionTimesLengthRate) {
  const auto q = Points(), qdot = Velocities();
  const PathGeometry path = MeasurePath(q);
  const double ldot = path.length_rate(qdot);
  const auto forces = Forces(q, qdot);
  double power = 0.0;
  for (std::size_t j = 0; j < q.size(); ++j) power += forces[j].dot(qdot[j]);
  EXPECT_NEAR(power, -Law(path.length, ldot).tension * ldot, 1e-12);
}

TEST(ElementPath, OnALineItIsTheElementOfSectionSeven) {
  // x_b > x_a: l = x_b - x_a, +T on a, -T on b, and no sideways stiffness along the line
  const std::vector<Point> q = {Point(0.02, 0, 0), Point(0.17, 0, 0)};
  const PathGeometry path = MeasurePath(q);
  EXPECT_DOUBLE_EQ(path.length, 0.15);
  EXPECT_EQ(path.gradient[0], Point(-1, 0, 0));
  EXPECT_EQ(path.gradient[1], Point(1, 0, 0));
  const PathTension tension{30.0, 900.0, 4.0};
  const std::vector<Point> qdot = {Point(0.1, 0, 0), Point(-0.2, 0, 0)};
  const PathForceJacobian jacobian = ForceJacobian(path, qdot, tension);
  // dF_a/dx_a = -(dT/dl) (-1)(-1); dF_a/dx_b = -(dT/dl)(-1)(+1)
  EXPECT_DOUBLE_EQ(jacobian.position_block(0, 0)(0, 0), -900.0);
  EXPECT_DOUBLE_EQ(jacobian.position_block(0, 1)(0, 0), 900.0);
  EXPECT_DOUBLE_EQ(jacobian.velocity_block(1, 1)(0, 0), -4.0);
  // sideways, the string's geometric stiffness T / L
  EXPECT_DOUBLE_EQ(jacobian.position_block(0, 0)(1, 1), -30.0 / 0.15);
}

TEST(ElementPath, ATautStringResistsSidewaysMotionWithTensionOverEachSegment) {
  // a via point on a straight string, the ends fixed: pushed sideways by y, it is pulled back
  // by T (1/L_0 + 1/L_1) y, the classic string stiffness
  const double tension = 120.0, l0 = 0.1, l1 = 0.3;
  const std::vector<Point> q = {Point(0, 0, 0), Point(l0, 0, 0), Point(l0 + l1, 0, 0)};
  const std::vector<Point> still(3, Point::Zero());
  const PathForceJacobian jacobian = ForceJacobian(MeasurePath(q), still, {tension, 0.0, 0.0});
  EXPECT_NEAR(jacobian.position_block(1, 1)(1, 1), -tension * (1 / l0 + 1 / l1), 1e-9);
  EXPECT_NEAR(jacobian.position_block(1, 1)(2, 2), -tension * (1 / l0 + 1 / l1), 1e-9);
  EXPECT_NEAR(jacobian.position_block(1, 1)(0, 0), 0.0, 1e-12);  // along it, none
  EXPECT_NEAR(MeasurePath(q).shortest_segment(), l0, 1e-15);
}

TEST(ElementPath, APlanarPathStaysInItsPlane) {
  const std::vector<Point> q = {Point(0, 0, 0), Point(0.1, 0.05, 0), Point(0.2, -0.02, 0)};
  const std::vector<Point> qdot = {Point(0.1, 0.3, 0), Point(-0.2, 0.1, 0), Point(0, 0, 0)};
  const PathGeometry path = MeasurePath(q);
  const PathForceJacobian jacobian = ForceJacobian(path, qdot, {50.0, 700.0, 3.0});
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(path.gradient[j].z(), 0.0);
    for (std::size_t k = 0; k < 3; ++k) {
      for (int c = 0; c < 2; ++c) {
        EXPECT_EQ(jacobian.position_block(j, k)(2, c), 0.0);  // no z force from x-y motion
        EXPECT_EQ(jacobian.velocity_block(j, k)(2, c), 0.0);
      }
    }
  }
}

}  // namespace
}  // namespace musclesim
