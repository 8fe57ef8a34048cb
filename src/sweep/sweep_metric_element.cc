#include "sweep/sweep_metric_element.h"

#include <algorithm>

namespace musclesim {

namespace {

std::string List(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) text += (i ? ", " : "") + names[i];
  return text;
}

}  // namespace

std::string ResolveMetricElement(const yaml::Source& src, const YAML::Node& root,
                                 const SweepSpec& spec, const MetricElements& elements) {
  const YAML::Node options = root["metric_options"];
  if (options && options["element"]) {
    const YAML::Node given = options["element"];
    const std::string name = yaml::ReadString(src, given, "metric_options.element");
    if (std::find(elements.all.begin(), elements.all.end(), name) == elements.all.end()) {
      yaml::Fail(
          src, given, "metric_options.element", name,
          spec.form == ScenarioForm::kNetwork
              ? "must name an element of the network " + spec.base + ": " + List(elements.all)
              : "the single-actuator scenario " + spec.base +
                    " has one element, `actuator`: give that or leave element out");
    }
    return name;
  }
  if (elements.actuators.size() == 1) return elements.actuators.front();
  // the metrics read one element, and with none or several actuators none is the obvious one
  const YAML::Node at = options ? options : root["metrics"];
  const std::string actuators = elements.actuators.empty()
                                    ? "no actuator"
                                    : std::to_string(elements.actuators.size()) + " actuators (" +
                                          List(elements.actuators) + ")";
  throw InputError("metric_options.element (" + yaml::Location(src, at) +
                   "): missing: the network " + spec.base + " has " + actuators +
                   ", so name the element the metrics read, one of: " + List(elements.all));
}

}  // namespace musclesim
