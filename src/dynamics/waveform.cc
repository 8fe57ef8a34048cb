#include "musclesim/dynamics/waveform.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/enum_names.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

constexpr EnumName<WaveformKind> kWaveformNames[] = {
    {WaveformKind::kConstant, "constant"}, {WaveformKind::kStep, "step"},
    {WaveformKind::kRamp, "ramp"},         {WaveformKind::kSine, "sine"},
    {WaveformKind::kPulses, "pulses"},     {WaveformKind::kTable, "table"},
};

std::string_view ToString(WaveformKind kind) { return ToString(kWaveformNames, kind); }

WaveformKind ParseWaveformKind(std::string_view text) {
  return Parse(kWaveformNames, "type", text);
}

double Waveform::Evaluate(double t) const {
  switch (kind) {
    case WaveformKind::kConstant: return value;
    case WaveformKind::kStep: return t < time ? before : after;
    case WaveformKind::kRamp:
      if (t <= start) return from;
      if (t >= end) return to;
      return from + (to - from) * (t - start) / (end - start);
    case WaveformKind::kSine:
      return offset + amplitude * std::sin(2.0 * std::numbers::pi * frequency * t + phase);
    case WaveformKind::kPulses: {
      if (t < start) return low;
      const double into_period = std::fmod(t - start, period);
      return into_period < width ? high : low;
    }
    case WaveformKind::kTable: {
      if (t <= points.front().t) return points.front().value;
      if (t >= points.back().t) return points.back().value;
      const auto right = std::upper_bound(points.begin(), points.end(), t,
                                          [](double s, const TablePoint& p) { return s < p.t; });
      const TablePoint& a = *(right - 1);
      const TablePoint& b = *right;
      return a.value + (b.value - a.value) * (t - a.t) / (b.t - a.t);
    }
  }
  return 0.0;
}

double Waveform::Slope(double t) const {
  switch (kind) {
    case WaveformKind::kConstant:
    case WaveformKind::kStep:
    case WaveformKind::kPulses: return 0.0;
    case WaveformKind::kRamp: return t >= start && t < end ? (to - from) / (end - start) : 0.0;
    case WaveformKind::kSine: {
      const double omega = 2.0 * std::numbers::pi * frequency;
      return amplitude * omega * std::cos(omega * t + phase);
    }
    case WaveformKind::kTable: {
      if (t < points.front().t || t >= points.back().t) return 0.0;
      const auto right = std::upper_bound(points.begin(), points.end(), t,
                                          [](double s, const TablePoint& p) { return s < p.t; });
      const TablePoint& a = *(right - 1);
      const TablePoint& b = *right;
      return (b.value - a.value) / (b.t - a.t);
    }
  }
  return 0.0;
}

std::vector<double> Waveform::Breakpoints(double t0, double t1) const {
  std::vector<double> times;
  const auto add = [&](double t) {
    if (t > t0 && t < t1) times.push_back(t);
  };
  switch (kind) {
    case WaveformKind::kConstant:
    case WaveformKind::kSine: break;
    case WaveformKind::kStep: add(time); break;
    case WaveformKind::kRamp:
      add(start);
      add(end);
      break;
    case WaveformKind::kPulses: {
      // every rising and falling edge inside the window
      const double first = std::max(0.0, std::floor((t0 - start) / period));
      for (double k = first; start + k * period < t1; k += 1.0) {
        add(start + k * period);
        if (width < period) add(start + k * period + width);
      }
      break;
    }
    case WaveformKind::kTable:
      for (const TablePoint& p : points) add(p.t);
      break;
  }
  SortUnique(times);
  return times;
}

void SortUnique(std::vector<double>& times) {
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
}

double Waveform::Minimum(double t0, double t1) const {
  double lowest = std::min(Evaluate(t0), Evaluate(t1));
  for (double t : Breakpoints(t0, t1)) {
    lowest = std::min({lowest, Evaluate(t), Evaluate(std::nextafter(t, t0))});
  }
  if (kind == WaveformKind::kSine) lowest = std::min(lowest, offset - std::abs(amplitude));
  if (kind == WaveformKind::kPulses && t1 > start) lowest = std::min(lowest, low);
  return lowest;
}

double Waveform::Maximum(double t0, double t1) const {
  double highest = std::max(Evaluate(t0), Evaluate(t1));
  for (double t : Breakpoints(t0, t1)) {
    highest = std::max({highest, Evaluate(t), Evaluate(std::nextafter(t, t0))});
  }
  if (kind == WaveformKind::kSine) highest = std::max(highest, offset + std::abs(amplitude));
  if (kind == WaveformKind::kPulses && t1 > start) highest = std::max(highest, high);
  return highest;
}

void Validate(const Waveform& w) {
  const auto finite = [](const char* key, double v) {
    Require(std::isfinite(v), key, v, "must be finite");
  };
  switch (w.kind) {
    case WaveformKind::kConstant: finite("value", w.value); break;
    case WaveformKind::kStep:
      finite("time", w.time);
      finite("before", w.before);
      finite("after", w.after);
      break;
    case WaveformKind::kRamp:
      finite("start", w.start);
      finite("from", w.from);
      finite("to", w.to);
      Require(std::isfinite(w.end) && w.end > w.start, "end", w.end,
              "must be finite and greater than start = " + FormatNumber(w.start));
      break;
    case WaveformKind::kSine:
      finite("offset", w.offset);
      finite("amplitude", w.amplitude);
      finite("phase", w.phase);
      Require(std::isfinite(w.frequency) && w.frequency >= 0.0, "frequency", w.frequency,
              "must be finite and >= 0 [Hz]");
      break;
    case WaveformKind::kPulses:
      finite("start", w.start);
      finite("low", w.low);
      finite("high", w.high);
      Require(std::isfinite(w.period) && w.period > 0.0, "period", w.period,
              "must be finite and > 0 [s]");
      Require(std::isfinite(w.width) && w.width > 0.0 && w.width <= w.period, "width", w.width,
              "must be > 0 and at most period = " + FormatNumber(w.period));
      break;
    case WaveformKind::kTable:
      if (w.points.empty()) throw ParameterError("points", "[]", "needs at least one [t, value]");
      for (std::size_t i = 0; i < w.points.size(); ++i) {
        const std::string at = "points[" + std::to_string(i) + "]";
        Require(std::isfinite(w.points[i].t), at + "[0]", w.points[i].t, "must be finite");
        Require(std::isfinite(w.points[i].value), at + "[1]", w.points[i].value, "must be finite");
        if (i > 0) {
          Require(w.points[i].t > w.points[i - 1].t, at + "[0]", w.points[i].t,
                  "table times must be strictly increasing (previous t = " +
                      FormatNumber(w.points[i - 1].t) + ")");
        }
      }
      break;
  }
}

namespace {

// Every value of `w` within [0, 1]; `what` names the signal in the rule ("activation").
void ValidateUnitInterval(const Waveform& w, const std::string& what) {
  Validate(w);
  const std::string rule = what + " must stay within [0, 1]";
  const auto unit = [&](const std::string& key, double v) {
    Require(v >= 0.0 && v <= 1.0, key, v, rule);
  };
  switch (w.kind) {
    case WaveformKind::kConstant: unit("value", w.value); break;
    case WaveformKind::kStep:
      unit("before", w.before);
      unit("after", w.after);
      break;
    case WaveformKind::kRamp:
      unit("from", w.from);
      unit("to", w.to);
      break;
    case WaveformKind::kSine:
      Require(w.offset - std::abs(w.amplitude) >= 0.0 && w.offset + std::abs(w.amplitude) <= 1.0,
              "amplitude", w.amplitude,
              rule + ": offset = " + FormatNumber(w.offset) + " -+ |amplitude| leaves it");
      break;
    case WaveformKind::kPulses:
      unit("low", w.low);
      unit("high", w.high);
      break;
    case WaveformKind::kTable:
      for (std::size_t i = 0; i < w.points.size(); ++i) {
        unit("points[" + std::to_string(i) + "][1]", w.points[i].value);
      }
      break;
  }
}

}  // namespace

void ValidateActivation(const Waveform& w) { ValidateUnitInterval(w, "activation"); }

void ValidateExcitation(const Waveform& w) { ValidateUnitInterval(w, "excitation"); }

void CheckPulseTrain(const Waveform& w, double t_start, double t_end) {
  if (w.kind != WaveformKind::kPulses) return;
  const double resolution = kMinIntervalRelative * TimeScale(t_start, t_end);
  for (const char* key : {"period", "width"}) {
    const double value = std::string_view(key) == "period" ? w.period : w.width;
    Require(value >= resolution, key, value,
            "must be at least " + FormatNumber(resolution) +
                " s, 1e-12 of the run's time scale max(1 s, |time.start|, |time.end|): "
                "shorter times are not resolved in double precision");
  }
  Require(!((t_end - std::max(w.start, t_start)) / w.period > kMaxBreakpoints), "period", w.period,
          "gives more than 5 million pulses between the start and time.end: each edge is a "
          "stop time where the integrator restarts");
}

Waveform Waveform::Constant(double value) {
  Waveform w;
  w.kind = WaveformKind::kConstant;
  w.value = value;
  return Validated(std::move(w));
}

Waveform Waveform::Step(double time, double before, double after) {
  Waveform w;
  w.kind = WaveformKind::kStep;
  w.time = time;
  w.before = before;
  w.after = after;
  return Validated(std::move(w));
}

Waveform Waveform::Ramp(double start, double end, double from, double to) {
  Waveform w;
  w.kind = WaveformKind::kRamp;
  w.start = start;
  w.end = end;
  w.from = from;
  w.to = to;
  return Validated(std::move(w));
}

Waveform Waveform::Sine(double offset, double amplitude, double frequency, double phase) {
  Waveform w;
  w.kind = WaveformKind::kSine;
  w.offset = offset;
  w.amplitude = amplitude;
  w.frequency = frequency;
  w.phase = phase;
  return Validated(std::move(w));
}

Waveform Waveform::Pulses(double start, double period, double width, double low, double high) {
  Waveform w;
  w.kind = WaveformKind::kPulses;
  w.start = start;
  w.period = period;
  w.width = width;
  w.low = low;
  w.high = high;
  return Validated(std::move(w));
}

Waveform Waveform::Table(std::vector<TablePoint> points) {
  Waveform w;
  w.kind = WaveformKind::kTable;
  w.points = std::move(points);
  return Validated(std::move(w));
}

}  // namespace musclesim
