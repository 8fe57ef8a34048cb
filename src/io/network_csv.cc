#include "musclesim/io/network_csv.h"

#include <string_view>

#include "musclesim/io/trajectory_csv.h"

namespace musclesim {

namespace {

constexpr std::size_t kBlockBytes = 1 << 16;

// The columns an actuator adds after its length and tension; one with activation dynamics
// has `excitation` after `activation` too.
constexpr const char* kActuatorColumns[] = {"shortening_velocity", "activation",
                                            "tension_passive", "tension_active", "phase"};

// The columns of every controller, after the loads.
constexpr const char* kControllerColumns[] = {"reference", "measured", "error", "output"};

}  // namespace

std::vector<std::string> NetworkCsvColumns(const NetworkSystem& system) {
  std::vector<std::string> columns = {"t"};
  for (const Node& node : system.nodes()) {
    columns.push_back(node.name + ".position");
    columns.push_back(node.name + ".velocity");
  }
  for (const Element& element : system.elements()) {
    columns.push_back(element.name + ".length");
    columns.push_back(element.name + ".tension");
    if (element.kind != ElementKind::kActuator) continue;
    for (const char* column : kActuatorColumns) {
      columns.push_back(element.name + "." + column);
      if (element.excitation && std::string_view(column) == "activation") {
        columns.push_back(element.name + ".excitation");
      }
    }
  }
  for (const Node& node : system.nodes()) {
    if (node.kind == NodeKind::kFree) columns.push_back(node.name + ".load");
  }
  for (const Controller& controller : system.controllers()) {
    for (const char* column : kControllerColumns) columns.push_back(controller.name + "." + column);
  }
  return columns;
}

NetworkCsvFormat::NetworkCsvFormat(const NetworkSystem& system,
                                   std::optional<double> phase_tolerance) {
  for (const std::string& column : NetworkCsvColumns(system)) {
    header_ += (header_.empty() ? "" : ",") + column;
  }
  for (const Element& element : system.elements()) {
    excitation_.push_back(element.excitation.has_value());
    // the single actuator's default (ScenarioSpec::PhaseTolerance): its model's epsilon
    phase_tolerance_.push_back(
        element.kind != ElementKind::kActuator
            ? -1.0
            : phase_tolerance.value_or(element.model->params().velocity.epsilon));
  }
  for (std::size_t i = 0; i < system.nodes().size(); ++i) {
    if (system.nodes()[i].kind == NodeKind::kFree) free_nodes_.push_back(static_cast<int>(i));
  }
}

void NetworkCsvFormat::AppendRow(std::string& csv, double t, const NetworkSample& s) const {
  const auto number = [&](double value) {
    csv += ',';
    csv += FormatFull(value);
  };
  csv += FormatFull(t);
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    number(s.position[i]);
    number(s.velocity[i]);
  }
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    const ElementSample& element = s.elements[e];
    number(element.length);
    number(element.tension);
    if (phase_tolerance_[e] < 0.0) continue;
    // +0 rather than -0 at rest, as the single actuator's column
    const double shortening_velocity = 0.0 - element.lengthening_rate;
    number(shortening_velocity);
    number(element.activation);
    if (excitation_[e]) number(element.excitation);
    number(element.parts.passive);
    number(element.parts.active);
    csv += ',';
    csv += ToString(ClassifyPhase(shortening_velocity, phase_tolerance_[e]));
  }
  for (const int node : free_nodes_) number(s.load[static_cast<std::size_t>(node)]);
  for (const ControllerSample& controller : s.controllers) {
    number(controller.reference);
    number(controller.measured);
    number(controller.error);
    number(controller.output);
  }
  csv += '\n';
}

std::string FormatNetworkCsv(const NetworkSystem& system, const NetworkRunResult& result,
                             std::optional<double> phase_tolerance) {
  const NetworkCsvFormat format(system, phase_tolerance);
  std::string csv = format.header() + "\n";
  for (std::size_t k = 0; k < result.times.size(); ++k) {
    format.AppendRow(csv, result.times[k], result.samples[k]);
  }
  return csv;
}

NetworkCsvWriter::NetworkCsvWriter(StreamedOutput& output, const NetworkSystem& system,
                                   std::optional<double> phase_tolerance)
    : output_(output), format_(system, phase_tolerance) {
  buffer_.reserve(kBlockBytes + 4096);
  buffer_ += format_.header();
  buffer_ += '\n';
}

void NetworkCsvWriter::Record(double t, const NetworkSample& sample) {
  format_.AppendRow(buffer_, t, sample);
  ++rows_;
  if (buffer_.size() >= kBlockBytes) Flush();
}

void NetworkCsvWriter::Flush() {
  output_.Write(buffer_);
  buffer_.clear();
}

}  // namespace musclesim
