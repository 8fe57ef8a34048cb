#include "musclesim/dynamics/element_laws.h"

#include <cmath>

namespace musclesim {

namespace {

// OpenSim's default tendon strain at the maximum isometric force [-].
constexpr double kDeGrooteTendonStrain = 0.049;

int Tag(ElementPartial partial) { return static_cast<int>(partial); }

// A spring's or linear tendon's stiffness.
ElementField Stiffness() {
  return MemberField("stiffness", &Element::stiffness, kStiffnessRange, std::nullopt,
                     "the force per metre of stretch", Tag(ElementPartial::kStiffness));
}

ElementLaw Spring() {
  ElementLaw law;
  law.type = "spring";
  law.name = "spring";
  law.law = "T = stiffness (l - rest_length), pushing when compressed";
  law.fields = {
      Stiffness(),
      MemberField("rest_length", &Element::rest_length, kPositionRange, std::nullopt,
                  "the length at which it pulls nothing", Tag(ElementPartial::kRestLength)),
  };
  law.is = [](const Element& e) { return e.kind == ElementKind::kSpring; };
  law.make = [](Element& e) { e.kind = ElementKind::kSpring; };
  return law;
}

ElementField SlackLength() {
  return MemberField("slack_length", &Element::slack_length, kSlackLengthRange, std::nullopt,
                     "the length below which it pulls nothing", Tag(ElementPartial::kSlackLength));
}

ElementLaw LinearTendon() {
  ElementLaw law;
  law.type = "tendon";
  law.name = "linear tendon";
  law.selector = "stiffness";
  law.selector_doc = "stiffness (a linear tendon [N/m])";
  law.law = "T = stiffness (l - slack_length) above the slack length, else 0";
  law.fields = {
      SlackLength(),
      Stiffness(),
  };
  law.is = [](const Element& e) {
    return e.kind == ElementKind::kTendon && !e.exponential() && !e.pushes_below_slack;
  };
  law.make = [](Element& e) { e.kind = ElementKind::kTendon; };
  return law;
}

ElementLaw ExponentialTendon() {
  ElementLaw law;
  law.type = "tendon";
  law.name = "exponential tendon";
  law.selector = "exponential";
  law.selector_doc = "exponential ({k, alpha}: k (exp(alpha (l - slack_length)) - 1))";
  law.law = "T = k (exp(alpha (l - slack_length)) - 1) above the slack length, else 0";
  law.fields = {
      SlackLength(),
      MemberField("exponential.k", &Element::k, kPositiveForceRange, std::nullopt,
                  "the tension's scale", Tag(ElementPartial::kScale)),
      MemberField("exponential.alpha", &Element::alpha, kTendonRateRange, std::nullopt,
                  "the rate: the tension grows e-fold over 1/alpha of stretch",
                  Tag(ElementPartial::kRate)),
  };
  law.is = [](const Element& e) {
    return e.kind == ElementKind::kTendon && e.exponential() && !e.pushes_below_slack;
  };
  law.make = [](Element& e) { e.kind = ElementKind::kTendon; };
  return law;
}

// Stored as the exponential tendon k = 0.2 F0, alpha = ln 6 / strain / l_s, pushing below
// the slack length (Element::DeGrooteTendon). No field has a closed-form derivative here: the
// rate follows the slack length, which the exponential's closed form at fixed alpha leaves
// out, so a difference quotient is used.
ElementLaw DeGrooteTendon() {
  ElementLaw law;
  law.type = "tendon";
  law.name = "De Groote tendon";
  law.selector = "degroote2016";
  law.selector_doc =
      "degroote2016 ({max_isometric_force, strain_at_one_norm_force}: OpenSim's De Groote "
      "tendon)";
  law.law =
      "T = F0 (0.2 exp(kT (l / slack_length - 1)) - 0.2), kT = ln(6) / strain, on both sides "
      "of the slack length (OpenSim's DeGrooteFregly2016Muscle)";
  law.fields = {
      {"slack_length", kDeGrooteSlackRange, std::nullopt,
       "the length at which it pulls nothing; changing it keeps the strain",
       [](const Element& e) { return e.slack_length; },
       [](Element& e, double v) {
         e.alpha *= e.slack_length / v;
         e.slack_length = v;
       }},
      {"degroote2016.max_isometric_force", kPositiveForceRange, std::nullopt,
       "F0, the muscle's maximum isometric force, which the tendon carries at its strain",
       [](const Element& e) { return e.k / 0.2; }, [](Element& e, double v) { e.k = 0.2 * v; }},
      {"degroote2016.strain_at_one_norm_force", kTendonStrainRange, kDeGrooteTendonStrain,
       "the strain at F0 (OpenSim's default 0.049)",
       [](const Element& e) { return std::log(6.0) / (e.alpha * e.slack_length); },
       [](Element& e, double v) { e.alpha = std::log(6.0) / v / e.slack_length; }},
  };
  law.is = [](const Element& e) {
    return e.kind == ElementKind::kTendon && e.exponential() && e.pushes_below_slack;
  };
  law.make = [](Element& e) {
    e.kind = ElementKind::kTendon;
    e.pushes_below_slack = true;
  };
  return law;
}

ElementLaw Damper() {
  ElementLaw law;
  law.type = "damper";
  law.name = "damper";
  law.law = "T = damping dl/dt";
  law.fields = {
      MemberField("damping", &Element::damping, kDampingRange, std::nullopt,
                  "the force per metre per second of lengthening", Tag(ElementPartial::kDamping)),
  };
  law.is = [](const Element& e) { return e.kind == ElementKind::kDamper; };
  law.make = [](Element& e) { e.kind = ElementKind::kDamper; };
  return law;
}

}  // namespace

const std::vector<ElementLaw>& ElementLaws() {
  static const std::vector<ElementLaw> laws{Spring(), LinearTendon(), ExponentialTendon(),
                                            DeGrooteTendon(), Damper()};
  return laws;
}

const ElementLaw* LawOf(const Element& element) { return VariantOf(ElementLaws(), element); }

const std::vector<NameField<Element>>& ElementNames() {
  static const std::vector<NameField<Element>> names{
      MemberName("name", &Element::name, "", "the element's name, unique among the elements"),
      MemberName("from", &Element::from, "a node",
                 "where it starts: its length is the distance from this node"),
      MemberName("to", &Element::to, "a node", "where it ends")};
  return names;
}

}  // namespace musclesim
