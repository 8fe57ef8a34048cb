#include "musclesim/scenario/run_columns.h"

#include "musclesim/core/enum_names.h"
#include "musclesim/scenario/actuator_scenario.h"

namespace musclesim {

constexpr EnumName<Phase> kPhaseNames[] = {
    {Phase::kConcentric, "concentric"},
    {Phase::kEccentric, "eccentric"},
    {Phase::kIsometric, "isometric"},
};

std::string_view ToString(Phase phase) { return ToString(kPhaseNames, phase); }

RunColumns::RunColumns(const Scenario& scenario, const NetworkSystem& system)
    : RunColumns(scenario, system, scenario.form) {}

RunColumns::RunColumns(const Scenario& scenario, const NetworkSystem& system, ScenarioForm form) {
  if (form == ScenarioForm::kActuator) {
    AddActuatorView(scenario, system);
  } else {
    AddNetworkView(scenario, system);
  }
}

void RunColumns::Add(std::string name, Kind kind, int index, double tolerance) {
  names_.push_back(std::move(name));
  columns_.push_back({kind, index, tolerance});
  phase_flags_.push_back(kind == Kind::kPhase ? 1 : 0);
  if (kind >= Kind::kReference) whole_sample_ = true;  // a controller's
  if (OfElement(kind) && (elements_read_.empty() || elements_read_.back() != index)) {
    elements_read_.push_back(index);  // an element's columns are consecutive
  }
}

void RunColumns::AddActuatorView(const Scenario& scenario, const NetworkSystem& system) {
  const int e = kActuatorElement;
  Add("t", Kind::kTime);
  Add("length", Kind::kLength, e);
  Add("shortening_velocity", Kind::kShortening, e);
  Add("activation", Kind::kActivation, e);
  if (system.elements()[e].excitation) Add("excitation", Kind::kExcitation, e);
  Add("tension_passive", Kind::kPassive, e);
  Add("tension_active", Kind::kActive, e);
  Add("tension_total", Kind::kTotal, e);
  Add("load", Kind::kLoad, kActuatorTipNode);
  Add("phase", Kind::kPhase, e, scenario.PhaseTolerance(e));
  actuator_view_ = true;
  excitation_ = system.elements()[e].excitation.has_value();
}

void RunColumns::AddNetworkView(const Scenario& scenario, const NetworkSystem& system) {
  Add("t", Kind::kTime);
  const std::vector<Node>& nodes = system.nodes();
  const int d = system.dimensions();
  // in 2 or 3 dimensions: a column per coordinate, at its index in the sample (node-major)
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int node = static_cast<int>(i);
    if (d == 1) {
      Add(nodes[i].name + ".position", Kind::kPosition, node);
      Add(nodes[i].name + ".velocity", Kind::kVelocity, node);
      continue;
    }
    for (int c = 0; c < d; ++c) Add(nodes[i].name + "." + kAxes[c], Kind::kPosition, node * d + c);
    for (int c = 0; c < d; ++c) {
      Add(nodes[i].name + ".v" + kAxes[c], Kind::kVelocity, node * d + c);
    }
  }
  // Observe's sample holds the coordinates (FillFromState reads single values)
  whole_sample_ = whole_sample_ || d > 1;
  const Skeleton* skeleton = system.skeleton();
  const int coordinates = skeleton != nullptr ? skeleton->coordinate_count() : 0;
  for (int k = 0; k < coordinates; ++k) {
    Add(skeleton->coordinate(k).name + ".q", Kind::kCoordinate, k);
    Add(skeleton->coordinate(k).name + ".u", Kind::kSpeed, k);
  }
  for (std::size_t k = 0; k < system.elements().size(); ++k) {
    const Element& element = system.elements()[k];
    const int e = static_cast<int>(k);
    Add(element.name + ".length", Kind::kLength, e);
    Add(element.name + ".tension", Kind::kTension, e);
    for (int c = 0; c < coordinates; ++c) {
      if (!system.Spans(e, c)) continue;
      Add(element.name + ".moment_arm." + skeleton->coordinate(c).name, Kind::kMomentArm,
          e * coordinates + c);
    }
    if (element.kind != ElementKind::kActuator) continue;
    Add(element.name + ".shortening_velocity", Kind::kShortening, e);
    Add(element.name + ".activation", Kind::kActivation, e);
    if (element.excitation) Add(element.name + ".excitation", Kind::kExcitation, e);
    Add(element.name + ".tension_passive", Kind::kPassive, e);
    Add(element.name + ".tension_active", Kind::kActive, e);
    Add(element.name + ".phase", Kind::kPhase, e, scenario.PhaseTolerance(e));
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].kind != NodeKind::kFree) continue;
    const int node = static_cast<int>(i);
    if (d == 1) {
      Add(nodes[i].name + ".load", Kind::kLoad, node);
      continue;
    }
    for (int c = 0; c < d; ++c) {
      Add(nodes[i].name + ".load_" + kAxes[c], Kind::kLoad, node * d + c);
    }
  }
  for (std::size_t k = 0; k < system.controllers().size(); ++k) {
    const std::string& name = system.controllers()[k].name;
    const int c = static_cast<int>(k);
    Add(name + ".reference", Kind::kReference, c);
    Add(name + ".measured", Kind::kMeasured, c);
    Add(name + ".error", Kind::kError, c);
    Add(name + ".output", Kind::kOutput, c);
  }
}

void RunColumns::Fill(double t, const NetworkSample& s, double* row) const {
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Column& column = columns_[c];
    const auto i = static_cast<std::size_t>(column.index);
    switch (column.kind) {
      case Kind::kTime: row[c] = t; break;
      case Kind::kPosition: row[c] = s.position[i]; break;
      case Kind::kVelocity: row[c] = s.velocity[i]; break;
      case Kind::kLength: row[c] = s.elements[i].length; break;
      case Kind::kTension: row[c] = s.elements[i].tension; break;
      // +0 rather than -0 at rest
      case Kind::kShortening:
      case Kind::kPhase: row[c] = 0.0 - s.elements[i].lengthening_rate; break;
      case Kind::kActivation: row[c] = s.elements[i].activation; break;
      case Kind::kExcitation: row[c] = s.elements[i].excitation; break;
      case Kind::kPassive: row[c] = s.elements[i].parts.passive; break;
      case Kind::kActive: row[c] = s.elements[i].parts.active; break;
      case Kind::kTotal: row[c] = s.elements[i].parts.total; break;
      case Kind::kLoad: row[c] = s.load[i]; break;
      case Kind::kReference: row[c] = s.controllers[i].reference; break;
      case Kind::kMeasured: row[c] = s.controllers[i].measured; break;
      case Kind::kError: row[c] = s.controllers[i].error; break;
      case Kind::kOutput: row[c] = s.controllers[i].output; break;
      case Kind::kCoordinate: row[c] = s.coordinates[i]; break;
      case Kind::kSpeed: row[c] = s.speeds[i]; break;
      case Kind::kMomentArm: row[c] = s.moment_arms[i]; break;
    }
  }
}

bool RunColumns::FillFromState(const NetworkSystem& system, double t, const double* y, double* row,
                               std::vector<ElementSample>& scratch) const {
  if (whole_sample_) return false;
  scratch.resize(system.elements().size());
  if (actuator_view_) {
    // t, length, shortening_velocity, activation, [excitation], the tensions, load, phase
    ElementSample& s = scratch[kActuatorElement];
    system.ObserveElement(kActuatorElement, t, y, s);
    const double shortening = 0.0 - s.lengthening_rate;  // +0 rather than -0 at rest
    double* out = row;
    *out++ = t;
    *out++ = s.length;
    *out++ = shortening;
    *out++ = s.activation;
    if (excitation_) *out++ = s.excitation;
    *out++ = s.parts.passive;
    *out++ = s.parts.active;
    *out++ = s.parts.total;
    *out++ = system.LoadOn(kActuatorTipNode, t, y);
    *out = shortening;
    return true;
  }
  for (const int e : elements_read_)
    system.ObserveElement(e, t, y, scratch[static_cast<std::size_t>(e)]);
  const ElementSample* samples = scratch.data();
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Column& column = columns_[c];
    const ElementSample& s = samples[OfElement(column.kind) ? column.index : 0];
    switch (column.kind) {
      case Kind::kTime: row[c] = t; break;
      case Kind::kPosition: row[c] = system.NodePosition(column.index, t, y); break;
      case Kind::kVelocity: row[c] = system.NodeVelocity(column.index, t, y); break;
      case Kind::kLoad: row[c] = system.LoadOn(column.index, t, y); break;
      case Kind::kLength: row[c] = s.length; break;
      case Kind::kTension: row[c] = s.tension; break;
      // +0 rather than -0 at rest
      case Kind::kShortening:
      case Kind::kPhase: row[c] = 0.0 - s.lengthening_rate; break;
      case Kind::kActivation: row[c] = s.activation; break;
      case Kind::kExcitation: row[c] = s.excitation; break;
      case Kind::kPassive: row[c] = s.parts.passive; break;
      case Kind::kActive: row[c] = s.parts.active; break;
      case Kind::kTotal: row[c] = s.parts.total; break;
      default: break;  // a controller's: not reached (whole_sample_)
    }
  }
  return true;
}

}  // namespace musclesim
