#include "musclesim/dynamics/node_kinds.h"

#include <utility>

namespace musclesim {

namespace {

NodeVariant Kind(NodeKind kind, const char* name, const char* selector, const char* selector_doc,
                 const char* law) {
  NodeVariant variant;
  variant.type = "node";
  variant.name = name;
  variant.selector = selector;
  variant.selector_doc = selector_doc;
  variant.law = law;
  variant.is = [kind](const Node& n) { return n.kind == kind; };
  variant.make = [kind](Node& n) { n.kind = kind; };
  return variant;
}

// The node's position: x in `position`, y and z in `position_yz`.
PointField<Node> Position(const char* key, const char* doc) {
  return {key,
          kPositionRange,
          true,
          "",
          doc,
          [](const Node& n) { return n.PositionCoordinates(); },
          [](Node& n, const FieldPoint& x) {
            n.position = x[0];
            n.position_yz = {x[1], x[2]};
          }};
}

NodeVariant Fixed() {
  NodeVariant variant = Kind(NodeKind::kFixed, "fixed", "fixed", "fixed (its position [m])",
                             "held at its position: an anchor of the network");
  variant.points = {Position("fixed", "where it is held")};
  return variant;
}

NodeVariant Free() {
  NodeVariant variant =
      Kind(NodeKind::kFree, "free", "mass", "mass (a free node [kg], with position and velocity)",
           "mass xddot = the forces of its elements and loads (docs/model.md 7)");
  NumberField<Node> mass = MemberField("mass", &Node::mass, kMassRange, std::nullopt,
                                       "its mass (its hanging mass loads add to it)");
  mass.also = 0.0;
  mass.also_means =
      "a massless junction whose velocity its force balance fixes (docs/model.md 14.4)";
  variant.fields = {std::move(mass)};
  PointField<Node> velocity{
      "velocity",
      kSpeedRange,
      false,
      "v",
      "its velocity at the start; absent on a massless junction, whose velocity follows",
      [](const Node& n) { return n.VelocityCoordinates(); },
      [](Node& n, const FieldPoint& v) {
        n.velocity = v[0];
        n.velocity_yz = {v[1], v[2]};
      }};
  variant.points = {Position("position", "its position at the start"), std::move(velocity)};
  return variant;
}

NodeVariant Prescribed() {
  NodeVariant variant =
      Kind(NodeKind::kPrescribed, "prescribed", "prescribed", "prescribed (its motion)",
           "moves as its motion x(t) says, whatever the forces");
  variant.other_keys = {"prescribed"};
  return variant;
}

NodeVariant OnBody() {
  NodeVariant variant =
      Kind(NodeKind::kOnBody, "on_body", "point", "point (of a body, with its body)",
           "moves with its body; the forces on it act on the body (docs/model.md 15.1)");
  variant.points = {Position("point", "where it is, in the body's frame")};
  variant.texts = {{"body", "the body it is fixed in (bodies:)",
                    [](const Node& n) { return n.body; },
                    [](Node& n, std::string body) { n.body = std::move(body); }, true}};
  return variant;
}

}  // namespace

const std::vector<NodeVariant>& NodeKinds() {
  static const std::vector<NodeVariant> variants{Fixed(), Prescribed(), Free(), OnBody()};
  return variants;
}

const std::vector<SignalField<Node>>& NodeSignals() {
  static const std::vector<SignalField<Node>> signals = [] {
    SignalField<Node> motion = Signal<Node>(
        "prescribed", "m",
        "its motion x(t); in 2 or 3 dimensions a list [x(t), y(t)] or [x(t), y(t), z(t)]",
        [](auto& n, std::size_t c) {
          if (n.kind != NodeKind::kPrescribed) return decltype(&n.motion){nullptr};
          return c == 0 ? &n.motion : &n.motion_yz[c - 1];
        },
        &kPositionRange, CheckWaveform);
    motion.continuous = true;
    motion.per_coordinate = true;
    motion.coordinate_noun = "motion";
    return std::vector{std::move(motion)};
  }();
  return signals;
}

const std::vector<NameField<Node>>& NodeNames() {
  static const std::vector<NameField<Node>> names{MemberName(
      "name", &Node::name, "", "the node's name, unique among the nodes, which elements join")};
  return names;
}

}  // namespace musclesim
