// Private: reads a network scenario's `controllers` list (docs/model.md section 11) into the
// Controllers of dynamics/controller.h, and the actuators they drive. A driven actuator's
// activation (or, with activation_dynamics, its excitation) is its controller's output, so
// in the file it has neither `activation:` nor `excitation:`. Each controller is validated
// on its own here; how it fits the network (names resolved, one controller per actuator, no
// algebraic loop) is NetworkSystem's to check, whose errors the caller relocates.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/readers/yaml_fields.h"
#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/network_parts.h"

namespace musclesim {

// The controller that drives an actuator, as messages name it: controllers[index] (name).
struct ControllerRef {
  std::size_t index = 0;
  std::string name;
};

// The actuators the controllers name (`drives`, `co_contraction.actuators`), by name. An
// actuator named twice keeps its first controller: NetworkSystem refuses the second.
using DrivenActuators = std::map<std::string, ControllerRef>;

// `node` is the value of `controllers` (a list); pulses are checked against [t_start, t_end].
// A measured node's `coordinate` (x, y, z) is required in 2 or 3 `dimensions` and optional on
// a line, where it can only be x; an element's measure has none.
std::vector<Controller> ReadControllers(const yaml::Source& src, const Document& node,
                                        int dimensions, double t_start, double t_end);

DrivenActuators DrivenActuatorsOf(const std::vector<Controller>& controllers);

// The actuator at `item` (key path `path`, its name, nodes and model already read) that
// `driver` drives: Element::ControlledActuator, with activation dynamics when the map has
// `activation_dynamics` (and `initial_activation`, by default 0). An `activation` or
// `excitation` key is an InputError naming the controller.
Element ReadControlledActuator(const yaml::Source& src, const Document& item,
                               const std::string& path, const std::string& name,
                               const std::string& from, const std::string& to,
                               std::shared_ptr<const TensionModel> model,
                               const ControllerRef& driver);

}  // namespace musclesim
