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

const std::vector<SignalField<Controller>>& ControllerSignals() {
  static const std::vector<SignalField<Controller>> signals = [] {
    SignalField<Controller> reference = Signal<Controller>(
        "reference", "m or N",
        "r(t), in the measured quantity's unit: a position or length [m], "
        "a tension [N]",
        [](auto& c, std::size_t) { return &c.reference; }, nullptr, CheckWaveform);
    reference.accepted = "a position's or length's " + kPositionRange.Bounds() +
                         " m, a tension's " + kForceRange.Bounds() + " N";
    reference.values = [](const Controller& c) {
      return c.measure.quantity == MeasuredQuantity::kTension ? &kForceRange : &kPositionRange;
    };
    SignalField<Controller> feedforward = Signal<Controller>(
        "feedforward", "-", "u_ff(t), added to the command; 0 when absent",
        [](auto& c, std::size_t) { return &c.feedforward; }, &kFeedforwardRange, CheckWaveform);
    feedforward.required = false;
    SignalField<Controller> level = Signal<Controller>(
        "co_contraction.level", "-",
        "the pair's common activation (co_contraction's actuators: [FIRST, SECOND]): FIRST "
        "takes level + c, SECOND level - c",
        [](auto& c, std::size_t) { return c.co_contraction ? &c.co_contraction->level : nullptr; },
        nullptr, CheckActivation);
    level.accepted = ActivationValues();
    level.required_with = "co_contraction";
    return std::vector{std::move(reference), std::move(feedforward), std::move(level)};
  }();
  return signals;
}

const std::vector<PartVariant<PidGains>>& ControllerGains() {
  static const std::vector<PartVariant<PidGains>> gains{Pid()};
  return gains;
}

}  // namespace musclesim

namespace musclesim {

const std::vector<PartVariant<Controller>>& ControllerTypes() {
  static const std::vector<PartVariant<Controller>> types = [] {
    std::vector<PartVariant<Controller>> of_gains;
    for (const PartVariant<PidGains>& law : ControllerGains()) {
      of_gains.push_back(OnlyVariant<Controller>(
          law.type, law.law, NestedFields("gains", &Controller::gains, law.fields)));
    }
    return of_gains;
  }();
  return types;
}

}  // namespace musclesim
