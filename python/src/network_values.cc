#include "network_values.h"

#include <string_view>

#include "musclesim/io/network_csv.h"

namespace musclesim::python {

namespace {

bool IsPhase(std::string_view column) {
  constexpr std::string_view kSuffix = ".phase";
  return column.size() > kSuffix.size() && column.substr(column.size() - kSuffix.size()) == kSuffix;
}

}  // namespace

std::vector<std::string> NumericNetworkColumns(const NetworkSystem& system) {
  std::vector<std::string> columns;
  for (const std::string& column : NetworkCsvColumns(system)) {
    if (column != "t" && !IsPhase(column)) columns.push_back(column);
  }
  return columns;
}

// The order of NetworkCsvColumns (and NetworkCsvFormat::AppendRow) without t and phase.
void AppendNumericNetworkValues(const NetworkSystem& system, const NetworkSample& s,
                                std::vector<double>& values) {
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    values.push_back(s.position[i]);
    values.push_back(s.velocity[i]);
  }
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    const ElementSample& element = s.elements[e];
    const Element& spec = system.elements()[e];
    values.push_back(element.length);
    values.push_back(element.tension);
    if (spec.kind != ElementKind::kActuator) continue;
    values.push_back(0.0 - element.lengthening_rate);  // shortening velocity, +0 at rest
    values.push_back(element.activation);
    if (spec.excitation) values.push_back(element.excitation);
    values.push_back(element.parts.passive);
    values.push_back(element.parts.active);
  }
  for (std::size_t i = 0; i < system.nodes().size(); ++i) {
    if (system.nodes()[i].kind == NodeKind::kFree) values.push_back(s.load[i]);
  }
  for (const ControllerSample& controller : s.controllers) {
    values.push_back(controller.reference);
    values.push_back(controller.measured);
    values.push_back(controller.error);
    values.push_back(controller.output);
  }
}

}  // namespace musclesim::python
