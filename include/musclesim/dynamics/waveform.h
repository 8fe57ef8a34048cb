// Signals over time: the activation u(t) and the force loads. Each kind is a few numbers
// evaluated by a switch (no virtual call or std::function in the right-hand side), and
// knows its breakpoints, which the simulator makes CVODE stop times.
#pragma once

#include <string_view>
#include <vector>

namespace musclesim {

enum class WaveformKind { kConstant, kStep, kRamp, kSine, kPulses, kTable };
std::string_view ToString(WaveformKind kind);
// Throws ParameterError("type", text, ...) for an unknown name.
WaveformKind ParseWaveformKind(std::string_view text);

struct TablePoint {
  double t = 0.0;      // time [s]
  double value = 0.0;  // the signal's value there
};

// One signal. Only the fields of its kind are used:
//   constant: value
//   step:     time, before, after        (after from `time` on)
//   ramp:     start, end, from, to       (from before start, linear, to after end)
//   sine:     offset + amplitude sin(2 pi frequency t + phase), phase in radians
//   pulses:   low before start; from start, high for `width` at the beginning of every
//             `period`, low for the rest of it
//   table:    piecewise linear through `points` (t strictly increasing), flat beyond them
struct Waveform {
  WaveformKind kind = WaveformKind::kConstant;
  double value = 0.0;
  double time = 0.0, before = 0.0, after = 0.0;
  double start = 0.0, end = 0.0, from = 0.0, to = 0.0;
  double offset = 0.0, amplitude = 0.0, frequency = 0.0, phase = 0.0;
  double period = 1.0, width = 0.5, low = 0.0, high = 1.0;
  std::vector<TablePoint> points;

  double Evaluate(double t) const;
  // Times in (t0, t1) where the value or its slope jumps, sorted.
  std::vector<double> Breakpoints(double t0, double t1) const;
  // The least and greatest value on [t0, t1] (sine: offset -+ |amplitude|, a bound).
  double Minimum(double t0, double t1) const;
  double Maximum(double t0, double t1) const;
};

// Throws ParameterError with paths named as the YAML keys ("period", "points[2][0]").
void Validate(const Waveform& waveform);

// Sorts `times` and removes repeated entries: the form every breakpoint list takes.
void SortUnique(std::vector<double>& times);

}  // namespace musclesim

namespace musclesim {

// An activation must stay within [0, 1] at every point of its waveform (sine: offset -+
// |amplitude|). Throws ParameterError naming the offending key.
void ValidateActivation(const Waveform& waveform);

}  // namespace musclesim
