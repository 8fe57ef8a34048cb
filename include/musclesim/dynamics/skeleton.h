// A skeleton (docs/model.md 15) built on a rigid-body library (Pinocchio): its coordinates
// q and speeds u (one per coordinate: no joint here has a quaternion), the kinematics of
// points fixed in its bodies, and the forward dynamics M(q) u' = tau + J^T F - C(q, u) by the
// articulated-body algorithm. Immutable once built and shared by every thread that
// integrates it; what an evaluation writes is in a SkeletonWorkspace its caller owns.
// A build without Pinocchio (MUSCLESIM_HAVE_PINOCCHIO off) has this interface, and its
// constructor throws SkeletonUnavailable.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/core/coordinates.h"
#include "musclesim/dynamics/skeleton_parts.h"

namespace musclesim {

// Whether this build has the skeleton component (Pinocchio).
bool SkeletonAvailable();

// A scenario with bodies, in a build without Pinocchio.
class SkeletonUnavailable : public std::runtime_error {
 public:
  SkeletonUnavailable();
};

// The kinematics and dynamics buffers of one evaluation (the rigid-body library's data).
class SkeletonWorkspace {
 public:
  ~SkeletonWorkspace();
  SkeletonWorkspace(SkeletonWorkspace&&) noexcept;
  SkeletonWorkspace& operator=(SkeletonWorkspace&&) noexcept;
  struct Impl;
  Impl& impl() { return *impl_; }
  const Impl& impl() const { return *impl_; }

 private:
  friend class Skeleton;
  explicit SkeletonWorkspace(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class Skeleton {
 public:
  // Validates every part and how they fit (ParameterError with paths "bodies[1].inertia",
  // "joints[0].child"): names unique and not "ground", each body the child of one joint,
  // parents known, no joint whose parent is its own descendant; `gravity` acts on every body.
  // Each wrap cylinder on a body of the skeleton or the ground ("wraps[0].body").
  Skeleton(std::vector<Body> bodies, std::vector<Joint> joints, Coordinates gravity,
           std::vector<WrapCylinder> wraps = {});
  ~Skeleton();
  Skeleton(Skeleton&&) noexcept;

  // q and u have this many entries each.
  int coordinate_count() const { return static_cast<int>(coordinates_.size()); }
  // Coordinate k's name, its joint and its index among the joint's.
  const JointCoordinate& coordinate(int k) const { return coordinates_[k]; }
  // Whether coordinate k turns (revolute, a planar joint's rotation) rather than slides.
  bool rotational(int k) const { return rotational_[k]; }
  int FindCoordinate(std::string_view name) const;  // -1 if none
  int FindBody(std::string_view name) const;        // -1: the ground; -2: none such
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Joint>& joints() const { return joints_; }  // as given
  const std::vector<WrapCylinder>& wraps() const { return wraps_; }
  const Coordinates& gravity() const { return gravity_; }  // [m/s^2]
  int FindWrap(std::string_view name) const;               // -1 if none
  // The body of wrap w (-1: the ground).
  int WrapBody(int w) const { return wrap_bodies_[w]; }
  // (q holds the coordinates in tree order: a joint's after its parent's; the order given
  // where that allows)
  // Whether coordinate k moves body `body` (-1: the ground, which none moves): its joint is
  // on the chain from the body to the ground.
  bool Moves(int body, int k) const { return body >= 0 && moves_[body][k]; }
  // A number of this skeleton alone among every skeleton built in the process.
  std::uint64_t id() const { return id_; }
  // Every coordinate's value and speed at the start.
  void InitialState(double* q, double* u) const;

  SkeletonWorkspace NewWorkspace() const;
  // The positions and velocities of every body at (q, u): what the point functions read.
  void Update(const double* q, const double* u, SkeletonWorkspace& ws) const;
  // Point `point` of body `body` (-1: the ground) in the world frame, and its velocity, at
  // the workspace's last Update.
  Coordinates PointPosition(int body, const Coordinates& point, const SkeletonWorkspace& ws) const;
  Coordinates PointVelocity(int body, const Coordinates& point, const SkeletonWorkspace& ws) const;
  // The world point `point` in the frame of body `body` (-1: the ground), and the direction
  // `direction` of the body's frame in the world's, at the workspace's last Update.
  Coordinates PointInBody(int body, const Coordinates& point, const SkeletonWorkspace& ws) const;
  Coordinates DirectionInWorld(int body, const Coordinates& direction,
                               const SkeletonWorkspace& ws) const;
  // The point's translational Jacobian d(position)/dq (3 rows of coordinate_count(),
  // row-major) at (q) of the last Update.
  void PointJacobian(int body, const Coordinates& point, SkeletonWorkspace& ws,
                     double* jacobian) const;

  // The forces on the bodies, before Accelerations: none, then each force F (world frame [N])
  // at a point of a body.
  void ClearForces(SkeletonWorkspace& ws) const;
  void AddForce(int body, const Coordinates& point, const Coordinates& force,
                SkeletonWorkspace& ws) const;
  // u' of M(q) u' = tau + (the forces added) - C(q, u) (gravity in C), by ABA. `tau` holds a
  // generalized force per coordinate.
  void Accelerations(const double* q, const double* u, const double* tau, SkeletonWorkspace& ws,
                     double* acceleration) const;
  // (1/2) u^T M u [J] and the potential energy of gravity, -sum m g . c [J]; each leaves the
  // workspace's placements at its q.
  double KineticEnergy(const double* q, const double* u, SkeletonWorkspace& ws) const;
  double PotentialEnergy(const double* q, SkeletonWorkspace& ws) const;

  struct Model;
  // The backend's (a deleter of its own, so that this class needs no complete Model)
  struct ModelDeleter {
    void operator()(Model* model) const;
  };

 private:
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<JointCoordinate> coordinates_;
  std::vector<bool> rotational_;
  std::vector<WrapCylinder> wraps_;
  Coordinates gravity_{};
  std::vector<int> wrap_bodies_;
  std::vector<std::vector<bool>> moves_;  // per body, per coordinate
  std::uint64_t id_ = 0;
  std::unique_ptr<Model, ModelDeleter> model_;
};

}  // namespace musclesim
