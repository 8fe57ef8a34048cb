#include "scenario/sensitivity_columns.h"

#include <algorithm>

namespace musclesim {

SensitivityColumns::SensitivityColumns(ScenarioForm form, const NetworkSystem& system,
                                       const std::vector<SensitivityParameter>& parameters)
    : system_(system), parameters_(parameters) {
  const auto add = [&](std::string name, Kind kind, int index) {
    names_.push_back(std::move(name));
    columns_.push_back({kind, index});
  };
  if (form == ScenarioForm::kActuator) {
    // the single actuator's columns: element 0 is the actuator, state (x, xdot[, u])
    add("length", Kind::kPosition, 0);
    add("shortening_velocity", Kind::kShortening, 1);
    if (system.activation_count() > 0) add("activation", Kind::kActivation, 2);
    add("tension_passive", Kind::kPassive, 0);
    add("tension_active", Kind::kActive, 0);
    add("tension_total", Kind::kTension, 0);
  } else {
    const int d = system.dimensions();
    for (std::size_t i = 0; i < system.nodes().size(); ++i) {
      const int state = system.StateIndex(static_cast<int>(i));
      if (state < 0) continue;
      if (d > 1) {
        AddCoordinates(system.nodes()[i].name, d, state);
        continue;
      }
      add(system.nodes()[i].name + ".position", Kind::kPosition, state);
      const int velocity = system.VelocityStateIndex(static_cast<int>(i));
      // a massless junction's velocity is no state: a function of it and the parameters
      if (velocity >= 0) {
        add(system.nodes()[i].name + ".velocity", Kind::kVelocity, velocity);
      } else {
        add(system.nodes()[i].name + ".velocity", Kind::kJunctionVelocity, static_cast<int>(i));
      }
    }
    for (std::size_t e = 0; e < system.elements().size(); ++e) {
      const Element& element = system.elements()[e];
      const int index = static_cast<int>(e);
      add(element.name + ".length", Kind::kLength, index);
      add(element.name + ".tension", Kind::kTension, index);
      if (element.kind != ElementKind::kActuator) continue;
      const int state = system.ActivationStateIndex(index);
      if (state >= 0) add(element.name + ".activation", Kind::kActivation, state);
      add(element.name + ".tension_passive", Kind::kPassive, index);
      add(element.name + ".tension_active", Kind::kActive, index);
    }
  }
  partials_.resize(system.elements().size());
}

void SensitivityColumns::AddCoordinates(const std::string& node, int d, int state) {
  // named as the run's own columns (RunColumns): NODE.x, NODE.y (NODE.z), then NODE.vx ...;
  // the free node's states are its d coordinates, then their d rates
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int c = 0; c < d; ++c) {
    names_.push_back(std::string(node).append(".").append(kAxes[c]));
    columns_.push_back({Kind::kPosition, state + c});
  }
  for (int c = 0; c < d; ++c) {
    names_.push_back(std::string(node).append(".v").append(kAxes[c]));
    columns_.push_back({Kind::kVelocity, state + d + c});
  }
}

int SensitivityColumns::StateOf(std::size_t c, double& sign) const {
  const Column& column = columns_[c];
  sign = column.kind == Kind::kShortening ? -1.0 : 1.0;
  return column.kind < Kind::kLength ? column.index : -1;
}

void SensitivityColumns::Evaluate(double t, const double* y, const double* const* s, double* values,
                                  double* derivatives) {
  const NetworkSystem& system = system_;
  system.Observe(t, y, sample_);
  const std::size_t count = columns_.size();
  for (std::size_t c = 0; c < count; ++c) {
    const Column& column = columns_[c];
    if (column.kind == Kind::kJunctionVelocity) {
      values[c] = sample_.velocity[static_cast<std::size_t>(column.index)];
      continue;
    }
    const ElementSample* element =
        column.kind >= Kind::kLength ? &sample_.elements[column.index] : nullptr;
    switch (column.kind) {
      case Kind::kPosition:
      case Kind::kVelocity:
      case Kind::kActivation: values[c] = y[column.index]; break;
      case Kind::kShortening: values[c] = 0.0 - y[column.index]; break;  // +0 at rest, as the CSV
      case Kind::kLength: values[c] = element->length; break;
      case Kind::kTension: values[c] = element->tension; break;
      case Kind::kPassive: values[c] = element->parts.passive; break;
      case Kind::kActive: values[c] = element->parts.active; break;
      case Kind::kJunctionVelocity: break;  // (above)
    }
  }
  for (std::size_t p = 0; p < parameters_.size(); ++p) {
    const double* direction = s[p];
    std::fill(partials_.begin(), partials_.end(), NetworkSystem::ElementPartials{});
    parameters_[p].derivative->Elements(t, y, partials_.data(), scratch_);
    double* out = derivatives + p * count;
    int along_element = -1;  // the element `along` belongs to
    NetworkSystem::ElementPartials along;
    for (std::size_t c = 0; c < count; ++c) {
      const Column& column = columns_[c];
      if (column.kind < Kind::kLength) {
        const double state = direction[column.index];
        out[c] = column.kind == Kind::kShortening ? 0.0 - state : state;
        continue;
      }
      if (column.kind == Kind::kJunctionVelocity) {
        out[c] = system.NodeVelocityAlong(column.index, t, y, direction) +
                 parameters_[p].derivative->NodeVelocity(t, y, column.index, scratch_);
        continue;
      }
      // the chain rule: along the state's sensitivity, plus the parameter's own share; an
      // element's columns are consecutive, so its derivatives along s are computed once
      if (column.index != along_element) {
        along = system.Along(column.index, t, y, direction);
        along_element = column.index;
      }
      const NetworkSystem::ElementPartials& own = partials_[static_cast<std::size_t>(column.index)];
      switch (column.kind) {
        case Kind::kLength: out[c] = along.length + own.length; break;
        case Kind::kTension: out[c] = along.total + own.total; break;
        case Kind::kPassive: out[c] = along.passive + own.passive; break;
        default: out[c] = along.active + own.active; break;
      }
    }
  }
}

}  // namespace musclesim
