// A Skeleton in a build without Pinocchio: every skeleton is refused with
// SkeletonUnavailable, so a scenario with bodies says plainly what the build lacks.
#include "dynamics/skeleton_backend.h"

namespace musclesim {

struct Skeleton::Model {};
struct SkeletonWorkspace::Impl {};

bool SkeletonAvailable() { return false; }

std::unique_ptr<Skeleton::Model, Skeleton::ModelDeleter> BuildSkeletonModel(
    const std::vector<Body>&, const std::vector<Joint>&, const Coordinates&) {
  throw SkeletonUnavailable();
}

SkeletonWorkspace::SkeletonWorkspace(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SkeletonWorkspace::~SkeletonWorkspace() = default;
SkeletonWorkspace::SkeletonWorkspace(SkeletonWorkspace&&) noexcept = default;
SkeletonWorkspace& SkeletonWorkspace::operator=(SkeletonWorkspace&&) noexcept = default;
Skeleton::~Skeleton() = default;
void Skeleton::ModelDeleter::operator()(Model* model) const { delete model; }
Skeleton::Skeleton(Skeleton&&) noexcept = default;
SkeletonWorkspace Skeleton::NewWorkspace() const { throw SkeletonUnavailable(); }
void Skeleton::Update(const double*, const double*, SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
Coordinates Skeleton::PointPosition(int, const Coordinates&, const SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
Coordinates Skeleton::PointVelocity(int, const Coordinates&, const SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
Coordinates Skeleton::PointInBody(int, const Coordinates&, const SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
Coordinates Skeleton::DirectionInWorld(int, const Coordinates&, const SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
void Skeleton::PointJacobian(int, const Coordinates&, SkeletonWorkspace&, double*) const {
  throw SkeletonUnavailable();
}
void Skeleton::ClearForces(SkeletonWorkspace&) const { throw SkeletonUnavailable(); }
void Skeleton::AddForce(int, const Coordinates&, const Coordinates&, SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
void Skeleton::Accelerations(const double*, const double*, const double*, SkeletonWorkspace&,
                             double*) const {
  throw SkeletonUnavailable();
}
double Skeleton::KineticEnergy(const double*, const double*, SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}
double Skeleton::PotentialEnergy(const double*, SkeletonWorkspace&) const {
  throw SkeletonUnavailable();
}

}  // namespace musclesim
