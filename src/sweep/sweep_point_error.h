// Private: why a point of a sweep is not a valid scenario, told in the files the user
// wrote. A point's scenario is the base scenario with the axis values applied, and its
// validation error may come from the base file itself, from one axis value, or from a
// combination of values; the message names the base file's line:column in the first case,
// the axis (path, value, point, and its line:column in the sweep file) in the second.
#pragma once

#include <optional>
#include <string>

#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/sweep/sweep.h"

namespace musclesim {

// What messages call a value a sweep's axis gives a point: "KEY = VALUE (axis): rule".
inline const char* const kAxisLabel = "axis";

class PointErrorExplainer {
 public:
  // `base` must be the spec's base scenario file, read; both must outlive the explainer,
  // which reads the base file once more (for the positions of its keys) and validates it
  // alone.
  PointErrorExplainer(const SweepSpec& spec, const ScenarioTemplate& base);

  struct Explanation {
    InputError error;            // what to throw: the axis, the base or the combination named
    bool base_at_fault = false;  // the base scenario is invalid whatever the axes [-]
  };

  // `error` is the InputError that instantiating point `index` threw. Validates the base
  // with single axis values to find the culprit (only on failure, so its cost does not
  // matter).
  Explanation Explain(long index, const InputError& error) const;

 private:
  // The error with the base file's position restored where the scenario reader could not
  // know it.
  InputError Restore(const InputError& error) const;
  // The base scenario's own fault, wherever in the base it is placed.
  bool IsBaseError(const InputError& error) const;
  // Reads the base with `overrides` and checks it has the metrics' element (InputError).
  void Check(const std::vector<std::string>& overrides) const;

  const SweepSpec& spec_;
  const ScenarioTemplate& base_;
  Document base_root_;                    // the base file as written, with positions
  std::optional<InputError> base_error_;  // the base scenario's own error, if any
};

}  // namespace musclesim
