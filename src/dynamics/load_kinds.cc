#include "musclesim/dynamics/load_kinds.h"

#include <utility>

namespace musclesim {

namespace {

LoadVariant Kind(LoadKind kind, const char* type, const char* name, const char* law,
                 std::vector<NumberField<Load>> fields) {
  LoadVariant variant;
  variant.type = type;
  variant.name = name;
  variant.law = law;
  variant.fields = std::move(fields);
  variant.is = [kind](const Load& l) { return l.kind == kind; };
  variant.make = [kind](Load& l) { l.kind = kind; };
  return variant;
}

LoadVariant Spring() {
  return Kind(LoadKind::kSpring, "spring", "spring load", "F = stiffness (anchor - x)",
              {MemberField("stiffness", &Load::stiffness, kStiffnessRange, std::nullopt,
                           "the force per metre towards the anchor"),
               MemberField("anchor", &Load::anchor, kPositionRange, std::nullopt,
                           "the length at which it pulls nothing")});
}

LoadVariant Mass() {
  return Kind(LoadKind::kMass, "mass", "hanging mass",
              "F = mass gravity, and the mass joins the moving mass",
              {MemberField("mass", &Load::mass, kMassRange, std::nullopt, "the weight's mass"),
               MemberField("gravity", &Load::gravity, kGravityRange, 9.81,
                           "the acceleration along +x (lengthening)")});
}

}  // namespace

const std::vector<LoadVariant>& LoadVariants() {
  static const std::vector<LoadVariant> variants{Spring(), Mass()};
  return variants;
}

const std::vector<NameField<NodeLoad>>& LoadNames() {
  static const std::vector<NameField<NodeLoad>> names{MemberName(
      "node", &NodeLoad::node, "a free node",
      "the node it acts on; a network's loads only (the single actuator's act on its tip)")};
  return names;
}

}  // namespace musclesim
