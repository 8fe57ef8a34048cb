#include "musclesim/dynamics/network_parts.h"

#include <cassert>
#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/enum_names.h"

namespace musclesim {

constexpr EnumName<NodeKind> kNodeKindNames[] = {
    {NodeKind::kFixed, "fixed"},
    {NodeKind::kPrescribed, "prescribed"},
    {NodeKind::kFree, "free"},
    {NodeKind::kOnBody, "on_body"},
};

std::string_view ToString(NodeKind kind) { return ToString(kNodeKindNames, kind); }

constexpr EnumName<ElementKind> kElementKindNames[] = {
    {ElementKind::kActuator, "actuator"},
    {ElementKind::kSpring, "spring"},
    {ElementKind::kTendon, "tendon"},
    {ElementKind::kDamper, "damper"},
};

std::string_view ToString(ElementKind kind) { return ToString(kElementKindNames, kind); }

ElementKind ParseElementKind(std::string_view text) {
  return Parse(kElementKindNames, "type", text);
}

namespace {

// key + "[i]", built by appending (GCC 12 warns falsely on "[" + std::to_string(i)).
std::string Indexed(std::string key, std::size_t i) {
  key.append("[").append(std::to_string(i)).append("]");
  return key;
}

}  // namespace

void Validate(const Space& space) {
  Require(space.dimensions >= 1 && space.dimensions <= 3, "dimensions", space.dimensions,
          "must be 1, 2 or 3");
  for (int c = 0; c < 3; ++c) {
    const std::string path = Indexed("gravity", static_cast<std::size_t>(c));
    Require(std::isfinite(space.gravity[c]), path, space.gravity[c], "must be finite [m/s^2]");
    Require(c < space.dimensions || space.gravity[c] == 0.0, path, space.gravity[c],
            "must be 0: the network has " + std::to_string(space.dimensions) + " dimension(s)");
  }
  Require(space.dimensions > 1 || space.gravity[0] == 0.0, "gravity[0]", space.gravity[0],
          "must be 0 on a line: hang a weight with a load of type mass (docs/guide/networks.md)");
}

void Validate(const Node& node) {
  const NodeVariant* kind = VariantOf(NodeKinds(), node);
  assert(kind != nullptr);  // every NodeKind has its variant
  // finite, not a file's ranges: a program may build past them (a chain longer than a
  // kilometre; a mass too small for its forces, whose overflow NonFiniteCause then names)
  for (const PointField<Node>& point : kind->points) {
    const FieldPoint x = point.get(node);
    for (std::size_t c = 0; c < x.size(); ++c) {
      Require(std::isfinite(x[c]), CoordinateKey(point.key, c), x[c],
              std::string("must be finite [") + point.range.unit + "]");
    }
  }
  ValidateSignals(NodeSignals(), node);
  if (node.kind == NodeKind::kOnBody && node.body.empty()) {
    throw ParameterError("body", "\"\"", "must name a body of the skeleton");
  }
  if (node.kind == NodeKind::kFree) {
    Require(std::isfinite(node.mass) && node.mass >= 0.0, "mass", node.mass,
            "must be finite and >= 0 [kg] (0: a massless junction, docs/model.md 14.4)");
    // a massless junction's velocity is the root of its balance, not an initial condition
    Require(node.mass > 0.0 || node.VelocityCoordinates() == Coordinates{}, "velocity",
            node.velocity,
            "must be absent (or 0) on a massless junction: its velocity follows from its force "
            "balance");
  }
}

Node Node::Fixed(std::string name, double position) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kFixed;
  node.position = position;
  return Validated(std::move(node));
}

Node Node::Prescribed(std::string name, Waveform motion) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kPrescribed;
  node.motion = std::move(motion);
  return Validated(std::move(node));
}

Node Node::Fixed(std::string name, const Coordinates& position) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kFixed;
  node.position = position[0];
  node.position_yz = {position[1], position[2]};
  return Validated(std::move(node));
}

Node Node::Prescribed(std::string name, std::array<Waveform, 3> motion) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kPrescribed;
  node.motion = std::move(motion[0]);
  node.motion_yz = {std::move(motion[1]), std::move(motion[2])};
  return Validated(std::move(node));
}

Node Node::Free(std::string name, double mass, const Coordinates& position,
                const Coordinates& velocity) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kFree;
  node.mass = mass;
  node.position = position[0];
  node.position_yz = {position[1], position[2]};
  node.velocity = velocity[0];
  node.velocity_yz = {velocity[1], velocity[2]};
  return Validated(std::move(node));
}

Node Node::OnBody(std::string name, std::string body, const Coordinates& point) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kOnBody;
  node.body = std::move(body);
  node.position = point[0];
  node.position_yz = {point[1], point[2]};
  return Validated(std::move(node));
}

ViaPoint ViaPoint::Node(std::string name) {
  ViaPoint via;
  via.node = std::move(name);
  return via;
}

ViaPoint ViaPoint::Wrap(std::string surface) {
  ViaPoint via;
  via.wrap = std::move(surface);
  return via;
}

ViaPoint ViaPoint::Fixed(const Coordinates& position) {
  ViaPoint via;
  via.position = position;
  return via;
}

Node Node::Free(std::string name, double mass, double position, double velocity) {
  Node node;
  node.name = std::move(name);
  node.kind = NodeKind::kFree;
  node.mass = mass;
  node.position = position;
  node.velocity = velocity;
  return Validated(std::move(node));
}

namespace {

// A passive element's numbers against its law's ranges (dynamics/element_laws.h). De Groote's
// tendon is stored as k = 0.2 F0, alpha = ln 6 / strain / l_s: its F0 and strain, recomputed,
// may round past the bounds they were given at (Element::DeGrooteTendon checks what it is
// given), so what is checked here is what the law needs, under the keys a file gives.
void ValidateLaw(const Element& e) {
  // a k that is not > 0 reads as a linear tendon: it must be 0 then
  if (e.kind == ElementKind::kTendon && !e.exponential() && e.k != 0.0) {
    RequireInRange("exponential.k", e.k, kPositiveForceRange);
  }
  const ElementLaw* law = LawOf(e);
  if (law == nullptr) {
    throw ParameterError("pushes_below_slack", "true", "needs an exponential tendon (De Groote's)");
  }
  if (!e.pushes_below_slack) return ValidateFields(*law, e);
  RequireInRange("slack_length", e.slack_length, kDeGrooteSlackRange);
  Require(e.k <= 0.2 * kPositiveForceRange.max, "degroote2016.max_isometric_force", e.k / 0.2,
          kPositiveForceRange.Rule());
  Require(std::isfinite(e.alpha) && e.alpha > 0.0, "degroote2016.strain_at_one_norm_force",
          std::log(6.0) / (e.alpha * e.slack_length), kTendonStrainRange.Rule());
}

}  // namespace

void Validate(const Element& e) {
  switch (e.kind) {
    case ElementKind::kActuator:
      if (e.model == nullptr) throw ParameterError("model", "none", "an actuator needs a model");
      // a controlled actuator's activation is the controller's output
      if (!e.controlled) ValidateSignals(ActuatorSignals<Element>(), e);
      if (e.excitation) Validate(*e.excitation);  // its dynamics; paths the element's keys
      break;
    case ElementKind::kSpring:
    case ElementKind::kTendon:
    case ElementKind::kDamper: ValidateLaw(e); break;
  }
  for (std::size_t v = 0; v < e.via.size(); ++v) {
    if (!e.via[v].node.empty()) continue;
    for (int c = 0; c < 3; ++c) {
      Require(std::isfinite(e.via[v].position[c]),
              Indexed(Indexed("via", v), static_cast<std::size_t>(c)), e.via[v].position[c],
              "must be finite [m]");
    }
  }
}

namespace {

Element Make(std::string name, ElementKind kind, std::string from, std::string to) {
  Element e;
  e.name = std::move(name);
  e.kind = kind;
  e.from = std::move(from);
  e.to = std::move(to);
  return e;
}

}  // namespace

Element Element::Actuator(std::string name, std::string from, std::string to,
                          std::shared_ptr<const TensionModel> model, Waveform activation) {
  Element e = Make(std::move(name), ElementKind::kActuator, std::move(from), std::move(to));
  e.model = std::move(model);
  e.activation = std::move(activation);
  return Validated(std::move(e));
}

Element Element::Actuator(std::string name, std::string from, std::string to,
                          std::shared_ptr<const TensionModel> model, ExcitationInput excitation) {
  Element e = Make(std::move(name), ElementKind::kActuator, std::move(from), std::move(to));
  e.model = std::move(model);
  e.excitation = std::move(excitation);
  return Validated(std::move(e));
}

Element Element::ControlledActuator(std::string name, std::string from, std::string to,
                                    std::shared_ptr<const TensionModel> model) {
  Element e = Make(std::move(name), ElementKind::kActuator, std::move(from), std::move(to));
  e.model = std::move(model);
  e.controlled = true;
  return Validated(std::move(e));
}

Element Element::ControlledActuator(std::string name, std::string from, std::string to,
                                    std::shared_ptr<const TensionModel> model,
                                    ActivationDynamics dynamics, double initial_activation) {
  Element e = Make(std::move(name), ElementKind::kActuator, std::move(from), std::move(to));
  e.model = std::move(model);
  e.controlled = true;
  // the signal is unused: the controller's output is the excitation
  e.excitation = ExcitationInput{Waveform::Constant(0.0), dynamics, initial_activation};
  return Validated(std::move(e));
}

Element Element::Spring(std::string name, std::string from, std::string to, double stiffness,
                        double rest_length) {
  Element e = Make(std::move(name), ElementKind::kSpring, std::move(from), std::move(to));
  e.stiffness = stiffness;
  e.rest_length = rest_length;
  return Validated(std::move(e));
}

Element Element::LinearTendon(std::string name, std::string from, std::string to,
                              double slack_length, double stiffness) {
  Element e = Make(std::move(name), ElementKind::kTendon, std::move(from), std::move(to));
  e.slack_length = slack_length;
  e.stiffness = stiffness;
  return Validated(std::move(e));
}

Element Element::DeGrooteTendon(std::string name, std::string from, std::string to,
                                double slack_length, double max_isometric_force,
                                double strain_at_one_norm_force) {
  RequireInRange("degroote2016.max_isometric_force", max_isometric_force, kPositiveForceRange);
  RequireInRange("degroote2016.strain_at_one_norm_force", strain_at_one_norm_force,
                 kTendonStrainRange);
  RequireInRange("slack_length", slack_length, kDeGrooteSlackRange);
  Element e = Make(std::move(name), ElementKind::kTendon, std::move(from), std::move(to));
  e.slack_length = slack_length;
  // f_T = c1 exp(kT (l~ - c2)) - c3 with c1 = c3 = 0.2, c2 = 1: kT = ln((1 + c3) / c1) / strain
  e.k = 0.2 * max_isometric_force;
  e.alpha = std::log(6.0) / strain_at_one_norm_force / slack_length;
  e.pushes_below_slack = true;
  return Validated(std::move(e));
}

Element Element::ExponentialTendon(std::string name, std::string from, std::string to,
                                   double slack_length, double k, double alpha) {
  Element e = Make(std::move(name), ElementKind::kTendon, std::move(from), std::move(to));
  e.slack_length = slack_length;
  e.k = k;
  e.alpha = alpha;
  // k = 0 would read as a linear tendon: name the rule here
  RequireInRange("exponential.k", k, kPositiveForceRange);
  return Validated(std::move(e));
}

Element Element::Damper(std::string name, std::string from, std::string to, double damping) {
  Element e = Make(std::move(name), ElementKind::kDamper, std::move(from), std::move(to));
  e.damping = damping;
  return Validated(std::move(e));
}

}  // namespace musclesim
