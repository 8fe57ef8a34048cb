#include "musclesim/dynamics/actuator_fields.h"

namespace musclesim {

namespace {

NumberField<ActuatorParams> Of(const char* key, double ActuatorParams::*member,
                               const InputRange& range, std::optional<double> fallback,
                               const char* doc) {
  return {key,
          range,
          fallback,
          doc,
          [member](const ActuatorParams& p) { return p.*member; },
          [member](ActuatorParams& p, double v) { p.*member = v; }};
}

PartVariant<ActuatorParams> Block() {
  PartVariant<ActuatorParams> block;
  block.type = "actuator";
  block.name = "actuator";
  block.law = "m_eff xddot = F_load - T - c xdot - k (x - l0) (docs/model.md 6)";
  block.fields = {
      Of("mass", &ActuatorParams::mass, kMassRange, std::nullopt,
         "m, the moving mass (a hanging mass load adds to it)"),
      Of("damping", &ActuatorParams::damping, kDampingRange, 0.0, "c, the parallel damper"),
      Of("stiffness", &ActuatorParams::stiffness, kStiffnessRange, 0.0, "k, the parallel spring"),
      Of("rest_length", &ActuatorParams::rest_length, kPositionRange, 0.0,
         "l0, the length at which that spring pulls nothing"),
  };
  block.is = [](const ActuatorParams&) { return true; };
  block.make = [](ActuatorParams&) {};
  return block;
}

}  // namespace

const std::vector<PartVariant<ActuatorParams>>& ActuatorBlock() {
  static const std::vector<PartVariant<ActuatorParams>> block{Block()};
  return block;
}

}  // namespace musclesim
