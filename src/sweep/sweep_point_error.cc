#include "sweep/sweep_point_error.h"

#include <vector>

#include "musclesim/core/errors.h"
#include "sweep/sweep_base.h"
#include "io/readers/yaml_fields.h"

namespace musclesim {

namespace {

// The position of the deepest node of `root` that the key path `path` (model.velocity.n,
// load[0].after) reaches; the key itself rather than its value when `want_key` and the path
// ends in a key that exists. Messages name such paths first; "(top level)" reaches the root.
TextPosition Reach(const Document& root, const std::string& path, bool want_key) {
  const Document* node = &root;
  TextPosition mark = root.position();
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') ++i;
    if (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) break;
      const std::string digits = path.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos) {
        break;
      }
      const std::size_t index = std::stoul(digits);
      if (node->IsSequence() && index < node->size()) {
        node = &(*node)[index];
      } else if (!(node->IsMap() && index == 0)) {  // a single load written as a map is load[0]
        break;
      }
      mark = node->position();
      i = close + 1;
      continue;
    }
    const std::size_t end = path.find_first_of(".[", i);
    const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (key.empty() || !node->IsMap()) break;
    bool found = false;
    for (std::size_t k = 0; k < node->size(); ++k) {
      if (node->key(k) == key) {
        const bool last = end == std::string::npos;
        mark = last && want_key ? node->key_position(k) : node->items()[k].position();
        node = &node->items()[k];
        found = true;
        break;
      }
    }
    if (!found) break;
    i = end == std::string::npos ? path.size() : end;
  }
  return mark;
}

std::string Describe(const SweepSpec& spec, const std::vector<std::string>& values) {
  std::string point;
  for (std::size_t k = 0; k < spec.axes.size(); ++k) {
    point += (k ? ", " : "") + spec.axes[k].path + "=" + values[k];
  }
  return point;
}

}  // namespace

PointErrorExplainer::PointErrorExplainer(const SweepSpec& spec, const ScenarioTemplate& base)
    : spec_(spec), base_(base), base_root_(yaml::LoadFile(spec.base)) {
  // the base alone is read from its own nodes, whose positions are exact
  try {
    Check({});
  } catch (const InputError& e) {
    base_error_ = e;
  }
}

void PointErrorExplainer::Check(const std::vector<std::string>& overrides) const {
  const Scenario scenario = base_.Instantiate(Overrides(overrides, kAxisLabel));
  MetricElementIndex(scenario, spec_.metric_options.element);
}

InputError PointErrorExplainer::Restore(const InputError& error) const {
  // an overridden copy of the base places every node at 1:1; find the node its key names
  // (the key itself for a fault of no value: an unknown key)
  InputFault fault = error.fault();
  const InputPlace lost{spec_.base, 1, 1};
  if (!fault.place || fault.place->file != lost.file || fault.place->line != lost.line ||
      fault.place->column != lost.column) {
    return error;
  }
  const TextPosition mark = Reach(base_root_, fault.key, !fault.value.has_value());
  fault.place = InputPlace{spec_.base, mark.line + 1, mark.column + 1};
  return error.WithFault(fault);
}

bool PointErrorExplainer::IsBaseError(const InputError& error) const {
  // the same fault wherever in the base it is placed
  const auto unplaced = [this](const InputError& e) {
    InputFault fault = e.fault();
    if (fault.place && fault.place->file == spec_.base) fault.place = InputPlace{spec_.base};
    return std::string(e.WithFault(fault).what());
  };
  return base_error_ && unplaced(error) == unplaced(*base_error_);
}

PointErrorExplainer::Explanation PointErrorExplainer::Explain(long index,
                                                              const InputError& error) const {
  const std::string base_fault =
      spec_.base + " (the base scenario of the sweep " + spec_.source + ") is not a valid scenario";
  if (IsBaseError(error)) return {InputError(base_fault, *base_error_), true};

  // the first axis whose value alone breaks the base is the culprit
  const std::vector<std::string> values = PointValues(spec_, index);
  const std::vector<std::string> overrides = PointOverrides(spec_, index);
  for (std::size_t k = 0; k < spec_.axes.size(); ++k) {
    try {
      Check({overrides[k]});
    } catch (const InputError& e) {
      if (IsBaseError(e)) continue;  // that value leaves the base's own error as it is
      const SweepAxis& axis = spec_.axes[k];
      const std::string rule = "makes point " + std::to_string(index) + " (" +
                               Describe(spec_, values) +
                               ") an invalid scenario: " + Restore(e).what();
      return {InputError(PlaceText(axis.place) + ": axis " + axis.path + " = " + values[k] + " ",
                         InputFault{axis.place, "parameters." + axis.path, values[k], rule}),
              false};
    }
  }
  if (base_error_) return {InputError(base_fault, *base_error_), true};
  // no single value is wrong: their combination is
  const std::string where = spec_.axes.empty() ? spec_.source : PlaceText(spec_.axes.front().place);
  return {InputError(where + ": point " + std::to_string(index) + " (" + Describe(spec_, values) +
                         ") is not a valid scenario, though each of its values is valid alone",
                     Restore(error)),
          false};
}

}  // namespace musclesim
