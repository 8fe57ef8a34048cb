#include "musclesim/dynamics/waveform_shapes.h"

#include <utility>

namespace musclesim {

namespace {

using Field = NumberField<Waveform>;
using Member = double Waveform::*;

// The field of the member `member`: a time (kTimeRange), a value of the signal, or any
// finite number (Validate(Waveform) states its rule).
Field Of(const char* key, Member member, const InputRange& range, const char* doc) {
  return MemberField(key, member, range, std::nullopt, doc);
}

Field Time(const char* key, Member member, const char* doc) {
  return Of(key, member, kTimeRange, doc);
}

Field Signal(const char* key, Member member, const char* doc) {
  Field field = Of(key, member, InputRange{0.0, 0.0, "signal's", ""}, doc);
  field.values = FieldValues::kSignal;
  return field;
}

Field Finite(const char* key, Member member, const char* unit, const char* doc) {
  Field field = Of(key, member, InputRange{0.0, 0.0, unit, ""}, doc);
  field.values = FieldValues::kFinite;
  return field;
}

WaveformShape Shape(WaveformKind kind, const char* law, std::vector<Field> fields) {
  WaveformShape shape;
  shape.type = ToString(kind).data();  // the names are literals (waveform.cc)
  shape.name = shape.type;
  shape.law = law;
  shape.fields = std::move(fields);
  shape.is = [kind](const Waveform& w) { return w.kind == kind; };
  shape.make = [kind](Waveform& w) { w.kind = kind; };
  return shape;
}

std::vector<WaveformShape> Shapes() {
  using W = Waveform;
  Field phase = Finite("phase", &W::phase, "rad", "the phase at t = 0");
  phase.default_value = 0.0;
  WaveformShape table = Shape(WaveformKind::kTable,
                              "piecewise linear through points: [[t, value], ...], t strictly "
                              "increasing, flat beyond its ends",
                              {});
  table.other_keys = {"points"};
  return {
      Shape(WaveformKind::kConstant, "value at all times",
            {Signal("value", &W::value, "the value")}),
      Shape(WaveformKind::kStep, "before, then after from time on",
            {Time("time", &W::time, "when it switches"),
             Signal("before", &W::before, "the value before"),
             Signal("after", &W::after, "the value from time on")}),
      Shape(WaveformKind::kRamp, "from up to start, linear, to from end on",
            {Time("start", &W::start, "when it leaves from"),
             Time("end", &W::end, "when it reaches to (after start)"),
             Signal("from", &W::from, "the value up to start"),
             Signal("to", &W::to, "the value from end on")}),
      Shape(WaveformKind::kSine, "offset + amplitude sin(2 pi frequency t + phase)",
            {Signal("offset", &W::offset, "the mean value"),
             Signal("amplitude", &W::amplitude, "the swing either side of it"),
             Of("frequency", &W::frequency, kFrequencyRange, "cycles per second"), phase}),
      Shape(WaveformKind::kPulses,
            "low before start; from start, high for width at the beginning of every period",
            {Time("start", &W::start, "when the first pulse begins"),
             Finite("period", &W::period, "s",
                    "from one pulse's start to the next's (> 0; at most 5e6 pulses in a run)"),
             Finite("width", &W::width, "s", "how long each pulse is high (> 0, at most period)"),
             Signal("low", &W::low, "the value between pulses"),
             Signal("high", &W::high, "the value during a pulse")}),
      std::move(table),
  };
}

}  // namespace

const std::vector<WaveformShape>& WaveformShapes() {
  static const std::vector<WaveformShape> shapes = Shapes();
  return shapes;
}

}  // namespace musclesim
