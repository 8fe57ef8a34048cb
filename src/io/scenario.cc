// Reads scenario files: LoadScenario and the `--set` overrides applied before validation.
#include <cmath>

#include "io/key_path.h"
#include "io/model_yaml_node.h"
#include "musclesim/io/scenario.h"

namespace musclesim {

RunRequest ScenarioSpec::Request() const {
  RunRequest r;
  r.t_start = t_start;
  r.t_end = t_end;
  r.length = initial_length;
  r.lengthening_rate = initial_lengthening_rate;
  r.output_interval = output.every_step ? 0.0 : output.interval;
  r.min_length = min_length;
  r.max_length = max_length;
  return r;
}

double ScenarioSpec::PhaseTolerance() const {
  return output.phase_tolerance.value_or(model.params.velocity.epsilon);
}

namespace {

using yaml::Join;
using yaml::ReadOptionalNumber;
using yaml::Required;
using yaml::ValidateAt;

Waveform ReadWaveform(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                      WaveformKind kind) {
  Waveform w;
  w.kind = kind;
  const auto number = [&](const char* key) {
    return yaml::ReadNumber(src, Required(src, node, path, key), Join(path, key));
  };
  switch (kind) {
    case WaveformKind::kConstant:
      yaml::RequireMap(src, node, path, {"type", "value"});
      w.value = number("value");
      break;
    case WaveformKind::kStep:
      yaml::RequireMap(src, node, path, {"type", "time", "before", "after"});
      w.time = number("time");
      w.before = number("before");
      w.after = number("after");
      break;
    case WaveformKind::kRamp:
      yaml::RequireMap(src, node, path, {"type", "start", "end", "from", "to"});
      w.start = number("start");
      w.end = number("end");
      w.from = number("from");
      w.to = number("to");
      break;
    case WaveformKind::kSine:
      yaml::RequireMap(src, node, path, {"type", "offset", "amplitude", "frequency", "phase"});
      w.offset = number("offset");
      w.amplitude = number("amplitude");
      w.frequency = number("frequency");
      w.phase = ReadOptionalNumber(src, node, path, "phase", 0.0);
      break;
    case WaveformKind::kPulses:
      yaml::RequireMap(src, node, path, {"type", "start", "period", "width", "low", "high"});
      w.start = number("start");
      w.period = number("period");
      w.width = number("width");
      w.low = number("low");
      w.high = number("high");
      break;
    case WaveformKind::kTable: {
      yaml::RequireMap(src, node, path, {"type", "points"});
      const YAML::Node points = Required(src, node, path, "points");
      if (!points.IsSequence()) {
        yaml::Fail(src, points, Join(path, "points"), yaml::Describe(points),
                   "must be a list of [t, value] pairs");
      }
      for (std::size_t i = 0; i < points.size(); ++i) {
        const std::vector<double> pair = yaml::ReadNumbers(
            src, points[i], Join(path, "points") + "[" + std::to_string(i) + "]", 2);
        w.points.push_back({pair[0], pair[1]});
      }
      break;
    }
  }
  return w;
}

std::string ReadType(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) yaml::Fail(src, node, path, yaml::Describe(node), "must be a map with a type");
  return yaml::ReadString(src, Required(src, node, path, "type"), Join(path, "type"));
}

Waveform ReadActivation(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  const std::string type = ReadType(src, node, path);
  WaveformKind kind{};
  ValidateAt(src, node, path, [&] { kind = ParseWaveformKind(type); });
  Waveform w = ReadWaveform(src, node, path, kind);
  ValidateAt(src, node, path, [&] { ValidateActivation(w); });
  return w;
}

Load ReadLoad(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  const std::string type = ReadType(src, node, path);
  Load load;
  if (type == "spring") {
    yaml::RequireMap(src, node, path, {"type", "stiffness", "anchor"});
    load.kind = LoadKind::kSpring;
    load.stiffness = yaml::ReadNumber(src, Required(src, node, path, "stiffness"),
                                      Join(path, "stiffness"));
    load.anchor =
        yaml::ReadNumber(src, Required(src, node, path, "anchor"), Join(path, "anchor"));
  } else if (type == "mass") {
    yaml::RequireMap(src, node, path, {"type", "mass", "gravity"});
    load.kind = LoadKind::kMass;
    load.mass = yaml::ReadNumber(src, Required(src, node, path, "mass"), Join(path, "mass"));
    load.gravity = ReadOptionalNumber(src, node, path, "gravity", 9.81);
  } else {
    WaveformKind kind{};
    try {
      kind = ParseWaveformKind(type);
    } catch (const ParameterError&) {
      yaml::Fail(src, node["type"], Join(path, "type"), type,
                 "must be one of constant, step, ramp, sine, pulses, table, spring, mass");
    }
    load.kind = LoadKind::kForce;
    load.force = ReadWaveform(src, node, path, kind);
  }
  ValidateAt(src, node, path, [&] { Validate(load); });
  return load;
}

// Pulse trains and tables become stop times: refuse counts that could never run.
void CheckBreakpointCount(const yaml::Source& src, const YAML::Node& node,
                          const std::string& path, const Waveform& w, double t_end) {
  if (w.kind == WaveformKind::kPulses && (t_end - w.start) / w.period > 5e6) {
    yaml::Fail(src, node["period"], Join(path, "period"), FormatNumber(w.period),
               "gives more than 5 million pulses between the start and time.end");
  }
}

void ReadSolver(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                SolverOptions& o) {
  yaml::RequireMap(src, node, path,
                   {"method", "rtol", "atol", "jacobian", "max_step", "max_steps"});
  if (node["method"]) {
    const std::string text = yaml::ReadString(src, node["method"], Join(path, "method"));
    ValidateAt(src, node, path, [&] { o.method = ParseIntegrationMethod(text); });
  }
  if (node["jacobian"]) {
    const std::string text = yaml::ReadString(src, node["jacobian"], Join(path, "jacobian"));
    ValidateAt(src, node, path, [&] { o.jacobian = ParseJacobianKind(text); });
  }
  o.rtol = ReadOptionalNumber(src, node, path, "rtol", o.rtol);
  o.atol = ReadOptionalNumber(src, node, path, "atol", o.atol);
  o.max_step = ReadOptionalNumber(src, node, path, "max_step", o.max_step);
  if (node["max_steps"]) {
    const double steps = yaml::ReadNumber(src, node["max_steps"], Join(path, "max_steps"));
    if (!(steps >= 1.0 && steps <= 1e12) || steps != std::floor(steps)) {
      yaml::Fail(src, node["max_steps"], Join(path, "max_steps"), yaml::Describe(node["max_steps"]),
                 "must be an integer from 1 to 1e12");
    }
    o.max_steps = static_cast<long>(steps);
  }
  ValidateAt(src, node, path, [&] { Validate(o); });
}

void ReadOutput(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                ScenarioSpec& s) {
  yaml::RequireMap(src, node, path, {"file", "interval", "phase_tolerance"});
  if (node["file"]) {
    s.output.file = yaml::ReadString(src, node["file"], Join(path, "file"));
    if (s.output.file.empty()) {
      yaml::Fail(src, node["file"], Join(path, "file"), "\"\"", "must not be empty");
    }
  }
  const double span = s.t_end - s.t_start;
  s.output.interval = span / 1000.0;
  if (const YAML::Node interval = node["interval"]) {
    if (interval.IsScalar() && interval.Scalar() == "steps") {
      s.output.every_step = true;
      s.output.interval = 0.0;
    } else {
      s.output.interval = yaml::ReadNumber(src, interval, Join(path, "interval"));
      if (!(std::isfinite(s.output.interval) && s.output.interval > 0.0) ||
          span / s.output.interval > 1e8) {
        yaml::Fail(src, interval, Join(path, "interval"), yaml::Describe(interval),
                   "must be `steps` or a time > 0 [s] giving at most 1e8 rows");
      }
    }
  }
  if (const YAML::Node tol = node["phase_tolerance"]) {
    s.output.phase_tolerance = yaml::ReadNumber(src, tol, Join(path, "phase_tolerance"));
    if (!(std::isfinite(*s.output.phase_tolerance) && *s.output.phase_tolerance >= 0.0)) {
      yaml::Fail(src, tol, Join(path, "phase_tolerance"), yaml::Describe(tol),
                 "must be finite and >= 0 [m/s]");
    }
  }
}

ScenarioSpec ReadScenario(const yaml::Source& src, const YAML::Node& root) {
  yaml::RequireMap(src, root, "", kScenarioKeys);
  ScenarioSpec s;
  s.source = src.file;
  if (root["name"]) s.name = yaml::ReadString(src, root["name"], "name");
  s.model = ReadModelSpec(src, Required(src, root, "", "model"), "model");

  const YAML::Node actuator = Required(src, root, "", "actuator");
  yaml::RequireMap(src, actuator, "actuator", {"mass", "damping", "stiffness", "rest_length"});
  s.actuator.mass =
      yaml::ReadNumber(src, Required(src, actuator, "actuator", "mass"), "actuator.mass");
  s.actuator.damping = ReadOptionalNumber(src, actuator, "actuator", "damping", 0.0);
  s.actuator.stiffness = ReadOptionalNumber(src, actuator, "actuator", "stiffness", 0.0);
  s.actuator.rest_length = ReadOptionalNumber(src, actuator, "actuator", "rest_length", 0.0);
  ValidateAt(src, actuator, "actuator", [&] { Validate(s.actuator); });

  const YAML::Node time = Required(src, root, "", "time");
  yaml::RequireMap(src, time, "time", {"start", "end"});
  s.t_start = yaml::ReadNumber(src, Required(src, time, "time", "start"), "time.start");
  s.t_end = yaml::ReadNumber(src, Required(src, time, "time", "end"), "time.end");
  if (!std::isfinite(s.t_start)) {
    yaml::Fail(src, time["start"], "time.start", yaml::Describe(time["start"]), "must be finite [s]");
  }
  if (!(std::isfinite(s.t_end) && s.t_end > s.t_start)) {
    yaml::Fail(src, time["end"], "time.end", yaml::Describe(time["end"]),
               "must be finite and greater than time.start = " + FormatNumber(s.t_start));
  }

  const YAML::Node initial = Required(src, root, "", "initial");
  yaml::RequireMap(src, initial, "initial", {"length", "lengthening_rate"});
  const YAML::Node length = Required(src, initial, "initial", "length");
  s.initial_length = yaml::ReadNumber(src, length, "initial.length");
  s.initial_lengthening_rate = ReadOptionalNumber(src, initial, "initial", "lengthening_rate", 0.0);
  if (!(std::isfinite(s.initial_length) && s.initial_length > 0.0)) {
    yaml::Fail(src, length, "initial.length", yaml::Describe(length), "must be finite and > 0 [m]");
  }
  if (!std::isfinite(s.initial_lengthening_rate)) {
    yaml::Fail(src, initial["lengthening_rate"], "initial.lengthening_rate",
               yaml::Describe(initial["lengthening_rate"]), "must be finite [m/s]");
  }

  const YAML::Node activation = Required(src, root, "", "activation");
  s.activation = ReadActivation(src, activation, "activation");
  CheckBreakpointCount(src, activation, "activation", s.activation, s.t_end);

  if (const YAML::Node load = root["load"]) {
    if (load.IsMap()) {
      s.loads.push_back(ReadLoad(src, load, "load"));
      if (s.loads.back().kind == LoadKind::kForce) {
        CheckBreakpointCount(src, load, "load", s.loads.back().force, s.t_end);
      }
    } else if (load.IsSequence()) {
      for (std::size_t i = 0; i < load.size(); ++i) {
        const std::string at = "load[" + std::to_string(i) + "]";
        s.loads.push_back(ReadLoad(src, load[i], at));
        if (s.loads.back().kind == LoadKind::kForce) {
          CheckBreakpointCount(src, load[i], at, s.loads.back().force, s.t_end);
        }
      }
    } else {
      yaml::Fail(src, load, "load", yaml::Describe(load), "must be one load (a map) or a list of loads");
    }
  }

  if (const YAML::Node solver = root["solver"]) ReadSolver(src, solver, "solver", s.solver);
  if (const YAML::Node output = root["output"]) {
    ReadOutput(src, output, "output", s);
  } else {
    s.output.interval = (s.t_end - s.t_start) / 1000.0;
  }

  if (const YAML::Node limits = root["limits"]) {
    yaml::RequireMap(src, limits, "limits", {"min_length", "max_length"});
    for (const char* key : {"min_length", "max_length"}) {
      if (!limits[key]) continue;
      const std::string path = Join("limits", key);
      const double value = yaml::ReadNumber(src, limits[key], path);
      const bool is_min = std::string(key) == "min_length";
      const bool ok = std::isfinite(value) && (is_min ? value < s.initial_length && value >= 0.0
                                                      : value > s.initial_length);
      if (!ok) {
        yaml::Fail(src, limits[key], path, yaml::Describe(limits[key]),
                   std::string(is_min ? "must be >= 0 and below" : "must be above") +
                       " initial.length = " + FormatNumber(s.initial_length) + " [m]");
      }
      (is_min ? s.min_length : s.max_length) = value;
    }
  }
  return s;
}

void ApplyOverride(YAML::Node root, const std::string& text, const std::string& file) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    throw InputError("--set " + text + ": expected KEY=VALUE, e.g. model.velocity.n=4");
  }
  const std::string path = text.substr(0, eq);
  const std::string value = text.substr(eq + 1);
  const auto split = yaml::SplitKeyPath(path);
  if (!split || split->empty()) {
    throw InputError("--set " + text + ": '" + path +
                     "' is not a dotted key path such as model.velocity.n or load[0].value");
  }
  const std::vector<yaml::KeyPathStep>& steps = *split;
  YAML::Node node = root;  // handles share the document: assignment below edits it
  std::string walked;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const yaml::KeyPathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    const std::string here = step.key.empty()
                                 ? walked + "[" + std::to_string(step.index) + "]"
                                 : (walked.empty() ? step.key : walked + "." + step.key);
    YAML::Node next;
    if (step.key.empty()) {
      if (node.IsMap() && step.index == 0) {
        next.reset(node);  // a single load written as a map is load[0]
      } else if (!node.IsSequence() || step.index >= node.size()) {
        throw InputError("--set " + text + ": " + here + " does not exist in " + file);
      } else {
        next.reset(node[step.index]);
      }
    } else {
      if (!node.IsMap()) {
        throw InputError("--set " + text + ": " + (walked.empty() ? "the file" : walked) +
                         " is not a map in " + file);
      }
      if (!node[step.key] && !last) {
        throw InputError("--set " + text + ": " + here + " does not exist in " + file);
      }
      if (last) {
        if (node[step.key] && !node[step.key].IsScalar() && !node[step.key].IsNull()) {
          throw InputError("--set " + text + ": " + here +
                           " is a map or list; --set replaces single values only");
        }
        node[step.key] = YAML::Node(value);
        return;
      }
      next.reset(node[step.key]);
    }
    if (last) {
      if (!next.IsScalar()) {
        throw InputError("--set " + text + ": " + here +
                         " is a map or list; --set replaces single values only");
      }
      next = YAML::Node(value);
      return;
    }
    node.reset(next);
    walked = here;
  }
}

}  // namespace

struct ScenarioTemplate::Parsed {
  YAML::Node root;
};

ScenarioTemplate::ScenarioTemplate(const std::string& path)
    : ScenarioTemplate(path, yaml::ReadText(path)) {}

ScenarioTemplate::ScenarioTemplate(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)),
      parsed_(std::make_unique<Parsed>(Parsed{yaml::Parse(path_, text_)})) {}

ScenarioTemplate::~ScenarioTemplate() = default;

std::unique_ptr<ScenarioTemplate> ScenarioTemplate::Copy() const {
  return std::unique_ptr<ScenarioTemplate>(new ScenarioTemplate(path_, text_));
}

ScenarioSpec ScenarioTemplate::Instantiate(const std::vector<std::string>& overrides) const {
  if (overrides.empty()) return ReadScenario(yaml::Source{path_}, parsed_->root);
  YAML::Node root = YAML::Clone(parsed_->root);  // overrides must not touch the template
  for (const std::string& text : overrides) ApplyOverride(root, text, path_);
  return ReadScenario(yaml::Source{path_}, root);
}

ScenarioSpec LoadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  return ScenarioTemplate(path).Instantiate(overrides);
}

}  // namespace musclesim
