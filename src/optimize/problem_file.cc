// LoadProblemFile: the problem file read with io's YAML helpers (file:line:column messages).
#include "musclesim/optimize/problem_file.h"

#include <filesystem>

#include "io/yaml_fields.h"
#include "musclesim/io/scenario_yaml.h"

namespace musclesim {

namespace {

constexpr InputRange kIntervals{1.0, 100000.0, "", "the grid's intervals"};

std::string Item(const char* list, std::size_t i) {
  std::string path = list;
  path.append("[").append(std::to_string(i)).append("]");
  return path;
}

// [lower, upper] with lower <= upper, each within `range`.
std::pair<double, double> ReadBounds(const yaml::Source& src, const YAML::Node& node,
                                     const std::string& path, const InputRange& range) {
  const std::vector<double> bounds = yaml::ReadNumbers(src, node, path, 2);
  for (std::size_t k = 0; k < 2; ++k) {
    yaml::ReadNumberIn(src, node[k], path + "[" + std::to_string(k) + "]", range);
  }
  if (bounds[0] > bounds[1]) {
    yaml::Fail(src, node, path, yaml::Describe(node), "must be [lower, upper] with lower <= upper");
  }
  return {bounds[0], bounds[1]};
}

ControlSpec ReadControl(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  yaml::RequireMap(src, node, path, {"actuator", "bounds", "effort"});
  ControlSpec control;
  control.actuator = yaml::ReadString(src, yaml::Required(src, node, path, "actuator"),
                                      yaml::Join(path, "actuator"));
  if (node["bounds"]) {
    const InputRange unit{0.0, 1.0, "", "an activation"};
    std::tie(control.lower, control.upper) =
        ReadBounds(src, node["bounds"], yaml::Join(path, "bounds"), unit);
  }
  if (const YAML::Node effort = node["effort"]) {
    const std::string at = yaml::Join(path, "effort");
    yaml::RequireMap(src, effort, at, {"weight", "power"});
    const InputRange weights{0.0, 1e12, "", "a weight of the objective"};
    control.effort_weight = yaml::ReadOptionalNumberIn(src, effort, at, "weight", weights, 1.0);
    if (effort["power"]) {
      const int power = yaml::ReadInteger(src, effort["power"], yaml::Join(at, "power"));
      if (power != 2 && power != 3) {
        yaml::Fail(src, effort["power"], yaml::Join(at, "power"), std::to_string(power),
                   "must be 2 (integral of u^2) or 3 (integral of |u|^3)");
      }
      control.effort_power = power;
    }
  }
  return control;
}

FinalValue ReadFinal(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  yaml::RequireMap(src, node, path, {"column", "value", "bounds"});
  FinalValue final;
  final.column =
      yaml::ReadString(src, yaml::Required(src, node, path, "column"), yaml::Join(path, "column"));
  const InputRange any{-1e6, 1e6, "", "a coordinate [m] or velocity [m/s]"};
  if (node["value"] && node["bounds"]) {
    yaml::Fail(src, node["bounds"], yaml::Join(path, "bounds"), yaml::Describe(node["bounds"]),
               "give either value or bounds, not both");
  }
  if (node["value"]) {
    final.lower = final.upper =
        yaml::ReadNumberIn(src, node["value"], yaml::Join(path, "value"), any);
  } else if (node["bounds"]) {
    std::tie(final.lower, final.upper) =
        ReadBounds(src, node["bounds"], yaml::Join(path, "bounds"), any);
  } else {
    throw InputError(path + " (" + yaml::Location(src, node) +
                     "): missing required key: value (an equality) or bounds [lower, upper]");
  }
  return final;
}

}  // namespace

ProblemFile LoadProblemFile(const std::string& path) {
  const yaml::Source src{path};
  const YAML::Node root = yaml::LoadFile(path);
  yaml::RequireMap(src, root, "",
                   {"base", "intervals", "controls", "final_values", "optimizer", "output"});
  ProblemFile file;
  file.path = path;
  const std::string base = yaml::ReadString(src, yaml::Required(src, root, "", "base"), "base");
  file.base = (std::filesystem::path(path).parent_path() / base).lexically_normal().string();
  if (root["intervals"]) {
    const double n = yaml::ReadNumberIn(src, root["intervals"], "intervals", kIntervals);
    if (n != static_cast<double>(static_cast<int>(n))) {
      yaml::Fail(src, root["intervals"], "intervals", yaml::Describe(root["intervals"]),
                 "must be an integer from 1 to 100000");
    }
    file.problem.intervals = static_cast<int>(n);
  }
  const YAML::Node controls = yaml::Required(src, root, "", "controls");
  if (!controls.IsSequence() || controls.size() == 0) {
    yaml::Fail(src, controls, "controls", yaml::Describe(controls),
               "must be a list of at least one control, {actuator: NAME, ...}");
  }
  for (std::size_t j = 0; j < controls.size(); ++j) {
    file.problem.controls.push_back(ReadControl(src, controls[j], Item("controls", j)));
  }
  if (const YAML::Node finals = root["final_values"]) {
    if (!finals.IsSequence()) {
      yaml::Fail(src, finals, "final_values", yaml::Describe(finals),
                 "must be a list of {column: NODE.COLUMN, value: X} or {column, bounds}");
    }
    for (std::size_t k = 0; k < finals.size(); ++k) {
      file.problem.final_values.push_back(ReadFinal(src, finals[k], Item("final_values", k)));
    }
  }
  if (const YAML::Node optimizer = root["optimizer"]) {
    yaml::RequireMap(src, optimizer, "optimizer", {"tolerance", "max_iterations"});
    const InputRange tolerances{1e-14, 1.0, "", "IPOPT's tol"};
    file.options.tolerance =
        yaml::ReadOptionalNumberIn(src, optimizer, "optimizer", "tolerance", tolerances, 1e-8);
    if (optimizer["max_iterations"]) {
      const int n = yaml::ReadInteger(src, optimizer["max_iterations"], "optimizer.max_iterations");
      if (n < 1 || n > 100000) {
        yaml::Fail(src, optimizer["max_iterations"], "optimizer.max_iterations", std::to_string(n),
                   "must be an integer from 1 to 100000");
      }
      file.options.max_iterations = n;
    }
  }
  const std::string stem = std::filesystem::path(path).stem().string();
  file.outputs = {stem + "_optimum.yaml", stem + "_optimum.json", stem + "_optimum.csv"};
  if (const YAML::Node output = root["output"]) {
    yaml::RequireMap(src, output, "output", {"scenario", "summary", "trajectory"});
    for (const auto& [key, target] :
         {std::pair<const char*, std::string*>{"scenario", &file.outputs.scenario},
          {"summary", &file.outputs.summary},
          {"trajectory", &file.outputs.trajectory}}) {
      if (output[key]) *target = yaml::ReadString(src, output[key], yaml::Join("output", key));
    }
  }
  file.problem.scenario = LoadScenario(file.base);
  return file;
}

}  // namespace musclesim
