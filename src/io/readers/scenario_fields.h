// Private: the blocks both forms of a scenario file share (the single actuator of
// scenario/actuator_scenario.h and the network): waveforms, loads, the time span,
// the solver and the output. Each reader validates what it reads and throws InputError
// naming file:line:column, key path, value and rule.
#pragma once

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>

#include "io/readers/yaml_fields.h"
#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/setting_fields.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// The `type` of a map that must have one (a waveform, a load, an element).
std::string ReadType(const yaml::Source& src, const Document& node, const std::string& path);

// Reads one waveform of `kind`. `values` bounds its values (a force's, a position's); nullptr
// leaves them to ValidateActivation, which keeps an activation within [0, 1]. `extra` are
// more keys the map may hold besides the waveform's, read by the caller.
Waveform ReadWaveform(const yaml::Source& src, const Document& node, const std::string& path,
                      WaveformKind kind, const InputRange* values,
                      std::initializer_list<const char*> extra = {});

// Reads a signal's waveform (dynamics/signal_fields.h) at `node`, its `type` any shape or,
// `continuous`, constant, ramp, sine or table; its values within `values` (nullptr: any
// number), then `check`ed and its pulses checked against the run [t_start, t_end].
Waveform ReadSignalWaveform(const yaml::Source& src, const Document& node, const std::string& path,
                            const InputRange* values,
                            const std::function<void(const Waveform&)>& check, bool continuous,
                            double t_start, double t_end);

// How an actuator's activation is given: `activation` (u(t) itself) or `excitation` with
// `activation_dynamics` (docs/model.md section 8), exactly one.
struct ActuatorDrive {
  Waveform activation;                        // without activation dynamics: u(t) [-]
  std::optional<ExcitationInput> excitation;  // with them: units as in ExcitationInput
};

// Reads an `activation_dynamics` map: its time constants, its `family` (thelen2003, the
// default, degroote2016 or mujoco: docs/model.md 8.1) and that family's smoothing
// (`smoothing`, `tausmooth`), each key checked against its range.
ActivationDynamics ReadActivationDynamics(const yaml::Source& src, const Document& node,
                                          const std::string& path);

// Reads the drive of the map `owner` at key path `path` (the top level of a single-actuator
// scenario, "", or a network's actuator element): its `activation`, or its `excitation` and
// `activation_dynamics`; and the initial activation from `initial` at `initial_path` (an
// undefined node when absent), allowed only with an excitation. Pulses are checked against
// the run [t_start, t_end] (CheckPulses).
ActuatorDrive ReadActuatorDrive(const yaml::Source& src, const Document& owner,
                                const std::string& path, const Document& initial,
                                const std::string& initial_path, double t_start, double t_end);

// One load: a force waveform, a spring or a mass. `extra` as for ReadWaveform.
Load ReadLoad(const yaml::Source& src, const Document& node, const std::string& path,
              std::initializer_list<const char*> extra = {});

// A pulse train's edges become stop times: its period and width must be resolved at the
// run's times, and the run may hold at most kMaxBreakpoints edges. Nothing for other kinds.
void CheckPulses(const yaml::Source& src, const Document& node, const std::string& path,
                 const Waveform& w, double t_start, double t_end);

// The `time` block (setting_fields.h): start and end [s], the span at least
// kMinSpanRelative of the time scale.
TimeSpan ReadTime(const yaml::Source& src, const Document& time);

// The `solver` block (`path` its key path) of a run over [t_start, t_end].
SolverOptions ReadSolver(const yaml::Source& src, const Document& node, const std::string& path,
                         double t_start, double t_end);

// The `output` block (`path` its key path) of a run over [t_start, t_end]; the interval
// defaults to a thousandth of the span.
OutputRequest ReadOutput(const yaml::Source& src, const Document& node, const std::string& path,
                         double t_start, double t_end);

// The `sensitivities` list of parameter paths (strings), and where each is (file:line:column).
// Whether each names a parameter is checked when a run resolves it.
void ReadSensitivities(const yaml::Source& src, const Document& node,
                       std::vector<std::string>& paths, std::vector<std::string>& where);

}  // namespace musclesim
