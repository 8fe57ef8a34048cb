#include "sweep/sweep_metric_element.h"

#include <algorithm>

#include "musclesim/core/number_format.h"

namespace musclesim {

std::string ResolveMetricElement(const yaml::Source& src, const Document& root,
                                 const SweepSpec& spec, const MetricElements& elements) {
  const Document& options = root["metric_options"];
  if (options && options["element"]) {
    const Document& given = options["element"];
    const std::string name = yaml::ReadString(src, given, "metric_options.element");
    if (std::find(elements.all.begin(), elements.all.end(), name) == elements.all.end()) {
      yaml::Fail(src, given, "metric_options.element", name,
                 spec.form == ScenarioForm::kNetwork
                     ? "must name an element of the network " + spec.base + ": " +
                           CommaSeparated(elements.all)
                     : "the single-actuator scenario " + spec.base +
                           " has one element, `actuator`: give that or leave element out");
    }
    return name;
  }
  if (elements.actuators.size() == 1) return elements.actuators.front();
  // the metrics read one element, and with none or several actuators none is the obvious one
  const Document& at = options ? options : root["metrics"];
  const std::string actuators = elements.actuators.empty()
                                    ? "no actuator"
                                    : std::to_string(elements.actuators.size()) + " actuators (" +
                                          CommaSeparated(elements.actuators) + ")";
  throw InputError(InputFault{
      yaml::Place(src, at), "metric_options.element", std::nullopt,
      "missing: the network " + spec.base + " has " + actuators +
          ", so name the element the metrics read, one of: " + CommaSeparated(elements.all)});
}

}  // namespace musclesim
