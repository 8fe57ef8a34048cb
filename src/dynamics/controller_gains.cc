#include "musclesim/dynamics/controller_gains.h"

namespace musclesim {

namespace {

// kGainRange in the gain's own unit.
NumberField<PidGains> Gain(const char* key, double PidGains::*member, const char* unit,
                           const char* doc) {
  return MemberField(key, member, InputRange{kGainRange.min, kGainRange.max, unit, kGainRange.why},
                     0.0, doc);
}

PartVariant<PidGains> Pid() {
  return OnlyVariant<PidGains>(
      "pid", "c = u_ff + kp err + ki z + kd (r' - y'), z' = err, clamped to [0, 1]",
      {Gain("kp", &PidGains::kp, "1/unit", "negative where more activation lowers the error"),
       Gain("ki", &PidGains::ki, "1/(unit s)", "0 gives the controller no integral state"),
       Gain("kd", &PidGains::kd, "s/unit",
            "0 on a tension (its rate would be an algebraic loop)")});
}

}  // namespace

const std::vector<NameField<Controller>>& ControllerNames() {
  static const std::vector<NameField<Controller>> names{
      MemberName("name", &Controller::name, "", "the controller's name, heading its CSV columns"),
      MemberName("drives", &Controller::drives, "an actuator",
                 "the actuator it drives; or co_contraction, a pair, instead", false)};
  return names;
}

const std::vector<NameField<Measurement>>& MeasureNames() {
  static const std::vector<NameField<Measurement>> names{
      MemberName("element", &Measurement::element, "an element",
                 "the element measured, its length or tension; or node instead", false),
      MemberName("node", &Measurement::node, "a free node",
                 "the node measured, its position; or element instead", false)};
  return names;
}

const std::vector<PartVariant<PidGains>>& ControllerGains() {
  static const std::vector<PartVariant<PidGains>> gains{Pid()};
  return gains;
}

}  // namespace musclesim
