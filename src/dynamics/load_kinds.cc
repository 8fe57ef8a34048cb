#include "musclesim/dynamics/load_kinds.h"

namespace musclesim {

namespace {

LoadVariant Spring() {
  LoadVariant spring;
  spring.type = "spring";
  spring.name = "spring load";
  spring.law = "F = stiffness (anchor - x)";
  spring.fields = {
      {"stiffness", kStiffnessRange, std::nullopt, "the force per metre towards the anchor",
       [](const Load& l) { return l.stiffness; }, [](Load& l, double v) { l.stiffness = v; }},
      {"anchor", kPositionRange, std::nullopt, "the length at which it pulls nothing",
       [](const Load& l) { return l.anchor; }, [](Load& l, double v) { l.anchor = v; }},
  };
  spring.is = [](const Load& l) { return l.kind == LoadKind::kSpring; };
  spring.make = [](Load& l) { l.kind = LoadKind::kSpring; };
  return spring;
}

LoadVariant Mass() {
  LoadVariant mass;
  mass.type = "mass";
  mass.name = "hanging mass";
  mass.law = "F = mass gravity, and the mass joins the moving mass";
  mass.fields = {
      {"mass", kMassRange, std::nullopt, "the weight's mass", [](const Load& l) { return l.mass; },
       [](Load& l, double v) { l.mass = v; }},
      {"gravity", kGravityRange, 9.81, "the acceleration along +x (lengthening)",
       [](const Load& l) { return l.gravity; }, [](Load& l, double v) { l.gravity = v; }},
  };
  mass.is = [](const Load& l) { return l.kind == LoadKind::kMass; };
  mass.make = [](Load& l) { l.kind = LoadKind::kMass; };
  return mass;
}

}  // namespace

const std::vector<LoadVariant>& LoadVariants() {
  static const std::vector<LoadVariant> variants{Spring(), Mass()};
  return variants;
}

}  // namespace musclesim
