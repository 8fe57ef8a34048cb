// A Skeleton's rigid-body side on Pinocchio (docs/model.md 15, docs/dependencies.md): the
// joints added in tree order, each body's inertia appended to the joint that moves it (a
// welded body to its parent's), points kept in their joint's frame; kinematics, the point
// Jacobians and ABA with the path forces as external forces. The only file that includes
// Pinocchio: its headers cost about a minute of compilation.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "dynamics/skeleton_backend.h"
#include "pinocchio/algorithm/aba.hpp"
#include "pinocchio/algorithm/energy.hpp"
#include "pinocchio/algorithm/jacobian.hpp"
#include "pinocchio/algorithm/kinematics.hpp"
#include "pinocchio/multibody.hpp"

namespace musclesim {

namespace pin = pinocchio;

struct Skeleton::Model {
  pin::Model model;
  std::vector<pin::JointIndex> body_joint;               // per body: the joint that moves it
  PINOCCHIO_ALIGNED_STD_VECTOR(pin::SE3) body_in_joint;  // the body's frame in that joint's
};

struct SkeletonWorkspace::Impl {
  explicit Impl(const pin::Model& model)
      : data(model), forces(model.joints.size(), pin::Force::Zero()) {}
  pin::Data data;
  PINOCCHIO_ALIGNED_STD_VECTOR(pin::Force) forces;  // per joint, in its frame
  bool jacobians = false;                           // data.J is of the last Update's q
  Eigen::VectorXd q;                                // of the last Update
  pin::Data::Matrix6x joint_jacobian;
};

SkeletonWorkspace::SkeletonWorkspace(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SkeletonWorkspace::~SkeletonWorkspace() = default;
SkeletonWorkspace::SkeletonWorkspace(SkeletonWorkspace&&) noexcept = default;
SkeletonWorkspace& SkeletonWorkspace::operator=(SkeletonWorkspace&&) noexcept = default;

bool SkeletonAvailable() { return true; }

namespace {

pin::SE3 Placement(const Frame& frame) {
  const auto& o = frame.orientation;
  const Eigen::Quaterniond rotation(o[0], o[1], o[2], o[3]);
  return pin::SE3(rotation.normalized().toRotationMatrix(),
                  Eigen::Vector3d(frame.position[0], frame.position[1], frame.position[2]));
}

Eigen::Vector3d Vector(const Coordinates& c) { return Eigen::Vector3d(c[0], c[1], c[2]); }

pin::Inertia BodyInertia(const Body& body) {
  const auto& I = body.inertia;
  Eigen::Matrix3d inertia;
  inertia << I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2];
  return pin::Inertia(body.mass, Vector(body.center_of_mass), inertia);
}

}  // namespace

std::unique_ptr<Skeleton::Model, Skeleton::ModelDeleter> BuildSkeletonModel(
    const std::vector<Body>& bodies, const std::vector<Joint>& joints, const Coordinates& gravity) {
  std::unique_ptr<Skeleton::Model, Skeleton::ModelDeleter> m(new Skeleton::Model);
  m->model.gravity.linear(Vector(gravity));
  m->body_joint.assign(bodies.size(), 0);
  m->body_in_joint.assign(bodies.size(), pin::SE3::Identity());
  const auto body_named = [&](const std::string& name) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].name == name) return static_cast<int>(b);
    }
    return -1;  // the ground
  };
  for (const Joint& joint : joints) {
    const int parent = body_named(joint.parent);
    const int child = body_named(joint.child);
    // the joint frame in the frame of the joint that moves the parent
    const pin::JointIndex parent_joint = parent < 0 ? 0 : m->body_joint[parent];
    const pin::SE3 in_parent_joint =
        (parent < 0 ? pin::SE3::Identity() : m->body_in_joint[parent]) * Placement(joint.in_parent);
    const pin::SE3 child_in_joint = Placement(joint.in_child).inverse();
    pin::JointIndex moved = parent_joint;
    pin::SE3 body_in_joint = in_parent_joint * child_in_joint;
    const Eigen::Vector3d axis = Vector(joint.axis).normalized();
    switch (joint.kind) {
      case JointKind::kRevolute:
        moved = m->model.addJoint(parent_joint, pin::JointModelRevoluteUnaligned(axis),
                                  in_parent_joint, joint.name);
        body_in_joint = child_in_joint;
        break;
      case JointKind::kPrismatic:
        moved = m->model.addJoint(parent_joint, pin::JointModelPrismaticUnaligned(axis),
                                  in_parent_joint, joint.name);
        body_in_joint = child_in_joint;
        break;
      case JointKind::kPlanar: {
        pin::JointModelComposite planar;
        planar.addJoint(pin::JointModelPX());
        planar.addJoint(pin::JointModelPY());
        planar.addJoint(pin::JointModelRZ());
        moved = m->model.addJoint(parent_joint, planar, in_parent_joint, joint.name);
        body_in_joint = child_in_joint;
        break;
      }
      case JointKind::kWeld: break;  // the child rides on its parent's joint
    }
    m->body_joint[child] = moved;
    m->body_in_joint[child] = body_in_joint;
    m->model.appendBodyToJoint(moved, BodyInertia(bodies[child]), body_in_joint);
  }
  return m;
}

Skeleton::~Skeleton() = default;
void Skeleton::ModelDeleter::operator()(Model* model) const { delete model; }
Skeleton::Skeleton(Skeleton&&) noexcept = default;

SkeletonWorkspace Skeleton::NewWorkspace() const {
  return SkeletonWorkspace(std::make_unique<SkeletonWorkspace::Impl>(model_->model));
}

namespace {

Eigen::Map<const Eigen::VectorXd> Map(const double* values, int n) {
  return Eigen::Map<const Eigen::VectorXd>(values, n);
}

}  // namespace

void Skeleton::Update(const double* q, const double* u, SkeletonWorkspace& ws) const {
  SkeletonWorkspace::Impl& w = ws.impl();
  const int n = coordinate_count();
  pin::forwardKinematics(model_->model, w.data, Map(q, n), Map(u, n));
  w.q = Map(q, n);
  w.jacobians = false;
}

namespace {

// The point in the frame of the joint that moves its body, and that joint (0: the ground).
std::pair<pin::JointIndex, Eigen::Vector3d> InJoint(const Skeleton::Model& m, int body,
                                                    const Coordinates& point) {
  if (body < 0) return {0, Vector(point)};
  return {m.body_joint[body], m.body_in_joint[body].act(Vector(point))};
}

}  // namespace

Coordinates Skeleton::PointPosition(int body, const Coordinates& point,
                                    const SkeletonWorkspace& ws) const {
  const auto [joint, local] = InJoint(*model_, body, point);
  const Eigen::Vector3d p = ws.impl().data.oMi[joint].act(local);
  return {p[0], p[1], p[2]};
}

Coordinates Skeleton::PointVelocity(int body, const Coordinates& point,
                                    const SkeletonWorkspace& ws) const {
  const auto [joint, local] = InJoint(*model_, body, point);
  const pin::Data& data = ws.impl().data;
  const pin::Motion& v = data.v[joint];  // in the joint's frame
  const Eigen::Vector3d velocity =
      data.oMi[joint].rotation() * (v.linear() + v.angular().cross(local));
  return {velocity[0], velocity[1], velocity[2]};
}

Coordinates Skeleton::PointInBody(int body, const Coordinates& point,
                                  const SkeletonWorkspace& ws) const {
  if (body < 0) return point;
  const pin::JointIndex joint = model_->body_joint[body];
  const Eigen::Vector3d in_joint = ws.impl().data.oMi[joint].actInv(Vector(point));
  const Eigen::Vector3d p = model_->body_in_joint[body].actInv(in_joint);
  return {p[0], p[1], p[2]};
}

Coordinates Skeleton::DirectionInWorld(int body, const Coordinates& direction,
                                       const SkeletonWorkspace& ws) const {
  if (body < 0) return direction;
  const pin::JointIndex joint = model_->body_joint[body];
  const Eigen::Vector3d d = ws.impl().data.oMi[joint].rotation() *
                            (model_->body_in_joint[body].rotation() * Vector(direction));
  return {d[0], d[1], d[2]};
}

void Skeleton::PointJacobian(int body, const Coordinates& point, SkeletonWorkspace& ws,
                             double* jacobian) const {
  SkeletonWorkspace::Impl& w = ws.impl();
  const int n = coordinate_count();
  if (!w.jacobians) {
    pin::computeJointJacobians(model_->model, w.data, w.q);
    w.jacobians = true;
  }
  const auto [joint, local] = InJoint(*model_, body, point);
  Eigen::Map<Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> out(jacobian, 3, n);
  if (joint == 0) {
    out.setZero();
    return;
  }
  w.joint_jacobian.setZero(6, n);
  pin::getJointJacobian(model_->model, w.data, joint, pin::LOCAL_WORLD_ALIGNED, w.joint_jacobian);
  // v_P = v_o + omega x r, r the point from the joint's origin along the world's axes
  const Eigen::Vector3d r = w.data.oMi[joint].rotation() * local;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d linear = w.joint_jacobian.col(k).head<3>();
    const Eigen::Vector3d angular = w.joint_jacobian.col(k).tail<3>();
    const Eigen::Vector3d column = linear + angular.cross(r);
    for (int c = 0; c < 3; ++c) out(c, k) = column[c];
  }
}

void Skeleton::ClearForces(SkeletonWorkspace& ws) const {
  for (pin::Force& f : ws.impl().forces) f.setZero();
}

void Skeleton::AddForce(int body, const Coordinates& point, const Coordinates& force,
                        SkeletonWorkspace& ws) const {
  const auto [joint, local] = InJoint(*model_, body, point);
  if (joint == 0) return;  // the ground absorbs it
  SkeletonWorkspace::Impl& w = ws.impl();
  const Eigen::Vector3d f = w.data.oMi[joint].rotation().transpose() * Vector(force);
  w.forces[joint].linear() += f;
  w.forces[joint].angular() += local.cross(f);
}

void Skeleton::Accelerations(const double* q, const double* u, const double* tau,
                             SkeletonWorkspace& ws, double* acceleration) const {
  SkeletonWorkspace::Impl& w = ws.impl();
  const int n = coordinate_count();
  pin::aba(model_->model, w.data, Map(q, n), Map(u, n), Map(tau, n), w.forces);
  Eigen::Map<Eigen::VectorXd>(acceleration, n) = w.data.ddq;
  // (ABA recomputes the joints' velocities, not their placements oMi: the point functions
  // read the last Update's, which callers give the same (q, u))
}

double Skeleton::KineticEnergy(const double* q, const double* u, SkeletonWorkspace& ws) const {
  const int n = coordinate_count();
  const double energy =
      pin::computeKineticEnergy(model_->model, ws.impl().data, Map(q, n), Map(u, n));
  Update(q, u, ws);  // the kinematics the point functions read: of this (q, u)
  return energy;
}

double Skeleton::PotentialEnergy(const double* q, SkeletonWorkspace& ws) const {
  const int n = coordinate_count();
  const double energy = pin::computePotentialEnergy(model_->model, ws.impl().data, Map(q, n));
  ws.impl().jacobians = false;  // its forward kinematics moved the placements to q
  ws.impl().q = Map(q, n);
  return energy;
}

}  // namespace musclesim
