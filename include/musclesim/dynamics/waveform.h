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

// One signal. Make one with the factories below (Waveform::Step(0.05, 0.0, 1.0)), which
// validate; the fields are public for readers that fill them key by key and then call
// Validate. Only the fields of its kind are used:
//   constant: value
//   step:     time, before, after        (after from `time` on)
//   ramp:     start, end, from, to       (from before start, linear, to after end)
//   sine:     offset + amplitude sin(2 pi frequency t + phase), phase in radians
//   pulses:   low before start; from start, high for `width` at the beginning of every
//             `period`, low for the rest of it
//   table:    piecewise linear through `points` (t strictly increasing), flat beyond them
// Values are in the signal's own unit: activation (dimensionless, [0, 1]) or force [N].
struct Waveform {
  WaveformKind kind = WaveformKind::kConstant;
  double value = 0.0;              // constant: the value
  double time = 0.0;               // step: when it switches [s]
  double before = 0.0;             // step: value before `time`
  double after = 0.0;              // step: value from `time` on
  double start = 0.0;              // ramp, pulses: start time [s]
  double end = 0.0;                // ramp: end time [s], > start
  double from = 0.0;               // ramp: value up to `start`
  double to = 0.0;                 // ramp: value from `end` on
  double offset = 0.0;             // sine: mean value
  double amplitude = 0.0;          // sine: amplitude
  double frequency = 0.0;          // sine: [Hz], >= 0
  double phase = 0.0;              // sine: [rad]
  double period = 1.0;             // pulses: [s], > 0
  double width = 0.5;              // pulses: length of the high part [s], in (0, period]
  double low = 0.0;                // pulses: value between pulses
  double high = 1.0;               // pulses: value during a pulse
  std::vector<TablePoint> points;  // table: (t [s], value), t strictly increasing

  // Validated factories: each throws ParameterError (paths named as the YAML keys).
  static Waveform Constant(double value);
  static Waveform Step(double time, double before, double after);
  static Waveform Ramp(double start, double end, double from, double to);
  static Waveform Sine(double offset, double amplitude, double frequency, double phase = 0.0);
  static Waveform Pulses(double start, double period, double width, double low, double high);
  static Waveform Table(std::vector<TablePoint> points);

  double Evaluate(double t) const;
  // d/dt of the value; where the slope jumps, the slope after t (the side a run goes on).
  // Step and pulses jump in value: their slope is 0 everywhere else.
  double Slope(double t) const;
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

// An activation must stay within [0, 1] at every point of its waveform (sine: offset -+
// |amplitude|). Throws ParameterError naming the offending key.
void ValidateActivation(const Waveform& waveform);

// A pulse train's edges become stop times of a run over [t_start, t_end]: its period and
// width must be resolved at the run's times (at least 1e-12 of its time scale), and the run
// may hold at most kMaxBreakpoints pulses. Throws ParameterError ("period", "width");
// nothing for other kinds.
void CheckPulseTrain(const Waveform& waveform, double t_start, double t_end);
// The same for an excitation (docs/model.md section 8), its rule naming the excitation.
void ValidateExcitation(const Waveform& waveform);

}  // namespace musclesim
