// Private to scenario/: the walk of one key path into a Parameter handle (parameter.cc: the
// path and the scenario's top level; parameter_model_fields.cc: a model block's keys;
// parameter_network_fields.cc: the network's nodes, elements, loads, controllers and
// settings). Each step knows the keys its part has and the range the file reader checks
// them against.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/key_path.h"
#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/signal_fields.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

// `steps` written back the one way: "load[0].after" for "load[00]after".
std::string Canonical(const std::vector<KeyPathStep>& steps);

// A reference into the scenario (or a model block) from its parts' indices, for both Get
// (const) and Set.
template <typename T, typename In = Scenario>
using Locate = std::function<T&(In&)>;

// Walks the steps of one path and fills the handle.
class ParameterResolver {
 public:
  ParameterResolver(const Scenario& scenario, std::string path)
      : scenario_(scenario), given_(std::move(path)) {}

  Parameter Resolve();

 private:
  [[noreturn]] void Fail(const std::string& rule) const {
    throw ParameterError(p_.path_, "", rule);
  }
  std::size_t size() const { return steps_.size(); }
  // The key of step i ("" for an index or past the end).
  const std::string& Key(std::size_t i) const {
    static const std::string none;
    return i < steps_.size() ? steps_[i].key : none;
  }
  // The index of step i, within `count` items of `what`.
  std::size_t Index(std::size_t i, std::size_t count, const char* what) const {
    if (i >= steps_.size() || !steps_[i].key.empty())
      Fail(std::string("needs an index of ") + what);
    if (steps_[i].index >= count) {
      Fail("indexes past the end of " + std::string(what) + " (" + std::to_string(count) + ")");
    }
    return steps_[i].index;
  }
  // The steps from i on, written back the one way: "exponential.k".
  std::string PathFrom(std::size_t i) const {
    return Canonical(std::vector<KeyPathStep>(steps_.begin() + static_cast<long>(i), steps_.end()));
  }
  void End(std::size_t i) const {
    if (i != steps_.size()) Fail("names a block, not one number");
  }

  // A plain number of the scenario.
  void Number(Locate<double> at, const InputRange* range) {
    p_.get_ = [at](const Scenario& s) { return at(const_cast<Scenario&>(s)); };
    p_.set_ = [at](Scenario& s, double v) { at(s) = v; };
    if (range != nullptr) {
      p_.range_ = *range;
      p_.bounded_ = true;
    }
  }

  // A described field (core/part_fields.h) of the part at `at`: bounded by its own range, by
  // `signal` for a value of the signal (nullptr: unbounded), not at all for any finite number.
  template <typename Part>
  void Field(const NumberField<Part>& field, Locate<Part> at, const InputRange* signal = nullptr) {
    p_.get_ = [at, get = field.get](const Scenario& s) {
      return get(at(const_cast<Scenario&>(s)));
    };
    p_.set_ = [at, set = field.set](Scenario& s, double v) { set(at(s), v); };
    p_.integer_ = field.integer;
    const InputRange* range = field.values == FieldValues::kRange    ? &field.range
                              : field.values == FieldValues::kSignal ? signal
                                                                     : nullptr;
    if (range != nullptr) {
      p_.range_ = *range;
      p_.bounded_ = true;
    }
  }

  // Coordinate c of a described point field (core/part_fields.h) of the part at `at`, bounded
  // by `range` (the field's own, unless the context narrows it).
  template <typename Part>
  void Point(const PointField<Part>& point, Locate<Part> at, std::size_t c,
             const InputRange& range) {
    p_.get_ = [at, get = point.get, c](const Scenario& s) {
      return get(at(const_cast<Scenario&>(s)))[c];
    };
    p_.set_ = [at, get = point.get, set = point.set, c](Scenario& s, double v) {
      Part& part = at(s);
      FieldPoint x = get(part);
      x[c] = v;
      set(part, x);
    };
    p_.range_ = range;
    p_.bounded_ = true;
  }

  // The signal among `signals` (dynamics/signal_fields.h) of `part`, at `at`, that the steps
  // from i name, and its waveform's field after them; in 2 or 3 dimensions a per-coordinate
  // signal's coordinate comes first ("prescribed[1].to"). False when they name none that the
  // part has.
  template <typename Part>
  bool Signal(std::size_t i, const std::vector<SignalField<Part>>& signals, const Part& part,
              Locate<Part> at) {
    for (const SignalField<Part>& signal : signals) {
      std::size_t next = i;
      bool named = true;  // by the steps from i, one per step of the signal's key
      for (std::size_t begin = 0; named;) {
        const std::size_t dot = signal.key.find('.', begin);
        named = Key(next++) == signal.key.substr(begin, dot - begin);
        if (dot == std::string::npos) break;
        begin = dot + 1;
      }
      if (!named || signal.get(part, 0) == nullptr) continue;
      std::size_t c = 0;
      if (signal.per_coordinate) {
        c = Coordinate(next, signal.key);
        if (scenario_.space.dimensions > 1) ++next;
      }
      WaveformField(
          next, [at, c, pick = signal.at](Scenario& s) -> Waveform& { return *pick(at(s), c); },
          signal.values(part));
      return true;
    }
    return false;
  }

  void Top();
  void Model(std::size_t i);
  // A key of a model block of its family (docs/model.md 14.1), step i its first.
  void FamilyField(std::size_t i, CurveFamily family);
  void ModelValue(std::function<double(const ModelSpec&)> get,
                  std::function<void(ModelSpec&, double)> set, bool refits = false);
  // The fit's settings of a fitted paper model (active_length.fit), step i the leaf.
  void FitField(std::size_t i);
  // A number of an item of a list of sub-parts of the model (a Gaussian's width).
  void ListItemField(const ListItemKey<ModelParams>& key);
  // Fails when `key_path`, which names no field of `family`, names one of its lists of
  // numbers: without an index, or with one past its end; returns for any other path.
  void RequireListIndex(const PartVariant<ModelParams>& family, const std::string& key_path) const;
  // The coordinate step i names of a node's `key` (fixed, prescribed, position, velocity):
  // none on a line (0), an index below the dimensions in 2 or 3.
  std::size_t Coordinate(std::size_t i, const std::string& key) const;
  void Node(std::size_t i);
  void Element(std::size_t i);
  // A fixed via point's coordinate: elements[e].via[k][c].
  void Via(std::size_t i, std::size_t e);
  void Load(std::size_t i);
  void Controller(std::size_t i);
  void Gravity(std::size_t i);
  void Setting(std::size_t i);
  // A waveform's field at step i (the waveform at `at`); `values` bounds its values
  // (nullptr: an activation's [0, 1], which the scenario's validation checks).
  void WaveformField(std::size_t i, Locate<Waveform> at, const InputRange* values);

  const Scenario& scenario_;
  std::string given_;
  std::vector<KeyPathStep> steps_;
  Parameter p_;
  bool fitted_ = false;  // the model block asks for a fit
};

}  // namespace musclesim
