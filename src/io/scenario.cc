// Reads scenario files: LoadScenario and the `--set` overrides applied before validation.
#include <algorithm>
#include <cmath>

#include "musclesim/io/input_ranges.h"
#include "io/key_path.h"
#include "io/model_yaml_node.h"
#include "io/scenario_node.h"
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

// The time scale of a run [s]: max(1 s, |start|, |end|). The shortest span, interval and
// step are fractions of it (io/input_ranges.h), so that they stay many roundoffs wide.
double TimeScale(double t_start, double t_end) {
  return std::max({1.0, std::abs(t_start), std::abs(t_end)});
}

// Reads one waveform. `values` bounds its values (a force's); nullptr leaves them to
// ValidateActivation, which keeps an activation within [0, 1].
Waveform ReadWaveform(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                      WaveformKind kind, const InputRange* values) {
  Waveform w;
  w.kind = kind;
  const auto value = [&](const char* key) {
    const YAML::Node item = Required(src, node, path, key);
    return values ? yaml::ReadNumberIn(src, item, Join(path, key), *values)
                  : yaml::ReadNumber(src, item, Join(path, key));
  };
  const auto time = [&](const char* key) {
    return yaml::ReadNumberIn(src, Required(src, node, path, key), Join(path, key),
                              kTimeRange);
  };
  const auto number = [&](const char* key) {
    return yaml::ReadNumber(src, Required(src, node, path, key), Join(path, key));
  };
  switch (kind) {
    case WaveformKind::kConstant:
      yaml::RequireMap(src, node, path, {"type", "value"});
      w.value = value("value");
      break;
    case WaveformKind::kStep:
      yaml::RequireMap(src, node, path, {"type", "time", "before", "after"});
      w.time = time("time");
      w.before = value("before");
      w.after = value("after");
      break;
    case WaveformKind::kRamp:
      yaml::RequireMap(src, node, path, {"type", "start", "end", "from", "to"});
      w.start = time("start");
      w.end = time("end");
      w.from = value("from");
      w.to = value("to");
      break;
    case WaveformKind::kSine:
      yaml::RequireMap(src, node, path, {"type", "offset", "amplitude", "frequency", "phase"});
      w.offset = value("offset");
      w.amplitude = value("amplitude");
      w.frequency = yaml::ReadNumberIn(src, Required(src, node, path, "frequency"),
                                       Join(path, "frequency"), kFrequencyRange);
      w.phase = ReadOptionalNumber(src, node, path, "phase", 0.0);
      break;
    case WaveformKind::kPulses:
      yaml::RequireMap(src, node, path, {"type", "start", "period", "width", "low", "high"});
      w.start = time("start");
      w.period = number("period");  // checked against the run's time scale by CheckPulses
      w.width = number("width");
      w.low = value("low");
      w.high = value("high");
      break;
    case WaveformKind::kTable: {
      yaml::RequireMap(src, node, path, {"type", "points"});
      const YAML::Node points = Required(src, node, path, "points");
      const std::string at = Join(path, "points");
      if (!points.IsSequence()) {
        yaml::Fail(src, points, at, yaml::Describe(points), "must be a list of [t, value] pairs");
      }
      if (static_cast<double>(points.size()) > kMaxBreakpoints) {
        yaml::Fail(src, points, at, std::to_string(points.size()) + " points",
                   "at most 5 million: each point is a stop time where the integrator restarts");
      }
      for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string item = at + "[" + std::to_string(i) + "]";
        const std::vector<double> pair = yaml::ReadNumbers(src, points[i], item, 2);
        if (!kTimeRange.Contains(pair[0])) {
          yaml::Fail(src, points[i][0], item + "[0]", yaml::Describe(points[i][0]),
                     kTimeRange.Rule());
        }
        if (values && !values->Contains(pair[1])) {
          yaml::Fail(src, points[i][1], item + "[1]", yaml::Describe(points[i][1]),
                     values->Rule());
        }
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
  Waveform w = ReadWaveform(src, node, path, kind, nullptr);
  ValidateAt(src, node, path, [&] { ValidateActivation(w); });
  return w;
}

Load ReadLoad(const yaml::Source& src, const YAML::Node& node, const std::string& path) {
  const std::string type = ReadType(src, node, path);
  Load load;
  if (type == "spring") {
    yaml::RequireMap(src, node, path, {"type", "stiffness", "anchor"});
    load.kind = LoadKind::kSpring;
    load.stiffness = yaml::ReadNumberIn(src, Required(src, node, path, "stiffness"),
                                        Join(path, "stiffness"), kStiffnessRange);
    load.anchor = yaml::ReadNumberIn(src, Required(src, node, path, "anchor"),
                                     Join(path, "anchor"), kPositionRange);
  } else if (type == "mass") {
    yaml::RequireMap(src, node, path, {"type", "mass", "gravity"});
    load.kind = LoadKind::kMass;
    load.mass = yaml::ReadNumberIn(src, Required(src, node, path, "mass"), Join(path, "mass"),
                                   kMassRange);
    load.gravity =
        yaml::ReadOptionalNumberIn(src, node, path, "gravity", kGravityRange, 9.81);
  } else {
    WaveformKind kind{};
    try {
      kind = ParseWaveformKind(type);
    } catch (const ParameterError&) {
      yaml::Fail(src, node["type"], Join(path, "type"), type,
                 "must be one of constant, step, ramp, sine, pulses, table, spring, mass");
    }
    load.kind = LoadKind::kForce;
    load.force = ReadWaveform(src, node, path, kind, &kForceRange);
  }
  ValidateAt(src, node, path, [&] { Validate(load); });
  return load;
}

// A pulse train's edges become stop times: its period and width must be resolved at the
// run's times, and the run may hold at most kMaxBreakpoints edges.
void CheckPulses(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                 const Waveform& w, double t_start, double t_end) {
  if (w.kind != WaveformKind::kPulses) return;
  const double resolution = kMinIntervalRelative * TimeScale(t_start, t_end);
  for (const char* key : {"period", "width"}) {
    const double value = std::string(key) == "period" ? w.period : w.width;
    if (!(value >= resolution)) {
      yaml::Fail(src, node[key], Join(path, key), yaml::Describe(node[key]),
                 "must be at least " + FormatNumber(resolution) +
                     " s, 1e-12 of the run's time scale max(1 s, |time.start|, |time.end|): "
                     "shorter times are not resolved in double precision");
    }
  }
  if ((t_end - std::max(w.start, t_start)) / w.period > kMaxBreakpoints) {
    yaml::Fail(src, node["period"], Join(path, "period"), FormatNumber(w.period),
               "gives more than 5 million pulses between the start and time.end: each edge is "
               "a stop time where the integrator restarts");
  }
}

void ReadTime(const yaml::Source& src, const YAML::Node& time, ScenarioSpec& s) {
  yaml::RequireMap(src, time, "time", {"start", "end"});
  s.t_start = yaml::ReadNumberIn(src, Required(src, time, "time", "start"), "time.start",
                                 kTimeRange);
  s.t_end = yaml::ReadNumberIn(src, Required(src, time, "time", "end"), "time.end",
                               kTimeRange);
  const double shortest = kMinSpanRelative * TimeScale(s.t_start, s.t_end);
  if (!(s.t_end - s.t_start >= shortest)) {
    yaml::Fail(src, time["end"], "time.end", yaml::Describe(time["end"]),
               "must be greater than time.start = " + FormatNumber(s.t_start) + " by at least " +
                   FormatNumber(shortest) +
                   " s, 1e-9 of the time scale max(1 s, |start|, |end|): room for 1000 output "
                   "rows that double precision tells apart");
  }
}

void ReadSolver(const yaml::Source& src, const YAML::Node& node, const std::string& path,
                ScenarioSpec& s) {
  SolverOptions& o = s.solver;
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
  // a step limit the run could never finish with, or one below the time resolution
  const double span = s.t_end - s.t_start;
  const double shortest = std::max(kMinIntervalRelative * TimeScale(s.t_start, s.t_end),
                                   span / static_cast<double>(o.max_steps));
  if (o.max_step != 0.0 && o.max_step < shortest) {
    yaml::Fail(src, node["max_step"], Join(path, "max_step"), yaml::Describe(node["max_step"]),
               "must be 0 (no limit) or at least " + FormatNumber(shortest) +
                   " s: (time.end - time.start) / solver.max_steps, or else the run cannot "
                   "reach time.end, and 1e-12 of the time scale max(1 s, |start|, |end|), "
                   "below which double precision does not resolve a step");
  }
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
      const double shortest = kMinIntervalRelative * TimeScale(s.t_start, s.t_end);
      if (!(s.output.interval >= shortest && span / s.output.interval <= 1e8)) {
        yaml::Fail(src, interval, Join(path, "interval"), yaml::Describe(interval),
                   "must be `steps` or a time [s] giving at most 1e8 rows (at least " +
                       FormatNumber(span / 1e8) + " s here) and at least " +
                       FormatNumber(shortest) +
                       " s, 1e-12 of the time scale max(1 s, |start|, |end|), so that "
                       "double precision tells the output times apart");
      }
    }
  }
  if (node["phase_tolerance"]) {
    s.output.phase_tolerance = yaml::ReadNumberIn(src, node["phase_tolerance"],
                                                  Join(path, "phase_tolerance"),
                                                  kPhaseToleranceRange);
  }
}

void ReadLimits(const yaml::Source& src, const YAML::Node& limits, ScenarioSpec& s) {
  yaml::RequireMap(src, limits, "limits", {"min_length", "max_length"});
  if (const YAML::Node min = limits["min_length"]) {
    const double value = yaml::ReadNumber(src, min, "limits.min_length");
    if (!(value >= 0.0 && value < s.initial_length)) {
      yaml::Fail(src, min, "limits.min_length", yaml::Describe(min),
                 "must be >= 0 and below initial.length = " + FormatNumber(s.initial_length) +
                     " [m]");
    }
    s.min_length = value;
  }
  if (const YAML::Node max = limits["max_length"]) {
    const double value = yaml::ReadNumber(src, max, "limits.max_length");
    if (!(value > s.initial_length && value <= kLengthRange.max)) {
      yaml::Fail(src, max, "limits.max_length", yaml::Describe(max),
                 "must be above initial.length = " + FormatNumber(s.initial_length) +
                     " and at most 1000 [m]: " + kLengthRange.why);
    }
    s.max_length = value;
  }
}

}  // namespace

ScenarioSpec ReadScenario(const yaml::Source& src, const YAML::Node& root) {
  yaml::RequireMap(src, root, "", kScenarioKeys);
  ScenarioSpec s;
  s.source = src.file;
  if (root["name"]) s.name = yaml::ReadString(src, root["name"], "name");
  s.model = ReadModelSpec(src, Required(src, root, "", "model"), "model");

  const YAML::Node actuator = Required(src, root, "", "actuator");
  yaml::RequireMap(src, actuator, "actuator", {"mass", "damping", "stiffness", "rest_length"});
  s.actuator.mass = yaml::ReadNumberIn(src, Required(src, actuator, "actuator", "mass"),
                                       "actuator.mass", kMassRange);
  s.actuator.damping =
      yaml::ReadOptionalNumberIn(src, actuator, "actuator", "damping", kDampingRange, 0.0);
  s.actuator.stiffness = yaml::ReadOptionalNumberIn(src, actuator, "actuator", "stiffness",
                                                    kStiffnessRange, 0.0);
  s.actuator.rest_length = yaml::ReadOptionalNumberIn(src, actuator, "actuator", "rest_length",
                                                      kPositionRange, 0.0);
  ValidateAt(src, actuator, "actuator", [&] { Validate(s.actuator); });
  // before what needs it: the shortest interval, step and pulse are measured against it
  ReadTime(src, Required(src, root, "", "time"), s);

  const YAML::Node initial = Required(src, root, "", "initial");
  yaml::RequireMap(src, initial, "initial", {"length", "lengthening_rate"});
  s.initial_length = yaml::ReadNumberIn(src, Required(src, initial, "initial", "length"),
                                        "initial.length", kLengthRange);
  s.initial_lengthening_rate = yaml::ReadOptionalNumberIn(
      src, initial, "initial", "lengthening_rate", kSpeedRange, 0.0);

  const YAML::Node activation = Required(src, root, "", "activation");
  s.activation = ReadActivation(src, activation, "activation");
  CheckPulses(src, activation, "activation", s.activation, s.t_start, s.t_end);

  if (const YAML::Node load = root["load"]) {
    const auto read = [&](const YAML::Node& node, const std::string& at) {
      s.loads.push_back(ReadLoad(src, node, at));
      if (s.loads.back().kind == LoadKind::kForce) {
        CheckPulses(src, node, at, s.loads.back().force, s.t_start, s.t_end);
      }
    };
    if (load.IsMap()) {
      read(load, "load");
    } else if (load.IsSequence()) {
      for (std::size_t i = 0; i < load.size(); ++i) read(load[i], "load[" + std::to_string(i) + "]");
    } else {
      yaml::Fail(src, load, "load", yaml::Describe(load), "must be one load (a map) or a list of loads");
    }
  }

  if (const YAML::Node solver = root["solver"]) ReadSolver(src, solver, "solver", s);
  if (const YAML::Node output = root["output"]) {
    ReadOutput(src, output, "output", s);
  } else {
    s.output.interval = (s.t_end - s.t_start) / 1000.0;
  }
  if (const YAML::Node limits = root["limits"]) ReadLimits(src, limits, s);
  return s;
}

namespace {

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
                     "' is not a dotted key path such as model.velocity.n or load[0].value (names "
                     "joined by dots, list indices in brackets from 0 to 999999999)");
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
      if (node.IsMap() && walked == "load" && step.index == 0) {
        next.reset(node);  // a single load written as a map is load[0]
      } else if (node.IsMap()) {
        const std::string map = walked.empty() ? "the file's top level" : walked;
        throw InputError("--set " + text + ": " + map + " is a map, not a list, in " + file +
                         ": an index on it has no meaning (name a key instead)");
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
  const yaml::Source src{path_};
  if (overrides.empty()) return ReadScenario(src, parsed_->root);
  // overrides must not touch the template, so they go into a copy. yaml-cpp's Clone is fast
  // but gives no node its file position; errors are rare, so a failing scenario is read
  // again from its text parsed afresh, whose nodes keep their file:line:column for the
  // message (and the overridden nodes, which have none, say --set)
  try {
    YAML::Node root = YAML::Clone(parsed_->root);
    for (const std::string& text : overrides) ApplyOverride(root, text, path_);
    return ReadScenario(src, root);
  } catch (const InputError&) {
    YAML::Node root = YAML::Load(text_);
    for (const std::string& text : overrides) ApplyOverride(root, text, path_);
    return ReadScenario(src, root);
  }
}

ScenarioSpec LoadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  return ScenarioTemplate(path).Instantiate(overrides);
}

}  // namespace musclesim
