// Reads network scenario files: the top-level blocks in order, the parts checked one by one,
// then as a whole by building the system, whose ParameterErrors are put back at their keys.
#include <algorithm>
#include <initializer_list>
#include <memory>
#include <string>

#include "io/readers/controller_yaml.h"
#include "io/readers/model_yaml_node.h"
#include "io/readers/network_parts_yaml.h"
#include "io/readers/skeleton_yaml.h"
#include "io/readers/scenario_fields.h"
#include "io/readers/scenario_readers.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

using yaml::Required;

// The top-level keys of a network scenario file; those of the plane and space come last, so
// that the messages of files on a line read as they always have.
constexpr std::initializer_list<const char*> kNetworkKeys = {
    "name",   "models",        "nodes",       "elements",   "loads",   "time",   "solver", "output",
    "limits", "sensitivities", "controllers", "dimensions", "gravity", "bodies", "joints", "wraps"};

NamedModels ReadModels(const yaml::Source& src, const Document& node, Scenario& s) {
  if (!node.IsMap()) {
    yaml::Fail(src, node, "models", yaml::Describe(node),
               "must be a map of named model blocks (name: {f_iso, passive, active_length, "
               "velocity})");
  }
  NamedModels models;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string& name = node.key(i);
    // the reader has validated the block and run its fit: AddModel builds it once more
    ModelSpec spec = ReadModelSpec(src, node.items()[i], "models." + name);
    models.by_name[name] = s.AddModel(name, std::move(spec));
    models.names.push_back(name);
  }
  return models;
}

// The actuators' names in the file's elements list, as written (the elements are read later).
std::vector<std::string> ActuatorNames(const Document& elements) {
  std::vector<std::string> names;
  if (!elements || !elements.IsSequence()) return names;
  for (const Document& item : elements) {
    if (!item.IsMap() || !item["type"] || !item["name"]) continue;
    if (!item["type"].IsScalar() || item["type"].Scalar() != "actuator") continue;
    if (item["name"].IsScalar()) names.push_back(item["name"].Scalar());
  }
  return names;
}

// A controller driving no actuator of the network (a misspelt name) is told at its own key,
// before the actuator it meant is blamed for lacking an input.
void RequireDrivenActuators(const yaml::Source& src, const Document& controllers,
                            const std::vector<Controller>& read, const Document& elements) {
  const std::vector<std::string> actuators = ActuatorNames(elements);
  const auto require = [&](const Document& at, const std::string& path, const std::string& name) {
    if (std::find(actuators.begin(), actuators.end(), name) != actuators.end()) return;
    yaml::Fail(src, at, path, name,
               actuators.empty()
                   ? "must name an actuator, and the network has none"
                   : "must name an actuator of the network: " + CommaSeparated(actuators));
  };
  for (std::size_t k = 0; k < read.size(); ++k) {
    const Document& item = controllers[k];
    const std::string path = "controllers[" + std::to_string(k) + "]";
    if (read[k].co_contraction) {
      const Document& pair = item["co_contraction"]["actuators"];
      const std::string list = path + ".co_contraction.actuators";
      require(pair[0], list + "[0]", read[k].co_contraction->first);
      require(pair[1], list + "[1]", read[k].co_contraction->second);
    } else {
      require(item["drives"], path + ".drives", read[k].drives);
    }
  }
}

}  // namespace

LoadedScenario ReadNetworkScenario(const yaml::Source& src, const Document& root) {
  yaml::RequireMap(src, root, "", kNetworkKeys);
  Scenario s;
  s.source = src.file;
  if (root["name"]) s.name = yaml::ReadString(src, root["name"], "name");
  // before the parts: the dimensions say what a coordinate is
  s.space = ReadSpace(src, root);
  const int dimensions = s.space.dimensions;
  // before what needs it: the shortest interval, step and pulse are measured against it
  const TimeSpan time = ReadTime(src, Required(src, root, "", "time"));
  s.t_start = time.start;
  s.t_end = time.end;

  NamedModels models;
  if (const Document& node = root["models"]) models = ReadModels(src, node, s);
  // before the nodes and elements: their points may be on the bodies
  if (const Document& node = root["bodies"]) s.bodies = ReadBodies(src, node, dimensions);
  if (const Document& node = root["joints"]) s.joints = ReadJoints(src, node, dimensions);
  if (const Document& node = root["wraps"]) s.wraps = ReadWraps(src, node, dimensions);
  // a skeleton needs no node of its own: its paths' points may all be on bodies
  if (!s.bodies.empty() && !root["nodes"]) {
    s.nodes = {};
  } else {
    s.nodes = ReadNodes(src, Required(src, root, "", "nodes"), dimensions);
  }
  // before the elements: an actuator a controller drives has no activation of its own
  if (const Document& node = root["controllers"]) {
    s.controllers = ReadControllers(src, node, dimensions, s.t_start, s.t_end);
    RequireDrivenActuators(src, node, s.controllers, root["elements"]);
  }
  std::vector<Node> body_points;
  if (const Document& node = root["elements"]; node || s.bodies.empty()) {
    s.elements = ReadElements(src, Required(src, root, "", "elements"), models,
                              DrivenActuatorsOf(s.controllers), dimensions, s.t_start, s.t_end,
                              s.bodies, &body_points);
  }
  for (Node& point : body_points) s.nodes.push_back(std::move(point));
  if (const Document& node = root["loads"]) {
    s.loads = ReadNodeLoads(src, node, dimensions, s.t_start, s.t_end);
  }

  // how the parts fit: the system's paths ("elements[2].to", "controllers[0].drives") are the
  // file's key paths
  std::shared_ptr<const NetworkSystem> system;
  yaml::ValidateAt(src, root, "", [&] {
    system = std::make_shared<const NetworkSystem>(s.Build());
    std::vector<double> y(static_cast<std::size_t>(system->state_size()));
    system->InitialState(s.t_start, y.data());
    system->CheckInitialState(s.t_start, y.data());
  });

  if (const Document& node = root["solver"]) {
    s.solver = ReadSolver(src, node, "solver", s.t_start, s.t_end);
    const int states = system->state_size();
    if (s.solver.linear_solver == LinearSolverKind::kSmall && states > kSmallSystemMaxSize) {
      yaml::Fail(src, node["linear_solver"], "solver.linear_solver", "small",
                 "serves at most " + std::to_string(kSmallSystemMaxSize) +
                     " states and this network has " + std::to_string(states) +
                     ": use auto, dense, band or sparse");
    }
  }
  if (const Document& node = root["output"]) {
    s.output = ReadOutput(src, node, "output", s.t_start, s.t_end);
  } else {
    s.output.interval = (s.t_end - s.t_start) / 1000.0;
  }
  if (const Document& node = root["limits"]) {
    s.limits = ReadLengthLimits(src, node, *system, s.t_start);
  }
  if (const Document& node = root["sensitivities"]) {
    ReadSensitivities(src, node, s.sensitivities, s.sensitivities_at);
  }
  return {std::move(s), std::move(system)};
}

}  // namespace musclesim
