// Resolving a key path into a handle: the path split into steps, a single actuator's keys
// translated into its network's (scenario/actuator_scenario.h), then one block at a time
// (scenario/parameter_resolver.h); and the handles' reading and writing of a scenario.
#include "musclesim/scenario/parameter.h"

#include "scenario/parameter_resolver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/scenario/actuator_scenario.h"

namespace musclesim {

// `steps` written back the one way: "load[0].after" for "load[00]after".
std::string Canonical(const std::vector<KeyPathStep>& steps) {
  std::string path;
  for (const KeyPathStep& step : steps) {
    // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::string
    if (step.key.empty()) {
      path.append("[").append(std::to_string(step.index)).append("]");
    } else {
      if (!path.empty()) path += '.';
      path += step.key;
    }
  }
  return path;
}

Parameter ParameterResolver::Resolve() {
  std::optional<std::vector<KeyPathStep>> steps = SplitKeyPath(given_);
  if (!steps || steps->empty() || steps->front().key.empty()) {
    throw ParameterError(given_, "", "is not a key path such as model.f_iso or load[0].value");
  }
  p_.path_ = Canonical(*steps);
  p_.network_path_ = p_.path_;
  const std::optional<std::string> translated = NetworkPathOf(scenario_, p_.path_);
  if (!translated) Fail("names no key of a single-actuator scenario");
  if (*translated != p_.path_) p_.network_path_ = Canonical(*SplitKeyPath(*translated));
  steps_ = *SplitKeyPath(p_.network_path_);
  Top();
  return std::move(p_);
}

void ParameterResolver::Top() {
  const std::string& top = Key(0);
  if (top == "models") return Model(1);
  if (top == "nodes") return Node(1);
  if (top == "elements") return Element(1);
  if (top == "loads") return Load(1);
  if (top == "controllers") return Controller(1);
  if (top == "gravity") return Gravity(1);
  if (top == "time" || top == "solver" || top == "output" || top == "limits") return Setting(0);
  Fail(
      "names no numeric value of the scenario (a model, node, element, load, controller, "
      "gravity, time, solver, output or limits key)");
}

void ParameterResolver::Gravity(std::size_t i) {
  if (scenario_.space.dimensions == 1) {
    Fail("names nothing in 1 dimension: on a line a weight is a load of type mass");
  }
  const std::size_t c = Coordinate(i, "gravity");
  End(i + 1);
  Number([c](Scenario& s) -> double& { return s.space.gravity[c]; }, &kGravityRange);
}

double Parameter::Get(const Scenario& scenario) const {
  if (!model_.empty()) return model_get_(scenario.models.at(model_).spec);
  return get_(scenario);
}

void Parameter::Check(double value) const {
  Require(std::isfinite(value), path_, value, "must be finite");
  if (integer_) {
    // a model's integers are ints: the largest any of them accepts is far below 1e9
    Require(value == std::floor(value) && std::abs(value) <= (model_.empty() ? 1e15 : 1e9), path_,
            value, "must be an integer");
  }
  if (bounded_ && !range_.Contains(value)) {
    throw ParameterError(path_, FormatNumber(value), range_.Rule());
  }
}

void Parameter::Assign(Scenario& scenario, double value) const {
  if (model_.empty()) return set_(scenario, value);
  ModelSpec& spec = scenario.models.at(model_).spec;
  model_set_(spec, value);
  if (refits_) spec.fit_result.reset();
}

void Parameter::Set(Scenario& scenario, double value) const {
  SetParameters(scenario, {*this}, {value});
}

void SetParameters(Scenario& scenario, const std::vector<Parameter>& parameters,
                   const std::vector<double>& values) {
  for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i].Check(values[i]);
  Scenario saved = scenario;
  try {
    std::vector<std::string> blocks;
    bool others = false;  // a value outside the model blocks
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      parameters[i].Assign(scenario, values[i]);
      const std::string& block = parameters[i].model();
      others = others || block.empty();
      if (!block.empty() && std::find(blocks.begin(), blocks.end(), block) == blocks.end()) {
        blocks.push_back(block);
      }
    }
    for (const std::string& block : blocks) {
      try {
        scenario.RebuildModel(block);
      } catch (const ParameterError& error) {
        throw ParameterError(FileKeyPath(scenario, "models." + block + "." + error.path()),
                             error.value(), error.rule());
      }
    }
    // a model's change breaks no rule of the network's: validate it when more than models move
    if (others) scenario.Validate();
  } catch (...) {
    scenario = std::move(saved);
    throw;
  }
}

Parameter FindParameter(const Scenario& scenario, const std::string& path) {
  return ParameterResolver(scenario, path).Resolve();
}

}  // namespace musclesim
