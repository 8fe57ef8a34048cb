#include "io/readers/scenario_fields.h"

#include <algorithm>
#include <cmath>

#include "io/readers/part_fields_yaml.h"
#include "io/readers/signal_fields_yaml.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/waveform_shapes.h"
#include "musclesim/solver/solver_fields.h"

namespace musclesim {

using yaml::Join;
using yaml::Required;
using yaml::ValidateAt;

namespace {

// A table's `points`: [t, value] pairs, t in the time range and the values in `values`
// (any number when null); at most kMaxBreakpoints of them.
std::vector<TablePoint> ReadTablePoints(const yaml::Source& src, const Document& node,
                                        const std::string& path, const InputRange* values) {
  const Document& points = Required(src, node, path, "points");
  const std::string at = Join(path, "points");
  if (!points.IsSequence()) {
    yaml::Fail(src, points, at, yaml::Describe(points), "must be a list of [t, value] pairs");
  }
  if (static_cast<double>(points.size()) > kMaxBreakpoints) {
    yaml::Fail(src, points, at, std::to_string(points.size()) + " points",
               "at most 5 million: each point is a stop time where the integrator restarts");
  }
  std::vector<TablePoint> table;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string item = at + "[" + std::to_string(i) + "]";
    const std::vector<double> pair = yaml::ReadNumbers(src, points[i], item, 2);
    if (!kTimeRange.Contains(pair[0])) {
      yaml::Fail(src, points[i][0], item + "[0]", yaml::Describe(points[i][0]), kTimeRange.Rule());
    }
    if (values && !values->Contains(pair[1])) {
      yaml::Fail(src, points[i][1], item + "[1]", yaml::Describe(points[i][1]), values->Rule());
    }
    table.push_back({pair[0], pair[1]});
  }
  return table;
}

// Reads the signal `drive` was made for: its activation, or with an excitation that.
void ReadDriveSignal(const yaml::Source& src, const Document& owner, const std::string& path,
                     ActuatorDrive& drive, double t_start, double t_end) {
  for (const SignalField<ActuatorDrive>& signal : ActuatorSignals<ActuatorDrive>()) {
    ReadSignal(src, owner, path, signal, drive, 1, t_start, t_end);
  }
}

}  // namespace

Waveform ReadWaveform(const yaml::Source& src, const Document& node, const std::string& path,
                      WaveformKind kind, const InputRange* values,
                      std::initializer_list<const char*> extra) {
  // its shape's keys and fields (waveform_shapes.h); a table's points read here
  const WaveformShape& shape = WaveformShapes()[static_cast<std::size_t>(kind)];
  std::vector<std::string> keys{"type"};
  for (std::string& key : VariantKeys(WaveformShapes(), shape.type)) keys.push_back(std::move(key));
  keys.insert(keys.end(), extra.begin(), extra.end());
  yaml::RequireMap(src, node, path, keys);
  Waveform w;
  shape.make(w);
  ReadFields(src, node, path, shape, w, values);
  if (kind == WaveformKind::kTable) w.points = ReadTablePoints(src, node, path, values);
  return w;
}

std::string ReadType(const yaml::Source& src, const Document& node, const std::string& path) {
  if (!node.IsMap()) yaml::Fail(src, node, path, yaml::Describe(node), "must be a map with a type");
  return yaml::ReadString(src, Required(src, node, path, "type"), Join(path, "type"));
}

Waveform ReadSignalWaveform(const yaml::Source& src, const Document& node, const std::string& path,
                            const InputRange* values,
                            const std::function<void(const Waveform&)>& check, bool continuous,
                            double t_start, double t_end) {
  const std::string type = ReadType(src, node, path);
  WaveformKind kind{};
  ValidateAt(src, node, path, [&] { kind = ParseWaveformKind(type); });
  if (continuous && (kind == WaveformKind::kStep || kind == WaveformKind::kPulses)) {
    yaml::Fail(src, node["type"], Join(path, "type"), type,
               "must be continuous in time: constant, ramp, sine or table (a jump in position "
               "would move the node at infinite speed)");
  }
  Waveform w = ReadWaveform(src, node, path, kind, values);
  ValidateAt(src, node, path, [&] { check(w); });
  CheckPulses(src, node, path, w, t_start, t_end);
  return w;
}

ActivationDynamics ReadActivationDynamics(const yaml::Source& src, const Document& node,
                                          const std::string& path) {
  ActivationDynamics d;
  if (node.IsMap() && node["family"]) {
    const Document& family = node["family"];
    const std::string text = yaml::ReadString(src, family, Join(path, "family"));
    if (text == "degroote2016") {
      d.family = ActivationFamily::kDeGroote2016;
    } else if (text == "mujoco") {
      d.family = ActivationFamily::kMujoco;
    } else if (text != "thelen2003") {
      yaml::Fail(src, family, Join(path, "family"), yaml::Describe(family),
                 "must be thelen2003, degroote2016 or mujoco (docs/model.md 8.1)");
    }
  }
  // each family's own keys (activation_families.h), and no other's
  const char* family = ActivationFamilyName(d.family);
  std::vector<std::string> keys = VariantKeys(ActivationFamilies(), family);
  keys.emplace_back("family");
  yaml::RequireMap(src, node, path, keys);
  ReadFields(src, node, path, *SelectVariant(src, node, path, ActivationFamilies(), family), d);
  return d;
}

ActuatorDrive ReadActuatorDrive(const yaml::Source& src, const Document& owner,
                                const std::string& path, const Document& initial,
                                const std::string& initial_path, double t_start, double t_end) {
  const Document& activation = owner["activation"];
  const Document& excitation = owner["excitation"];
  const Document& dynamics = owner["activation_dynamics"];
  const std::string activation_path = Join(path, "activation");
  const std::string excitation_path = Join(path, "excitation");
  const std::string dynamics_path = Join(path, "activation_dynamics");
  constexpr const char* kEither =
      "give either activation (u(t) itself) or excitation (e(t), driving u through "
      "activation_dynamics)";
  ActuatorDrive drive;
  if (activation && excitation) {
    yaml::Fail(src, excitation, excitation_path, yaml::Describe(excitation),
               std::string(kEither) + ", not both");
  }
  if (!excitation) {
    if (dynamics) {
      yaml::Fail(src, dynamics, dynamics_path, yaml::Describe(dynamics),
                 "only with excitation: the time constants lag the activation behind an "
                 "excitation; activation: gives u(t) itself");
    }
    if (!activation) {
      throw InputError(InputFault{yaml::Place(src, owner), activation_path, std::nullopt,
                                  std::string("missing required key: ") + kEither});
    }
    if (initial) {
      yaml::Fail(src, initial, initial_path, yaml::Describe(initial),
                 "only with excitation and activation_dynamics: activation: gives u(t) "
                 "itself, its start included");
    }
    ReadDriveSignal(src, owner, path, drive, t_start, t_end);
    return drive;
  }

  ExcitationInput& input = drive.excitation.emplace();
  ReadDriveSignal(src, owner, path, drive, t_start, t_end);
  if (!dynamics) {
    yaml::Fail(src, excitation, excitation_path, yaml::Describe(excitation),
               "needs activation_dynamics: {tau_activation, tau_deactivation} [s] beside it, "
               "the time constants through which it drives the activation");
  }
  input.dynamics = ReadActivationDynamics(src, dynamics, dynamics_path);
  if (initial) {
    input.initial_activation = yaml::ReadNumberIn(src, initial, initial_path, kActivationRange);
  }
  return drive;
}

Load ReadLoad(const yaml::Source& src, const Document& node, const std::string& path,
              std::initializer_list<const char*> extra) {
  const std::string type = ReadType(src, node, path);
  Load load;
  if (const LoadVariant* variant = SelectVariant(src, node, path, LoadVariants(), type)) {
    std::vector<std::string> keys{"type"};
    for (std::string& key : VariantKeys(LoadVariants(), type)) keys.push_back(std::move(key));
    keys.insert(keys.end(), extra.begin(), extra.end());
    yaml::RequireMap(src, node, path, keys);
    variant->make(load);
    ReadFields(src, node, path, *variant, load);
  } else {
    WaveformKind kind{};
    try {
      kind = ParseWaveformKind(type);
    } catch (const ParameterError&) {
      yaml::Fail(src, node["type"], Join(path, "type"), type,
                 "must be one of constant, step, ramp, sine, pulses, table, spring, mass");
    }
    load.kind = LoadKind::kForce;
    load.force = ReadWaveform(src, node, path, kind, &kForceRange, extra);
  }
  ValidateAt(src, node, path, [&] { Validate(load); });
  return load;
}

void CheckPulses(const yaml::Source& src, const Document& node, const std::string& path,
                 const Waveform& w, double t_start, double t_end) {
  try {
    CheckPulseTrain(w, t_start, t_end);
  } catch (const ParameterError& error) {
    // the period or width at fault, as written
    const Document& at = node[error.path()];
    yaml::Fail(src, at, Join(path, error.path()), yaml::Describe(at), error.rule());
  }
}

TimeSpan ReadTime(const yaml::Source& src, const Document& time) {
  yaml::RequireMap(src, time, "time", VariantKeys(TimeBlock(), "time"));
  TimeSpan span;
  ReadFields(src, time, "time", TimeBlock().front(), span);
  const double shortest = kMinSpanRelative * TimeScale(span.start, span.end);
  if (!(span.end - span.start >= shortest)) {
    yaml::Fail(src, time["end"], "time.end", yaml::Describe(time["end"]),
               "must be greater than time.start = " + FormatNumber(span.start) + " by at least " +
                   FormatNumber(shortest) +
                   " s, 1e-9 of the time scale max(1 s, |start|, |end|): room for 1000 output "
                   "rows that double precision tells apart");
  }
  return span;
}

SolverOptions ReadSolver(const yaml::Source& src, const Document& node, const std::string& path,
                         double t_start, double t_end) {
  SolverOptions o;
  yaml::RequireMap(src, node, path, VariantKeys(SolverBlock(), "solver"));
  ReadFields(src, node, path, SolverBlock().front(), o);
  // a step limit the run could never finish with, or one below the time resolution
  const double span = t_end - t_start;
  const double shortest = std::max(kMinIntervalRelative * TimeScale(t_start, t_end),
                                   span / static_cast<double>(o.max_steps));
  if (o.max_step != 0.0 && o.max_step < shortest) {
    yaml::Fail(src, node["max_step"], Join(path, "max_step"), yaml::Describe(node["max_step"]),
               "must be 0 (no limit) or at least " + FormatNumber(shortest) +
                   " s: (time.end - time.start) / solver.max_steps, or else the run cannot "
                   "reach time.end, and 1e-12 of the time scale max(1 s, |start|, |end|), "
                   "below which double precision does not resolve a step");
  }
  return o;
}

OutputRequest ReadOutput(const yaml::Source& src, const Document& node, const std::string& path,
                         double t_start, double t_end) {
  OutputRequest output;
  yaml::RequireMap(src, node, path, VariantKeys(OutputBlock(), "output"));
  const double span = t_end - t_start;
  output.interval = span / 1000.0;
  ReadFields(src, node, path, OutputBlock().front(), output);
  if (const Document& interval = node["interval"]; interval && !output.every_step) {
    const double shortest = kMinIntervalRelative * TimeScale(t_start, t_end);
    if (!(output.interval >= shortest && span / output.interval <= 1e8)) {
      yaml::Fail(src, interval, Join(path, "interval"), yaml::Describe(interval),
                 "must be `steps` or a time [s] giving at most 1e8 rows (at least " +
                     FormatNumber(span / 1e8) + " s here) and at least " + FormatNumber(shortest) +
                     " s, 1e-12 of the time scale max(1 s, |start|, |end|), so that "
                     "double precision tells the output times apart");
    }
  }
  return output;
}

void ReadSensitivities(const yaml::Source& src, const Document& node,
                       std::vector<std::string>& paths, std::vector<std::string>& where) {
  if (!node.IsSequence()) {
    yaml::Fail(src, node, "sensitivities", yaml::Describe(node),
               "must be a list of parameter paths, e.g. [model.f_iso, model.velocity.v_max]");
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = "sensitivities[" + std::to_string(i) + "]";
    paths.push_back(yaml::ReadString(src, node[i], path));
    where.push_back(yaml::Location(src, node[i]));
  }
}

}  // namespace musclesim
