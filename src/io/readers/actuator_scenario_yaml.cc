// Reads the single-actuator form of a scenario file into its network (docs/model.md 7.4).
#include <cmath>

#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/actuator_fields.h"
#include "musclesim/model/passive.h"
#include "io/readers/model_yaml_node.h"
#include "io/readers/part_fields_yaml.h"
#include "io/readers/scenario_fields.h"
#include "io/readers/scenario_readers.h"

namespace musclesim {

namespace {

using yaml::Required;
using yaml::ValidateAt;

void ReadLimits(const yaml::Source& src, const Document& limits, ActuatorScenarioSpec& s) {
  yaml::RequireMap(src, limits, "limits", {"min_length", "max_length"});
  if (const Document& min = limits["min_length"]) {
    const double value = yaml::ReadNumber(src, min, "limits.min_length");
    if (!(value >= 0.0 && value < s.initial_length)) {
      yaml::Fail(
          src, min, "limits.min_length", yaml::Describe(min),
          "must be >= 0 and below initial.length = " + FormatNumber(s.initial_length) + " [m]");
    }
    s.min_length = value;
  }
  if (const Document& max = limits["max_length"]) {
    const double value = yaml::ReadNumber(src, max, "limits.max_length");
    if (!(value > s.initial_length && value <= kLengthRange.max)) {
      yaml::Fail(src, max, "limits.max_length", yaml::Describe(max),
                 "must be above initial.length = " + FormatNumber(s.initial_length) +
                     " and at most 1000 [m]: " + kLengthRange.why);
    }
    // the run may reach this length: the passive exponential must stay finite up to it
    const double passive = PassiveTension(s.model.params.passive, value).value;
    if (!std::isfinite(passive)) {
      yaml::Fail(src, max, "limits.max_length", yaml::Describe(max),
                 "is a length the run may reach, and there the passive tension overflows (" +
                     FormatNumber(passive) +
                     " N): model.passive.alpha times the stretch must stay below about 700");
    }
    s.max_length = value;
  }
}

}  // namespace

ActuatorScenarioSpec ReadActuatorScenarioSpec(const yaml::Source& src, const Document& root) {
  yaml::RequireMap(src, root, "", kScenarioKeys);
  ActuatorScenarioSpec s;
  s.source = src.file;
  if (root["name"]) s.name = yaml::ReadString(src, root["name"], "name");
  s.model = ReadModelSpec(src, Required(src, root, "", "model"), "model");

  const Document& actuator = Required(src, root, "", "actuator");
  yaml::RequireMap(src, actuator, "actuator", VariantKeys(ActuatorBlock(), "actuator"));
  ReadFields(src, actuator, "actuator", ActuatorBlock().front(), s.actuator);
  ValidateAt(src, actuator, "actuator", [&] { Validate(s.actuator); });
  // before what needs it: the shortest interval, step and pulse are measured against it
  const TimeSpan time = ReadTime(src, Required(src, root, "", "time"));
  s.t_start = time.start;
  s.t_end = time.end;

  const Document& initial = Required(src, root, "", "initial");
  yaml::RequireMap(src, initial, "initial", {"length", "lengthening_rate", "activation"});
  s.initial_length = yaml::ReadNumberIn(src, Required(src, initial, "initial", "length"),
                                        "initial.length", kLengthRange);
  s.initial_lengthening_rate =
      yaml::ReadOptionalNumberIn(src, initial, "initial", "lengthening_rate", kSpeedRange, 0.0);
  // the passive exponential must be finite where the run starts
  if (const double passive = PassiveTension(s.model.params.passive, s.initial_length).value;
      !std::isfinite(passive)) {
    yaml::Fail(src, initial["length"], "initial.length", yaml::Describe(initial["length"]),
               "there the passive tension overflows (" + FormatNumber(passive) +
                   " N): model.passive.alpha times the stretch beyond slack_length must stay "
                   "below about 700");
  }

  ActuatorDrive drive = ReadActuatorDrive(src, root, "", initial["activation"],
                                          "initial.activation", s.t_start, s.t_end);
  s.activation = std::move(drive.activation);
  s.excitation = std::move(drive.excitation);

  if (const Document& load = root["load"]) {
    const auto read = [&](const Document& node, const std::string& at) {
      s.loads.push_back(ReadLoad(src, node, at));
      if (s.loads.back().kind == LoadKind::kForce) {
        CheckPulses(src, node, at, s.loads.back().force, s.t_start, s.t_end);
      }
    };
    if (load.IsMap()) {
      read(load, "load");
    } else if (load.IsSequence()) {
      for (std::size_t i = 0; i < load.size(); ++i)
        read(load[i], "load[" + std::to_string(i) + "]");
    } else {
      yaml::Fail(src, load, "load", yaml::Describe(load),
                 "must be one load (a map) or a list of loads");
    }
  }

  if (const Document& solver = root["solver"]) {
    s.solver = ReadSolver(src, solver, "solver", s.t_start, s.t_end);
  }
  if (const Document& output = root["output"]) {
    s.output = ReadOutput(src, output, "output", s.t_start, s.t_end);
  } else {
    s.output.interval = (s.t_end - s.t_start) / 1000.0;
  }
  if (const Document& limits = root["limits"]) ReadLimits(src, limits, s);
  if (const Document& list = root["sensitivities"]) {
    ReadSensitivities(src, list, s.sensitivities, s.sensitivities_at);
  }
  return s;
}

Scenario ReadActuatorScenario(const yaml::Source& src, const Document& root) {
  ActuatorScenarioSpec spec = ReadActuatorScenarioSpec(src, root);
  Scenario scenario;
  // every part was validated as it was read; what is left is how they fit
  yaml::ValidateAt(src, root, "", [&] { scenario = MakeActuatorScenario(std::move(spec)); });
  return scenario;
}

}  // namespace musclesim
