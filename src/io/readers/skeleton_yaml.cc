#include "io/readers/skeleton_yaml.h"

#include "io/readers/coordinates_yaml.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::ValidateAt;

// A rigid body's inertia: a grain of sand to a ship's hull, products of either sign.
constexpr InputRange kInertiaRange{-1e9, 1e9, "kg m^2",
                                   "a milligram at a micrometre to a ship's hull"};
// A coordinate's value and speed: radians or metres.
constexpr InputRange kCoordinateRange{-1e3, 1e3, "rad or m",
                                      "a kilometre, or some 160 turns, beyond any joint"};
constexpr InputRange kCoordinateSpeedRange{-1e4, 1e4, "rad/s or m/s",
                                           "beyond any joint a muscle moves"};
constexpr InputRange kWrapRadiusRange{0.0, 1e3, "m",
                                      "a kilometre, beyond any surface a path wraps over", true};
constexpr InputRange kJointDampingRange{0.0, 1e9, "N m s/rad or N s/m", "finite and >= 0"};

Coordinates Point(const yaml::Source& src, const Document& map, const std::string& path,
                  const char* key, int dimensions, Coordinates fallback = {}) {
  const Document& node = map[key];
  if (!node) return fallback;
  return ReadCoordinateList(src, node, Join(path, key), dimensions, kPositionRange, "");
}

Frame ReadFrame(const yaml::Source& src, const Document& node, const std::string& path,
                int dimensions) {
  yaml::RequireMap(src, node, path, {"position", "orientation"});
  Frame frame;
  frame.position = Point(src, node, path, "position", dimensions);
  if (const Document& o = node["orientation"]) {
    const std::vector<double> q = yaml::ReadNumbers(src, o, Join(path, "orientation"), 4);
    frame.orientation = {q[0], q[1], q[2], q[3]};
  }
  return frame;
}

void ReadCoordinate(const yaml::Source& src, const Document& map, const std::string& path,
                    JointCoordinate& c) {
  c.value = yaml::ReadOptionalNumberIn(src, map, path, "value", kCoordinateRange, 0.0);
  c.speed = yaml::ReadOptionalNumberIn(src, map, path, "speed", kCoordinateSpeedRange, 0.0);
  c.damping = yaml::ReadOptionalNumberIn(src, map, path, "damping", kJointDampingRange, 0.0);
}

Joint ReadJoint(const yaml::Source& src, const Document& item, const std::string& path,
                int dimensions) {
  if (!item.IsMap()) {
    yaml::Fail(src, item, path, yaml::Describe(item),
               "must be a map: name, type, parent, child, and the joint's frames");
  }
  yaml::RequireMap(src, item, path,
                   {"name", "type", "parent", "child", "in_parent", "in_child", "axis",
                    "coordinates", "value", "speed", "damping"});
  const std::string name = yaml::ReadPlainName(src, item, path, "name");
  const Document& type = yaml::Required(src, item, path, "type");
  JointKind kind = JointKind::kRevolute;
  ValidateAt(src, item, path,
             [&] { kind = ParseJointKind(yaml::ReadString(src, type, Join(path, "type"))); });
  Joint joint;
  ValidateAt(src, item, path,
             [&] { joint = Joint::Make(name, kind, std::string(kGroundBody), "placeholder"); });
  if (const Document& parent = item["parent"]) {
    joint.parent = yaml::ReadString(src, parent, Join(path, "parent"));
  }
  joint.child =
      yaml::ReadString(src, yaml::Required(src, item, path, "child"), Join(path, "child"));
  if (const Document& f = item["in_parent"]) {
    joint.in_parent = ReadFrame(src, f, Join(path, "in_parent"), dimensions);
  }
  if (const Document& f = item["in_child"]) {
    joint.in_child = ReadFrame(src, f, Join(path, "in_child"), dimensions);
  }
  if (const Document& axis = item["axis"]) {
    if (kind != JointKind::kRevolute && kind != JointKind::kPrismatic) {
      yaml::Fail(src, axis, Join(path, "axis"), yaml::Describe(axis),
                 "belongs to a revolute or prismatic joint only (this one is " +
                     std::string(ToString(kind)) + ")");
    }
    joint.axis = ReadCoordinateList(src, axis, Join(path, "axis"), 3, kPositionRange, "");
  }
  // one coordinate: its value, speed and damping on the joint itself, named as the joint;
  // or any number, each named, in `coordinates`
  const bool inline_coordinate = item["value"] || item["speed"] || item["damping"];
  if (const Document& list = item["coordinates"]) {
    const std::string at = Join(path, "coordinates");
    if (inline_coordinate) {
      yaml::Fail(src, list, at, yaml::Describe(list),
                 "must not be given with value, speed or damping on the joint: give each "
                 "coordinate's in its entry");
    }
    if (!list.IsSequence() || list.size() != joint.coordinates.size()) {
      yaml::Fail(src, list, at, yaml::Describe(list),
                 "must be a list of " + std::to_string(joint.coordinates.size()) +
                     " coordinate(s) for a joint of type " + std::string(ToString(kind)) +
                     ", each {name, value, speed, damping}");
    }
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string entry = Indexed(at, k);
      yaml::RequireMap(src, list[k], entry, {"name", "value", "speed", "damping"});
      if (list[k]["name"])
        joint.coordinates[k].name = yaml::ReadPlainName(src, list[k], entry, "name");
      ReadCoordinate(src, list[k], entry, joint.coordinates[k]);
    }
  } else if (inline_coordinate) {
    if (joint.coordinates.size() != 1) {
      yaml::Fail(src, item, path, yaml::Describe(item),
                 "gives value, speed or damping for a joint of " +
                     std::to_string(joint.coordinates.size()) +
                     " coordinates: give them per coordinate in `coordinates`");
    }
    ReadCoordinate(src, item, path, joint.coordinates[0]);
  }
  ValidateAt(src, item, path, [&] { Validate(joint); });
  return joint;
}

}  // namespace

std::vector<Body> ReadBodies(const yaml::Source& src, const Document& node, int dimensions) {
  if (dimensions == 1) {
    yaml::Fail(src, node, "bodies", yaml::Describe(node),
               "need dimensions: 2 or 3 at the top level: a skeleton moves in the plane or in "
               "space");
  }
  if (!node.IsSequence()) {
    yaml::Fail(src, node, "bodies", yaml::Describe(node),
               "must be a list of bodies, each {name, mass, center_of_mass, inertia}");
  }
  std::vector<Body> bodies;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const Document& item = node[i];
    const std::string path = Indexed("bodies", i);
    if (!item.IsMap()) {
      yaml::Fail(src, item, path, yaml::Describe(item),
                 "must be a map: name, mass, center_of_mass, inertia");
    }
    yaml::RequireMap(src, item, path, {"name", "mass", "center_of_mass", "inertia"});
    Body body;
    body.name = yaml::ReadPlainName(src, item, path, "name");
    body.mass = yaml::ReadNumberIn(src, yaml::Required(src, item, path, "mass"), Join(path, "mass"),
                                   kMassRange);
    body.center_of_mass = Point(src, item, path, "center_of_mass", dimensions);
    const Document& inertia = yaml::Required(src, item, path, "inertia");
    const std::vector<double> I = yaml::ReadNumbers(src, inertia, Join(path, "inertia"), 6);
    for (std::size_t k = 0; k < 6; ++k) {
      if (!(I[k] >= kInertiaRange.min && I[k] <= kInertiaRange.max)) {
        yaml::Fail(src, inertia[k], Indexed(Join(path, "inertia"), k), yaml::Describe(inertia[k]),
                   "must be within [-1e9, 1e9] kg m^2 ([Ixx, Iyy, Izz, Ixy, Ixz, Iyz] about the "
                   "centre of mass)");
      }
      body.inertia[k] = I[k];
    }
    ValidateAt(src, item, path, [&] { Validate(body); });
    bodies.push_back(std::move(body));
  }
  return bodies;
}

std::vector<Joint> ReadJoints(const yaml::Source& src, const Document& node, int dimensions) {
  if (!node.IsSequence()) {
    yaml::Fail(src, node, "joints", yaml::Describe(node),
               "must be a list of joints, each {name, type, parent, child, ...}");
  }
  std::vector<Joint> joints;
  for (std::size_t i = 0; i < node.size(); ++i) {
    joints.push_back(ReadJoint(src, node[i], Indexed("joints", i), dimensions));
  }
  return joints;
}

std::vector<WrapCylinder> ReadWraps(const yaml::Source& src, const Document& node, int dimensions) {
  if (!node.IsSequence()) {
    yaml::Fail(src, node, "wraps", yaml::Describe(node),
               "must be a list of wrap surfaces, each {name, type: cylinder, body, center, "
               "radius, ...}");
  }
  std::vector<WrapCylinder> wraps;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const Document& item = node[i];
    const std::string path = Indexed("wraps", i);
    if (!item.IsMap()) {
      yaml::Fail(src, item, path, yaml::Describe(item),
                 "must be a map: name, type, body, center, axis, radius, side");
    }
    yaml::RequireMap(src, item, path, {"name", "type", "body", "center", "axis", "radius", "side"});
    WrapCylinder wrap;
    wrap.name = yaml::ReadPlainName(src, item, path, "name");
    const Document& type = yaml::Required(src, item, path, "type");
    if (yaml::ReadString(src, type, Join(path, "type")) != "cylinder") {
      yaml::Fail(src, type, Join(path, "type"), yaml::Describe(type),
                 "must be cylinder (spheres are to come)");
    }
    if (const Document& body = item["body"])
      wrap.body = yaml::ReadString(src, body, Join(path, "body"));
    wrap.center = Point(src, item, path, "center", dimensions);
    if (const Document& axis = item["axis"]) {
      wrap.axis = ReadCoordinateList(src, axis, Join(path, "axis"), 3, kPositionRange, "");
    }
    wrap.radius = yaml::ReadNumberIn(src, yaml::Required(src, item, path, "radius"),
                                     Join(path, "radius"), kWrapRadiusRange);
    if (const Document& side = item["side"]) {
      ValidateAt(src, item, path, [&] {
        wrap.side = ParseWrapSide(yaml::ReadString(src, side, Join(path, "side")));
      });
    }
    ValidateAt(src, item, path, [&] { Validate(wrap); });
    wraps.push_back(std::move(wrap));
  }
  return wraps;
}

Node ReadBodyPoint(const yaml::Source& src, const Document& node, const std::string& path,
                   const std::string& name, const std::vector<Body>& bodies, int dimensions) {
  yaml::RequireMap(src, node, path, {"body", "point"});
  const Document& body = yaml::Required(src, node, path, "body");
  const std::string body_name = yaml::ReadString(src, body, Join(path, "body"));
  bool known = false;
  std::string names;
  for (const Body& b : bodies) {
    known = known || b.name == body_name;
    names += (names.empty() ? "" : ", ") + b.name;
  }
  if (!known) {
    yaml::Fail(src, body, Join(path, "body"), body_name,
               bodies.empty() ? "names a body, and the file has no bodies: block"
                              : "names no body; the bodies are: " + names +
                                    " (a point of the ground is a fixed node)");
  }
  const Document& point = yaml::Required(src, node, path, "point");
  const Coordinates p =
      ReadCoordinateList(src, point, Join(path, "point"), dimensions, kPositionRange, "");
  Node result;
  ValidateAt(src, node, path, [&] { result = Node::OnBody(name, body_name, p); });
  return result;
}

}  // namespace musclesim
