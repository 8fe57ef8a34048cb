#include "musclesim/model/passive.h"

#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/model/tension_parameter.h"

namespace musclesim {

const PartVariant<PassiveParams>& PassiveBlock() {
  using Kind = TensionParameterKind;
  static const PartVariant<PassiveParams> block = OnlyVariant<PassiveParams>(
      "passive", "T_p = k_p (exp(alpha (x - slack_length)) - 1) above slack_length, else 0",
      {MemberField("k_p", &PassiveParams::k_p,
                   InputRange{0.0, kPositiveForceRange.max, "N", kPositiveForceRange.why},
                   std::nullopt, "the tension scale (0: no passive tension)",
                   static_cast<int>(Kind::kPassiveScale)),
       MemberField("alpha", &PassiveParams::alpha,
                   InputRange{0.0, 1e9, "1/m",
                              "a tension growing e-fold over less than a nanometre is no "
                              "actuator's",
                              true},
                   std::nullopt, "the exponential rate", static_cast<int>(Kind::kPassiveRate)),
       MemberField("slack_length", &PassiveParams::slack_length, kPositionRange, std::nullopt,
                   "the length where passive tension starts",
                   static_cast<int>(Kind::kSlackLength))});
  return block;
}

void Validate(const PassiveParams& params) { ValidateFields(PassiveBlock(), params); }

}  // namespace musclesim
