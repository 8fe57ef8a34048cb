#include "musclesim/dynamics/actuator_fields.h"

namespace musclesim {

namespace {

PartVariant<ActuatorParams> Block() {
  using A = ActuatorParams;
  return OnlyVariant<A>(
      "actuator", "m_eff xddot = F_load - T - c xdot - k (x - l0) (docs/model.md 6)",
      {MemberField("mass", &A::mass, kMassRange, std::nullopt,
                   "m, the moving mass (a hanging mass load adds to it)"),
       MemberField("damping", &A::damping, kDampingRange, 0.0, "c, the parallel damper"),
       MemberField("stiffness", &A::stiffness, kStiffnessRange, 0.0, "k, the parallel spring"),
       MemberField("rest_length", &A::rest_length, kPositionRange, 0.0,
                   "l0, the length at which that spring pulls nothing")});
}

}  // namespace

const std::vector<PartVariant<ActuatorParams>>& ActuatorBlock() {
  static const std::vector<PartVariant<ActuatorParams>> block{Block()};
  return block;
}

}  // namespace musclesim
