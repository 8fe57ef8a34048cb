#include "musclesim/scenario/actuator_scenario.h"

#include <array>
#include <string_view>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

// Each single-actuator key (a prefix ending in '.' or '[', or a whole key) and where the
// network holds it: docs/model.md 7.4 as a table.
struct KeyAlias {
  std::string_view actuator;
  std::string_view network;
};
constexpr std::array<KeyAlias, 15> kAliases = {{
    {"model.", "models.model."},
    {"actuator.mass", "nodes[1].mass"},
    {"actuator.damping", "elements[1].damping"},
    {"actuator.stiffness", "elements[2].stiffness"},
    {"actuator.rest_length", "elements[2].rest_length"},
    {"initial.length", "nodes[1].position"},
    {"initial.lengthening_rate", "nodes[1].velocity"},
    {"initial.activation", "elements[0].initial_activation"},
    {"activation.", "elements[0].activation."},
    {"excitation.", "elements[0].excitation."},
    {"activation_dynamics.", "elements[0].activation_dynamics."},
    {"load[", "loads["},
    {"load.", "loads[0]."},
    {"limits.min_length", "limits[0].min_length"},
    {"limits.max_length", "limits[0].max_length"},
}};

bool IsPrefix(std::string_view key) { return key.back() == '.' || key.back() == '['; }

// `path` with `from` replaced by `to` when `from` heads it (a whole key must match whole).
std::optional<std::string> Replace(const std::string& path, std::string_view from,
                                   std::string_view to) {
  if (path.compare(0, from.size(), from) != 0) return std::nullopt;
  if (!IsPrefix(from) && path.size() != from.size()) return std::nullopt;
  return std::string(to) + path.substr(from.size());
}

// The element factories' and validators' paths, relative to an element or a node, as the
// single-actuator keys.
ParameterError AsActuatorKey(const ParameterError& error, std::string_view owner) {
  std::string path = error.path();
  if (path == "initial_activation") {
    path = "initial.activation";
  } else if (owner == "actuator" || owner == "tip") {
    if (path == "mass" || path == "damping" || path == "stiffness" || path == "rest_length") {
      path = "actuator." + path;
    }
  }
  return ParameterError(path, error.value(), error.rule());
}

template <typename Make>
auto Made(std::string_view owner, Make make) {
  try {
    return make();
  } catch (const ParameterError& error) {
    throw AsActuatorKey(error, owner);
  }
}

}  // namespace

std::optional<std::string> NetworkKeyPath(const std::string& actuator_path) {
  for (const KeyAlias& alias : kAliases) {
    if (auto path = Replace(actuator_path, alias.actuator, alias.network)) return path;
  }
  for (std::string_view same : {"name", "time.", "solver.", "output."}) {
    if (Replace(actuator_path, same, same)) return actuator_path;
  }
  return std::nullopt;
}

std::string ActuatorKeyPath(const std::string& network_path) {
  for (const KeyAlias& alias : kAliases) {
    if (alias.actuator == "load.") continue;  // loads[0] reads back as load[0]
    if (auto path = Replace(network_path, alias.network, alias.actuator)) return *path;
  }
  return network_path;
}

ActuatorSample ActuatorSampleOf(const NetworkSample& s) {
  return ActuatorSampleOf(s.elements[kActuatorElement], s.load[kActuatorTipNode]);
}

ActuatorSample ActuatorSampleOf(const ElementSample& actuator, double load) {
  ActuatorSample sample;
  sample.length = actuator.length;
  sample.shortening_velocity = 0.0 - actuator.lengthening_rate;
  sample.activation = actuator.activation;
  sample.excitation = actuator.excitation;
  sample.tension = actuator.parts;
  sample.load = load;
  return sample;
}

bool IsSingleActuator(const Scenario& scenario) { return scenario.form == ScenarioForm::kActuator; }

std::string FileKeyPath(const Scenario& scenario, const std::string& network_path) {
  return IsSingleActuator(scenario) ? ActuatorKeyPath(network_path) : network_path;
}

std::optional<std::string> NetworkPathOf(const Scenario& scenario, const std::string& path) {
  return IsSingleActuator(scenario) ? NetworkKeyPath(path) : path;
}

std::string ElementColumn(const Scenario& scenario, const std::string& element,
                          const std::string& quantity) {
  return IsSingleActuator(scenario) ? quantity : element + "." + quantity;
}

std::string OfElement(const Scenario& scenario, const std::string& element) {
  return IsSingleActuator(scenario) ? "" : " of " + element;
}

std::string InitialLengthName(const Scenario& scenario) {
  return IsSingleActuator(scenario) ? "initial.length" : "the element's initial length";
}

ActuatorSystem MakeActuatorSystem(const ActuatorScenarioSpec& spec) {
  auto model = std::make_shared<const TensionModel>(spec.model.params);
  return spec.excitation
             ? ActuatorSystem(std::move(model), spec.actuator, *spec.excitation, spec.loads)
             : ActuatorSystem(std::move(model), spec.actuator, spec.activation, spec.loads);
}

RunRequest MakeActuatorRunRequest(const ActuatorScenarioSpec& spec) {
  RunRequest r;
  r.t_start = spec.t_start;
  r.t_end = spec.t_end;
  r.length = spec.initial_length;
  r.lengthening_rate = spec.initial_lengthening_rate;
  r.output_interval = spec.output.every_step ? 0.0 : spec.output.interval;
  r.min_length = spec.min_length;
  r.max_length = spec.max_length;
  return r;
}

Scenario MakeActuatorScenario(ActuatorScenarioSpec spec) {
  Scenario s;
  s.name = std::move(spec.name);
  s.source = std::move(spec.source);
  s.form = ScenarioForm::kActuator;
  std::shared_ptr<const TensionModel> model;
  try {
    model = s.AddModel("model", std::move(spec.model));
  } catch (const ParameterError& error) {
    throw ParameterError("model." + error.path(), error.value(), error.rule());
  }
  const ActuatorParams& a = spec.actuator;
  Made("actuator", [&] {
    Validate(a);
    return 0;
  });
  s.nodes = {Node::Fixed("ground", 0.0), Made("tip", [&] {
               return Node::Free("tip", a.mass, spec.initial_length, spec.initial_lengthening_rate);
             })};
  // the order of docs/model.md 7.4: the network's sum of forces is then the actuator's own
  // F - T - c xdot - k (x - l0), operation for operation
  s.elements.push_back(Made("actuator", [&] {
    return spec.excitation ? Element::Actuator("actuator", "ground", "tip", model, *spec.excitation)
                           : Element::Actuator("actuator", "ground", "tip", model, spec.activation);
  }));
  s.elements.push_back(
      Made("actuator", [&] { return Element::Damper("damper", "ground", "tip", a.damping); }));
  s.elements.push_back(Made("actuator", [&] {
    return Element::Spring("spring", "ground", "tip", a.stiffness, a.rest_length);
  }));
  for (Load& load : spec.loads) s.loads.push_back({"tip", std::move(load)});
  s.t_start = spec.t_start;
  s.t_end = spec.t_end;
  s.solver = spec.solver;
  s.output = std::move(spec.output);
  if (spec.min_length || spec.max_length) {
    s.limits.push_back({"actuator", spec.min_length, spec.max_length});
  }
  s.sensitivities = std::move(spec.sensitivities);
  s.sensitivities_at = std::move(spec.sensitivities_at);
  return s;
}

}  // namespace musclesim
