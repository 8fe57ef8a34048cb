#include "io/readers/controller_yaml.h"

#include <algorithm>
#include <string_view>
#include <utility>

#include "io/readers/network_parts_yaml.h"
#include "io/readers/part_fields_yaml.h"
#include "io/readers/scenario_fields.h"
#include "io/readers/signal_fields_yaml.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/controller_gains.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::Required;
using yaml::ValidateAt;

// A node's measured coordinate, `coordinate: x` (y, z): optional on a line, where it can
// only be x, required in 2 or 3 `dimensions`.
int ReadCoordinate(const yaml::Source& src, const Document& node, const std::string& at,
                   int dimensions) {
  const std::string path = Join(at, "coordinate");
  const Document& coordinate = node["coordinate"];
  const std::string names = dimensions == 1 ? "x" : dimensions == 2 ? "x or y" : "x, y or z";
  if (!coordinate) {
    if (dimensions == 1) return Measurement::kNoCoordinate;
    // told as Required tells a missing key, at the map that lacks it
    throw InputError(InputFault{
        yaml::Place(src, node), path, std::nullopt,
        "missing required key: in " + std::to_string(dimensions) +
            " dimensions a node's measured position is one coordinate (coordinate: " + names +
            ")"});
  }
  const std::string text = yaml::ReadString(src, coordinate, path);
  int c = Measurement::kNoCoordinate;
  ValidateAt(src, node, at, [&] { c = ParseCoordinate(text); });
  if (c >= dimensions) {
    yaml::Fail(src, coordinate, path, text,
               "is beyond the scenario's coordinates (" + names +
                   "): the scenario has dimensions: " + std::to_string(dimensions));
  }
  return c;
}

Measurement ReadMeasurement(const yaml::Source& src, const Document& item, const std::string& path,
                            int dimensions) {
  const Document& node = Required(src, item, path, "measure");
  const std::string at = Join(path, "measure");
  std::vector<std::string> keys = NameKeys(MeasureNames(), false);
  keys.insert(keys.end(), {"quantity", "coordinate"});
  yaml::RequireMap(src, node, at, keys);
  if (static_cast<bool>(node["element"]) == static_cast<bool>(node["node"])) {
    yaml::Fail(src, node, at, yaml::Describe(node),
               "give exactly one of element (its quantity length or tension) or node (its "
               "quantity position)");
  }
  Measurement m;
  ReadNames(src, node, at, MeasureNames(), m);
  if (node["element"]) {
    if (const Document& coordinate = node["coordinate"]) {
      yaml::Fail(src, coordinate, Join(at, "coordinate"), yaml::Describe(coordinate),
                 "only a node's position has coordinates: an element's length and tension are "
                 "numbers");
    }
  } else {
    m.coordinate = ReadCoordinate(src, node, at, dimensions);
  }
  const Document& quantity = Required(src, node, at, "quantity");
  const std::string text = yaml::ReadString(src, quantity, Join(at, "quantity"));
  ValidateAt(src, node, at, [&] { m.quantity = ParseMeasuredQuantity(text); });
  return m;
}

PidGains ReadGains(const yaml::Source& src, const Document& item, const std::string& path) {
  const Document& node = Required(src, item, path, "gains");
  const std::string at = Join(path, "gains");
  yaml::RequireMap(src, node, at, VariantKeys(ControllerGains(), "pid"));
  PidGains gains;
  ReadFields(src, node, at, ControllerGains().front(), gains);
  return gains;
}

// The pair's actuators; its level is one of the controller's signals.
CoContraction ReadCoContraction(const yaml::Source& src, const Document& node,
                                const std::string& at) {
  yaml::RequireMap(src, node, at, {"actuators", "level"});
  const Document& actuators = Required(src, node, at, "actuators");
  const std::string list = Join(at, "actuators");
  if (!actuators.IsSequence() || actuators.size() != 2) {
    yaml::Fail(src, actuators, list, yaml::Describe(actuators),
               "must be a list of two actuators, [FIRST, SECOND]: FIRST takes level + c, "
               "SECOND level - c");
  }
  CoContraction pair;
  pair.first = yaml::ReadString(src, actuators[0], list + "[0]");
  pair.second = yaml::ReadString(src, actuators[1], list + "[1]");
  return pair;
}

Controller ReadController(const yaml::Source& src, const Document& item, const std::string& path,
                          int dimensions, double t_start, double t_end) {
  if (!item.IsMap()) {
    yaml::Fail(src, item, path, yaml::Describe(item),
               "must be a map: {name, type: pid, measure, reference, gains, drives or "
               "co_contraction}");
  }
  std::vector<std::string> keys = NameKeys(ControllerNames(), true);
  keys.emplace_back("measure");
  for (std::string& key : SignalKeys(ControllerSignals())) keys.push_back(std::move(key));
  keys.emplace_back("gains");
  yaml::RequireMap(src, item, path, keys);
  Controller c;
  ReadNames(src, item, path, ControllerNames(), c);
  const Document& type = Required(src, item, path, "type");
  const std::string kind = yaml::ReadString(src, type, Join(path, "type"));
  std::vector<std::string_view> types;
  for (const PartVariant<Controller>& variant : ControllerTypes()) types.push_back(variant.type);
  if (std::find(types.begin(), types.end(), kind) == types.end()) {
    yaml::Fail(src, type, Join(path, "type"), kind, MustBeOneOf(types));
  }
  c.measure = ReadMeasurement(src, item, path, dimensions);
  c.gains = ReadGains(src, item, path);
  const Document& drives = item["drives"];
  const Document& pair = item["co_contraction"];
  if (static_cast<bool>(drives) == static_cast<bool>(pair)) {
    yaml::Fail(src, item, path, drives ? "drives and co_contraction" : "neither",
               "give exactly one of drives (the actuator driven) or co_contraction "
               "({actuators: [FIRST, SECOND], level}: an antagonist pair)");
  }
  if (!drives) c.co_contraction = ReadCoContraction(src, pair, Join(path, "co_contraction"));
  // after the measure, whose quantity is the reference's unit, and the pair, which holds its
  // level
  for (const SignalField<Controller>& signal : ControllerSignals()) {
    ReadSignal(src, item, path, signal, c, dimensions, t_start, t_end);
  }
  ValidateAt(src, item, path, [&] { Validate(c); });
  return c;
}

}  // namespace

std::vector<Controller> ReadControllers(const yaml::Source& src, const Document& node,
                                        int dimensions, double t_start, double t_end) {
  RequireList(src, node, "controllers",
              "controllers, each {name, type: pid, measure, reference, gains, drives or "
              "co_contraction}");
  std::vector<Controller> controllers;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = "controllers[" + std::to_string(i) + "]";
    controllers.push_back(ReadController(src, node[i], path, dimensions, t_start, t_end));
  }
  return controllers;
}

DrivenActuators DrivenActuatorsOf(const std::vector<Controller>& controllers) {
  DrivenActuators driven;
  for (std::size_t k = 0; k < controllers.size(); ++k) {
    const Controller& c = controllers[k];
    const ControllerRef ref{k, c.name};
    if (c.co_contraction) {
      driven.emplace(c.co_contraction->first, ref);
      driven.emplace(c.co_contraction->second, ref);
    } else {
      driven.emplace(c.drives, ref);
    }
  }
  return driven;
}

Element ReadControlledActuator(const yaml::Source& src, const Document& item,
                               const std::string& path, const std::string& name,
                               const std::string& from, const std::string& to,
                               std::shared_ptr<const TensionModel> model,
                               const ControllerRef& driver) {
  for (const SignalField<Element>& signal : ActuatorSignals<Element>()) {
    if (const Document& own = item[signal.key]) {
      yaml::Fail(src, own, Join(path, signal.key), yaml::Describe(own),
                 "actuator " + name + " is driven by controllers[" + std::to_string(driver.index) +
                     "] (" + driver.name + "): it has no activation of its own");
    }
  }
  const Document& dynamics = item["activation_dynamics"];
  const Document& initial = item["initial_activation"];
  const std::string initial_path = Join(path, "initial_activation");
  Element e;
  if (!dynamics) {
    if (initial) {
      yaml::Fail(src, initial, initial_path, yaml::Describe(initial),
                 "only with activation_dynamics: without them controllers[" +
                     std::to_string(driver.index) + "] (" + driver.name +
                     ") sets the activation itself, its start included");
    }
    ValidateAt(src, item, path,
               [&] { e = Element::ControlledActuator(name, from, to, std::move(model)); });
    return e;
  }
  const std::string at = Join(path, "activation_dynamics");
  const ActivationDynamics lag = ReadActivationDynamics(src, dynamics, at);
  const double u0 =
      initial ? yaml::ReadNumberIn(src, initial, initial_path, kActivationRange) : 0.0;
  ValidateAt(src, item, path,
             [&] { e = Element::ControlledActuator(name, from, to, std::move(model), lag, u0); });
  return e;
}

}  // namespace musclesim
