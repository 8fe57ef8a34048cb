// A part's signals described once, beside its numbers (core/part_fields.h): each waveform a
// part carries (a controller's reference, an actuator's activation, a prescribed node's
// motion), with its key, the unit and bounds of its values, its check and its meaning. In a
// file a signal is a map {type, ...} of one of WaveformShapes(). The readers, the waveforms'
// parameter handles (--set, sweeps), the parts' validation and the reference tables derive
// from these; the rules between a part's keys (activation or excitation) stay its reader's.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/waveform.h"

namespace musclesim {

template <typename Part>
struct SignalField {
  std::string key;        // below the part: "reference", or nested "co_contraction.level"
  const char* unit = "";  // of its values, for the reference table: "m or N"
  const char* doc = "";
  bool required = true;  // else absent is the part's own (its default, told in `doc`)
  // When it is required only with another key (a pair's level), that key, for the table.
  const char* required_with = nullptr;
  // Its values' bounds for the reference table where `values` depends on the part ("those of
  // the measured quantity"); "" states `values` of a default part.
  std::string accepted;
  // The bounds a file's values keep to at `part` (a reference's are its measured quantity's),
  // or null: any number `check` accepts (an activation's [0, 1] at every point).
  std::function<const InputRange*(const Part&)> values;
  // The part's waveform, of coordinate c for a motion; null where the part has none (a
  // controller without co_contraction, an actuator with an excitation in place of an
  // activation).
  std::function<const Waveform*(const Part&, std::size_t c)> get;
  std::function<Waveform*(Part&, std::size_t c)> at;
  // Throws ParameterError at the waveform's own keys: Validate, ValidateActivation.
  std::function<void(const Waveform&)> check;
  bool continuous = false;      // constant, ramp, sine or table only: a position's motion
  bool per_coordinate = false;  // one waveform per coordinate in 2 or 3 dimensions, a list
  const char* coordinate_noun = "waveform";  // a coordinate's, in messages: "motion"
};

// The signal field `key` whose waveform `pick(part, c)` gives (a generic lambda, for a const
// part and a mutable one; null where the part has none), its values bounded by `values`
// (null: `check`'s rule alone).
template <typename Part, typename Pick>
SignalField<Part> Signal(const char* key, const char* unit, const char* doc, Pick pick,
                         const InputRange* values, std::function<void(const Waveform&)> check) {
  SignalField<Part> field;
  field.key = key;
  field.unit = unit;
  field.doc = doc;
  field.values = [values](const Part&) { return values; };
  field.get = [pick](const Part& part, std::size_t c) -> const Waveform* { return pick(part, c); };
  field.at = [pick](Part& part, std::size_t c) -> Waveform* { return pick(part, c); };
  field.check = std::move(check);
  return field;
}

// The checks a signal's waveform meets: any valid waveform, or an activation's.
inline void CheckWaveform(const Waveform& w) { Validate(w); }
inline void CheckActivation(const Waveform& w) { ValidateActivation(w); }

// The values an activation's waveform keeps to, for the reference table: it is checked
// whole (a sine's offset -+ amplitude) rather than number by number.
inline std::string ActivationValues() {
  return kActivationRange.Bounds() + " at every point: " + kActivationRange.why;
}

// The signal of `signals` whose key is `key`; null when none is.
template <typename Part>
const SignalField<Part>* FindSignal(const std::vector<SignalField<Part>>& signals,
                                    std::string_view key) {
  for (const SignalField<Part>& signal : signals) {
    if (key == signal.key) return &signal;
  }
  return nullptr;
}

// "prescribed[1]" for coordinate 1 of a per-coordinate signal; its key for coordinate 0 of
// one on a line.
inline std::string SignalKey(const std::string& key, std::size_t c, bool indexed) {
  return indexed ? key + "[" + std::to_string(c) + "]" : key;
}

// Throws ParameterError for the first waveform of `part`'s signals that fails its check, its
// path below the signal's key ("co_contraction.level.to", "prescribed[1].type"). `coordinates`:
// how many a per-coordinate signal has (3: all of them, whatever the part's dimensions).
template <typename Part>
void ValidateSignals(const std::vector<SignalField<Part>>& signals, const Part& part,
                     std::size_t coordinates = 3) {
  for (const SignalField<Part>& signal : signals) {
    const std::size_t n = signal.per_coordinate ? coordinates : 1;
    for (std::size_t c = 0; c < n; ++c) {
      const Waveform* w = signal.get(part, c);
      if (w == nullptr) continue;
      const std::string key = SignalKey(signal.key, c, signal.per_coordinate && c > 0);
      try {
        signal.check(*w);
      } catch (const ParameterError& e) {
        throw ParameterError(key + "." + e.path(), e.value(), e.rule());
      }
      // a jump in position would move the node at infinite speed
      if (signal.continuous &&
          (w->kind == WaveformKind::kStep || w->kind == WaveformKind::kPulses)) {
        throw ParameterError(key + ".type", std::string(ToString(w->kind)),
                             "must be continuous in time: constant, ramp, sine or table");
      }
    }
  }
}

}  // namespace musclesim
