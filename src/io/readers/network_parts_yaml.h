// Private: reads the lists of a network scenario (`nodes`, `elements`, `loads`, `limits`)
// into the parts of dynamics/network_parts.h. Each part is validated on its own here, with
// file:line:column; how the parts fit together (names unique, references resolved, nothing
// floating) is NetworkSystem's to check, whose errors the caller relocates.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/readers/controller_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/dynamics/skeleton_parts.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// The tension models an actuator may name, by name, and the names in the file's order
// (for messages listing them).
struct NamedModels {
  std::map<std::string, std::shared_ptr<const TensionModel>> by_name;
  std::vector<std::string> names;
};

// Requires `node`, the value of the top-level key `list`, to be a list of `what`.
void RequireList(const yaml::Source& src, const Document& node, const char* list, const char* what);

// The space of the top-level map `root` (docs/model.md 12): `dimensions`, 1, 2 or 3 (1 when
// absent), and `gravity`, a list of `dimensions` numbers [m/s^2] (zero when absent; refused
// on a line, where a hanging weight is a load of type mass).
Space ReadSpace(const yaml::Source& src, const Document& root);

// `node` is the value of `nodes` (a list), in a space of `dimensions`: a coordinate (`fixed`,
// `position`, `velocity`) is a number on a line and a list of `dimensions` numbers otherwise,
// as a prescribed node's `prescribed` is one motion or a list of one per coordinate.
// Prescribed motions must be continuous.
std::vector<Node> ReadNodes(const yaml::Source& src, const Document& node, int dimensions);

// `node` is the value of `elements` (a list); an actuator's `model` must name one of `models`.
// An actuator `driven` names is a controlled one (ReadControlledActuator). In 2 or 3
// `dimensions` an element may pass through `via` points, each a node's name (resolved by
// NetworkSystem) or a list of `dimensions` coordinates; on a line `via` is refused. An end or
// via point given as a point of one of `bodies` ({body, point}) is a node of its own, added
// to `body_points` (ELEMENT.from, ELEMENT.to, ELEMENT.via1, ...).
std::vector<Element> ReadElements(const yaml::Source& src, const Document& node,
                                  const NamedModels& models, const DrivenActuators& driven,
                                  int dimensions, double t_start, double t_end,
                                  const std::vector<Body>& bodies = {},
                                  std::vector<Node>* body_points = nullptr);

// `node` is the value of `loads` (a list of loads, each with the `node` it acts on). In 2 or
// 3 `dimensions` each has a `direction`, a list of `dimensions` numbers, not all zero; on a
// line `direction` is refused.
std::vector<NodeLoad> ReadNodeLoads(const yaml::Source& src, const Document& node, int dimensions,
                                    double t_start, double t_end);

// `node` is the value of `limits` (a list); each limit's element must be one of `system`'s
// and its lengths must lie on either side of that element's length at t_start.
std::vector<LengthLimit> ReadLengthLimits(const yaml::Source& src, const Document& node,
                                          const NetworkSystem& system, double t_start);

}  // namespace musclesim
