#include "io/readers/network_parts_yaml.h"

#include <cmath>

#include "io/readers/controller_yaml.h"
#include "io/readers/coordinates_yaml.h"
#include "io/readers/part_fields_yaml.h"
#include "io/readers/scenario_fields.h"
#include "io/readers/signal_fields_yaml.h"
#include "io/readers/skeleton_yaml.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/scenario/element_limits.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::Required;
using yaml::ValidateAt;

std::string Item(const char* list, std::size_t i) {
  return std::string(list) + "[" + std::to_string(i) + "]";
}

Node ReadNode(const yaml::Source& src, const Document& item, const std::string& path,
              int dimensions) {
  if (!item.IsMap()) {
    yaml::Fail(src, item, path, yaml::Describe(item),
               "must be a map: a name and one of fixed, prescribed or mass");
  }
  // a misspelt key first: it would otherwise read as a missing kind
  std::vector<std::string> keys = NameKeys(NodeNames(), false);
  for (std::string& key : VariantKeys(NodeKinds(), "node")) keys.push_back(std::move(key));
  yaml::RequireMap(src, item, path, keys);
  Node node;
  ReadNames(src, item, path, NodeNames(), node);
  // its kind by the key only that kind has: fixed, prescribed or mass
  const NodeVariant& kind = *SelectVariant(src, item, path, NodeKinds(), "node");
  keys = NameKeys(NodeNames(), false);
  AddVariantKeys(kind, keys);
  yaml::RequireMap(src, item, path, keys);
  kind.make(node);
  ReadFields(src, item, path, kind, node, nullptr, dimensions);
  // a motion is continuous, no pulse train: it needs no run span to resolve its edges
  for (const SignalField<Node>& signal : NodeSignals()) {
    ReadSignal(src, item, path, signal, node, dimensions, 0, 0);
  }
  ValidateAt(src, item, path, [&] { Validate(node); });
  return node;
}

std::shared_ptr<const TensionModel> FindModel(const yaml::Source& src, const Document& item,
                                              const std::string& path, const NamedModels& models) {
  const Document& node = Required(src, item, path, "model");
  const std::string name = yaml::ReadString(src, node, Join(path, "model"));
  const auto found = models.by_name.find(name);
  if (found == models.by_name.end()) {
    std::string known;
    for (const std::string& n : models.names) known += (known.empty() ? "" : ", ") + n;
    yaml::Fail(src, node, Join(path, "model"), name,
               known.empty() ? "names no model: the file has no models block"
                             : "names no model; the models are: " + known);
  }
  return found->second;
}

// The keys an element of `type` may have: a misspelt one is an error before any is read. An
// actuator's are its model's and input's, a passive element's its laws' (element_laws.h).
// `via` comes last, so that the messages of files on a line read as they always have.
void RequireElementKeys(const yaml::Source& src, const Document& item, const std::string& path,
                        ElementKind kind, const std::string& type) {
  std::vector<std::string> keys = NameKeys(ElementNames(), true);
  if (kind == ElementKind::kActuator) {
    keys.emplace_back("model");
    for (std::string& key : SignalKeys(ActuatorSignals<Element>())) keys.push_back(std::move(key));
    keys.insert(keys.end(), {"activation_dynamics", "initial_activation"});
  }
  for (std::string& key : VariantKeys(ElementLaws(), type)) keys.push_back(std::move(key));
  keys.emplace_back("via");
  yaml::RequireMap(src, item, path, keys);
}

// An actuator's model and its input: a controller's (`driven` names it), or its own
// activation or excitation.
void ReadActuator(const yaml::Source& src, const Document& item, const std::string& path,
                  const NamedModels& models, const DrivenActuators& driven, double t_start,
                  double t_end, Element& e) {
  e.model = FindModel(src, item, path, models);
  if (const auto driver = driven.find(e.name); driver != driven.end()) {
    e = ReadControlledActuator(src, item, path, e.name, e.from, e.to, e.model, driver->second);
    return;
  }
  if (!item["activation"] && !item["excitation"]) {
    // neither an input of its own nor a controller's: perhaps a misspelt `drives`
    std::string drivers;
    for (const auto& [name, unused] : driven) drivers += (drivers.empty() ? "" : ", ") + name;
    throw InputError(InputFault{
        yaml::Place(src, item), Join(path, "activation"), std::nullopt,
        "missing required key: give activation (u(t) itself) or excitation (e(t), driving u "
        "through activation_dynamics), or name " +
            e.name + " in a controller's drives or co_contraction.actuators" +
            (drivers.empty() ? "" : " (the controllers drive: " + drivers + ")")});
  }
  ActuatorDrive drive = ReadActuatorDrive(src, item, path, item["initial_activation"],
                                          Join(path, "initial_activation"), t_start, t_end);
  e.activation = std::move(drive.activation);
  e.excitation = std::move(drive.excitation);
}

// An element's `via` points: each a node's name (NetworkSystem resolves it) or a fixed
// point, a list of `dimensions` coordinates.
std::vector<ViaPoint> ReadVia(const yaml::Source& src, const Document& node,
                              const std::string& path, int dimensions, const std::string& element,
                              const std::vector<Body>& bodies, std::vector<Node>& body_points) {
  if (dimensions == 1) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               "via points need dimensions: 2 or 3 at the top level (on a line an element runs "
               "straight from `from` to `to`)");
  }
  const std::string point = "a fixed point, a list of " + std::to_string(dimensions) + " numbers " +
                            CoordinateNames(dimensions, "");
  if (!node.IsSequence()) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               "must be a list of via points, each a node's name or " + point);
  }
  std::vector<ViaPoint> via;
  for (std::size_t k = 0; k < node.size(); ++k) {
    const Document& entry = node[k];
    const std::string at = Indexed(path, k);
    if (entry.IsSequence()) {
      via.push_back(
          ViaPoint::Fixed(ReadCoordinateList(src, entry, at, dimensions, kPositionRange, "")));
    } else if (entry.IsMap() && entry["wrap"]) {
      yaml::RequireMap(src, entry, at, {"wrap"});
      via.push_back(ViaPoint::Wrap(yaml::ReadString(src, entry["wrap"], Join(at, "wrap"))));
    } else if (entry.IsMap() && (entry["body"] || entry["point"])) {
      // a point of a body: the node ELEMENT.via1 (counted from 1)
      const std::string name = element + ".via" + std::to_string(k + 1);
      body_points.push_back(ReadBodyPoint(src, entry, at, name, bodies, dimensions));
      via.push_back(ViaPoint::Node(name));
    } else if (entry.IsScalar() && !entry.Scalar().empty()) {
      via.push_back(ViaPoint::Node(entry.Scalar()));
    } else {
      yaml::Fail(src, entry, at, entry.IsScalar() ? "\"\"" : yaml::Describe(entry),
                 "must be a node's name or " + point + ", or a point of a body {body, point}");
    }
  }
  return via;
}

// A load's `direction` in the map `item`: on a line x (the key refused), otherwise a list of
// `dimensions` numbers, not all zero (the system makes it a unit vector).
Coordinates ReadDirection(const yaml::Source& src, const Document& item, const std::string& path,
                          int dimensions) {
  const std::string at = Join(path, "direction");
  if (dimensions == 1) {
    if (const Document& node = item["direction"]) {
      yaml::Fail(src, node, at, yaml::Describe(node),
                 "needs dimensions: 2 or 3 at the top level (on a line a load acts along x)");
    }
    return {1.0, 0.0, 0.0};
  }
  if (!item["direction"]) {
    throw InputError(InputFault{yaml::Place(src, item), at, std::nullopt,
                                "missing required key: in " + std::to_string(dimensions) +
                                    " dimensions a load acts along a direction, a list of " +
                                    std::to_string(dimensions) + " numbers " +
                                    CoordinateNames(dimensions, "d")});
  }
  const Document& node = item["direction"];
  const Coordinates d = ReadCoordinateList(src, node, at, dimensions, kDirectionRange, "d");
  // a length that underflows would make no unit vector either
  if (!(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) > 0.0)) {
    yaml::Fail(src, node, at, yaml::Describe(node),
               "must not be zero: the load acts along it, made a unit vector");
  }
  return d;
}

Element ReadElement(const yaml::Source& src, const Document& item, const std::string& path,
                    const NamedModels& models, const DrivenActuators& driven, int dimensions,
                    double t_start, double t_end, const std::vector<Body>& bodies,
                    std::vector<Node>& body_points) {
  const std::string type = ReadType(src, item, path);
  Element e;
  ValidateAt(src, item, path, [&] { e.kind = ParseElementKind(type); });
  RequireElementKeys(src, item, path, e.kind, type);
  // an end given as a point of a body ({body, point}) is a node of its own, ELEMENT.from or
  // ELEMENT.to (docs/model.md 15.2)
  std::vector<NameField<Element>> names = ElementNames();
  std::erase_if(names, [&](const NameField<Element>& n) {
    return !n.is_own() && item[n.key] && item[n.key].IsMap();
  });
  ReadNames(src, item, path, names, e);
  for (const NameField<Element>& name : ElementNames()) {
    if (name.is_own() || !item[name.key] || !item[name.key].IsMap()) continue;
    const std::string node = e.name + "." + name.key;
    body_points.push_back(
        ReadBodyPoint(src, item[name.key], Join(path, name.key), node, bodies, dimensions));
    name.set(e, node);
  }
  // read before the kind's fields, kept after them: a controlled actuator is made afresh
  std::vector<ViaPoint> via;
  if (const Document& node = item["via"]) {
    via = ReadVia(src, node, Join(path, "via"), dimensions, e.name, bodies, body_points);
  }
  if (e.kind == ElementKind::kActuator) {
    ReadActuator(src, item, path, models, driven, t_start, t_end, e);
  } else {
    const ElementLaw& law = *SelectVariant(src, item, path, ElementLaws(), type);
    law.make(e);
    ReadFields(src, item, path, law, e);
  }
  e.via = std::move(via);
  ValidateAt(src, item, path, [&] { Validate(e); });
  return e;
}

}  // namespace

void RequireList(const yaml::Source& src, const Document& node, const char* list,
                 const char* what) {
  if (!node.IsSequence()) {
    yaml::Fail(src, node, list, yaml::Describe(node), std::string("must be a list of ") + what);
  }
}

Space ReadSpace(const yaml::Source& src, const Document& root) {
  Space space;
  if (const Document& node = root["dimensions"]) {
    const int d = yaml::ReadInteger(src, node, "dimensions");
    if (d < 1 || d > 3) {
      yaml::Fail(src, node, "dimensions", yaml::Describe(node),
                 "must be 1 (a line, the default), 2 (the x-y plane) or 3 (space)");
    }
    space.dimensions = d;
  }
  if (const Document& node = root["gravity"]) {
    if (space.dimensions == 1) {
      yaml::Fail(src, node, "gravity", yaml::Describe(node),
                 "needs dimensions: 2 or 3 at the top level; on a line hang a weight with a "
                 "load of type mass (docs/guide/networks.md)");
    }
    space.gravity = ReadCoordinateList(src, node, "gravity", space.dimensions, kGravityRange, "g");
  }
  ValidateAt(src, root, "", [&] { Validate(space); });
  return space;
}

std::vector<Node> ReadNodes(const yaml::Source& src, const Document& node, int dimensions) {
  RequireList(src, node, "nodes", "nodes, each a name and one of fixed, prescribed or mass");
  std::vector<Node> nodes;
  for (std::size_t i = 0; i < node.size(); ++i) {
    nodes.push_back(ReadNode(src, node[i], Item("nodes", i), dimensions));
  }
  return nodes;
}

std::vector<Element> ReadElements(const yaml::Source& src, const Document& node,
                                  const NamedModels& models, const DrivenActuators& driven,
                                  int dimensions, double t_start, double t_end,
                                  const std::vector<Body>& bodies, std::vector<Node>* body_points) {
  std::vector<Node> unused;  // with no bodies, ReadBodyPoint refuses every point of one
  if (body_points == nullptr) body_points = &unused;
  RequireList(src, node, "elements", "elements, each {name, type, from, to, ...}");
  std::vector<Element> elements;
  for (std::size_t i = 0; i < node.size(); ++i) {
    elements.push_back(ReadElement(src, node[i], Item("elements", i), models, driven, dimensions,
                                   t_start, t_end, bodies, *body_points));
  }
  return elements;
}

std::vector<NodeLoad> ReadNodeLoads(const yaml::Source& src, const Document& node, int dimensions,
                                    double t_start, double t_end) {
  RequireList(src, node, "loads", "loads, each {node, type, ...}");
  std::vector<NodeLoad> loads;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = Item("loads", i);
    const Document& item = node[i];
    NodeLoad load;
    load.load = ReadLoad(src, item, path, {LoadNames().front().key.c_str(), "direction"});
    ReadNames(src, item, path, LoadNames(), load);
    load.direction = ReadDirection(src, item, path, dimensions);
    if (load.load.kind == LoadKind::kForce) {
      CheckPulses(src, item, path, load.load.force, t_start, t_end);
    }
    loads.push_back(std::move(load));
  }
  return loads;
}

std::vector<LengthLimit> ReadLengthLimits(const yaml::Source& src, const Document& node,
                                          const NetworkSystem& system, double t_start) {
  RequireList(src, node, "limits", "limits, each {element, min_length, max_length}");
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  system.InitialState(t_start, y.data());
  std::vector<LengthLimit> limits;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = Item("limits", i);
    const Document& item = node[i];
    yaml::RequireMap(src, item, path, {"element", "min_length", "max_length"});
    LengthLimit limit;
    const Document& element = Required(src, item, path, "element");
    limit.element = yaml::ReadString(src, element, Join(path, "element"));
    const int e = system.FindElement(limit.element);
    if (e < 0) {
      std::string known;
      for (const Element& part : system.elements())
        known += (known.empty() ? "" : ", ") + part.name;
      yaml::Fail(src, element, Join(path, "element"), limit.element,
                 "names no element; the elements are: " + known);
    }
    if (!item["min_length"] && !item["max_length"]) {
      yaml::Fail(src, item, path, yaml::Describe(item), "give min_length, max_length or both [m]");
    }
    const double length = system.Length(e, t_start, y.data());
    const std::string initial =
        limit.element + "'s initial length = " + FormatNumber(length) + " [m]";
    if (const Document& min = item["min_length"]) {
      const double value = yaml::ReadNumber(src, min, Join(path, "min_length"));
      if (!(value >= 0.0 && value < length)) {
        yaml::Fail(src, min, Join(path, "min_length"), yaml::Describe(min),
                   "must be >= 0 and below " + initial);
      }
      limit.min_length = value;
    }
    if (const Document& max = item["max_length"]) {
      const double value = yaml::ReadNumber(src, max, Join(path, "max_length"));
      if (!(value > length && value <= kLengthRange.max)) {
        yaml::Fail(src, max, Join(path, "max_length"), yaml::Describe(max),
                   "must be above " + initial + " and at most 1000 [m]: " + kLengthRange.why);
      }
      // the run may reach this length: its law must stay finite up to it
      const double tension = TensionAtRest(system.elements()[static_cast<std::size_t>(e)], value);
      if (!std::isfinite(tension)) {
        yaml::Fail(src, max, Join(path, "max_length"), yaml::Describe(max),
                   "is a length the run may reach, and there the tension of " + limit.element +
                       " overflows (" + FormatNumber(tension) +
                       " N): an exponential's alpha times its stretch must stay below about 700");
      }
      limit.max_length = value;
    }
    limits.push_back(std::move(limit));
  }
  return limits;
}

}  // namespace musclesim
