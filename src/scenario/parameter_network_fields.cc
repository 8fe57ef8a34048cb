// The network's keys as parameter handles: nodes (with their coordinates), elements (with
// via points and De Groote's tendon), loads, controllers, the run's settings and the
// waveforms' fields.
#include "scenario/parameter_resolver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/dynamics/waveform_shapes.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/setting_fields.h"
#include "musclesim/solver/solver_fields.h"

namespace musclesim {

namespace {

// A length limit [m]: 0 (the element collapsed) to the longest length a file may give.
constexpr InputRange kLimitRange{0.0, 1e3, "m", "a kilometre is beyond any actuator"};

}  // namespace

std::size_t ParameterResolver::Coordinate(std::size_t i, const std::string& key) const {
  const int d = scenario_.space.dimensions;
  const bool indexed = i < steps_.size() && steps_[i].key.empty();
  if (d == 1) {
    if (indexed) Fail("takes no index: " + key + " is one number, x, in 1 dimension");
    return 0;
  }
  const std::string last = std::to_string(d - 1);
  if (!indexed) {
    Fail("needs a coordinate's index in " + std::to_string(d) + " dimensions: " + key +
         "[0] (x) to " + key + "[" + last + "]");
  }
  if (steps_[i].index >= static_cast<std::size_t>(d)) {
    Fail("indexes past the " + std::to_string(d) + " coordinates of " + key + " (0 to " + last +
         ")");
  }
  return steps_[i].index;
}

void ParameterResolver::Node(std::size_t i) {
  const std::size_t n = Index(i, scenario_.nodes.size(), "nodes");
  const std::string& key = Key(i + 1);
  const NodeKind kind = scenario_.nodes[n].kind;
  const Locate<musclesim::Node> node = [n](Scenario& s) -> musclesim::Node& { return s.nodes[n]; };
  if (Signal(i + 1, NodeSignals(), scenario_.nodes[n], node)) return;
  // in 2 or 3 dimensions a coordinate is indexed (nodes[1].position[1] is y)
  const std::size_t next = scenario_.space.dimensions > 1 ? i + 3 : i + 2;
  const NodeVariant& variant = *VariantOf(NodeKinds(), scenario_.nodes[n]);
  if (const PointField<musclesim::Node>* point = FindPoint(variant, key)) {
    const std::size_t c = Coordinate(i + 2, key);
    End(next);
    // the single actuator's node: its position is the actuator's length, above 0
    const bool length = IsSingleActuator(scenario_) && key == "position";
    return Point(*point, node, c, length ? kLengthRange : point->range);
  }
  End(i + 2);
  if (const NumberField<musclesim::Node>* field = FindField(variant, key)) {
    return Field(*field, node);
  }
  Fail("names no number of this " + std::string(ToString(kind)) + " node");
}

void ParameterResolver::Element(std::size_t i) {
  const std::size_t e = Index(i, scenario_.elements.size(), "elements");
  const std::string& key = Key(i + 1);
  const musclesim::Element& element = scenario_.elements[e];
  const Locate<musclesim::Element> at = [e](Scenario& s) -> musclesim::Element& {
    return s.elements[e];
  };
  if (key == "via") return Via(i + 2, e);
  if (element.kind == ElementKind::kActuator) {
    // a controlled actuator's activation is its controller's output
    if (!element.controlled && Signal(i + 1, ActuatorSignals<musclesim::Element>(), element, at)) {
      return;
    }
    if (key == "activation_dynamics" && element.excitation) {
      const ActivationFamilyVariant& family =
          *VariantOf(ActivationFamilies(), element.excitation->dynamics);
      const auto* field = FindField(family, PathFrom(i + 2));
      if (field == nullptr) {
        Fail("names no number of " + std::string(family.name) + "'s activation dynamics (" +
             FieldKeys(family) + ")");
      }
      return Field(*field, Locate<ActivationDynamics>([at](Scenario& s) -> ActivationDynamics& {
        return at(s).excitation->dynamics;
      }));
    }
    if (key == "initial_activation" && element.excitation) {
      End(i + 2);
      p_.get_ = [e](const Scenario& s) {
        return s.elements[e].excitation->InitialActivation(s.t_start);
      };
      p_.set_ = [e](Scenario& s, double v) { s.elements[e].excitation->initial_activation = v; };
      p_.range_ = kActivationRange;
      p_.bounded_ = true;
      return;
    }
    Fail("names no number of this actuator");
  }
  // a spring's, tendon's or damper's field, as its law describes it (element_laws.h); the
  // element and path let the sensitivities find its closed-form derivative
  const ElementLaw* law = LawOf(element);
  const std::string field_path = PathFrom(i + 1);
  const ElementField* field = law == nullptr ? nullptr : FindField(*law, field_path);
  if (law == nullptr) Fail("names no number of this element");
  if (field == nullptr) {
    Fail("names no number of this " + std::string(law->name) + " (" + FieldKeys(*law) + ")");
  }
  p_.element_ = static_cast<int>(e);
  p_.element_path_ = field_path;
  Field(*field, at);
}

void ParameterResolver::Via(std::size_t i, std::size_t e) {
  const std::vector<ViaPoint>& via = scenario_.elements[e].via;
  const std::size_t k = Index(i, via.size(), "via");
  if (!via[k].node.empty()) {
    Fail("names a via point that is node " + via[k].node +
         ": its coordinates are that node's (nodes[...].position or fixed)");
  }
  const std::size_t c = Coordinate(i + 1, "via[" + std::to_string(k) + "]");
  End(i + 2);
  Number([e, k, c](Scenario& s) -> double& { return s.elements[e].via[k].position[c]; },
         &kPositionRange);
}

void ParameterResolver::Load(std::size_t i) {
  const std::size_t k = Index(i, scenario_.loads.size(), "loads");
  const musclesim::Load& load = scenario_.loads[k].load;
  const Locate<musclesim::Load> at = [k](Scenario& s) -> musclesim::Load& {
    return s.loads[k].load;
  };
  if (load.kind == LoadKind::kForce) {
    return WaveformField(
        i + 1, [at](Scenario& s) -> Waveform& { return at(s).force; }, &kForceRange);
  }
  const LoadVariant& variant = *VariantOf(LoadVariants(), load);
  const NumberField<musclesim::Load>* field = FindField(variant, PathFrom(i + 1));
  if (field == nullptr) {
    Fail("names no number of this " + std::string(variant.name) + " (" + FieldKeys(variant) + ")");
  }
  Field(*field, at);
}

void ParameterResolver::Controller(std::size_t i) {
  const std::size_t c = Index(i, scenario_.controllers.size(), "controllers");
  const std::string& key = Key(i + 1);
  const musclesim::Controller& controller = scenario_.controllers[c];
  const Locate<musclesim::Controller> at = [c](Scenario& s) -> musclesim::Controller& {
    return s.controllers[c];
  };
  if (key == "gains") {
    const NumberField<PidGains>* field = FindField(ControllerGains().front(), PathFrom(i + 2));
    if (field == nullptr) Fail("names no gain (" + FieldKeys(ControllerGains().front()) + ")");
    return Field(*field, Locate<PidGains>([at](Scenario& s) -> PidGains& { return at(s).gains; }));
  }
  if (Signal(i + 1, ControllerSignals(), controller, at)) return;
  Fail("names no number of this controller");
}

void ParameterResolver::Setting(std::size_t i) {
  p_.setting_ = true;
  const std::string& block = Key(i);
  const std::string& key = Key(i + 1);
  if (block == "limits") {
    const std::size_t k = Index(i + 1, scenario_.limits.size(), "limits");
    End(i + 3);
    const std::string& leaf = Key(i + 2);
    const bool low = leaf == "min_length";
    if ((!low && leaf != "max_length") ||
        !(low ? scenario_.limits[k].min_length : scenario_.limits[k].max_length)) {
      Fail("names no length limit of this scenario");
    }
    return Number(
        [k, low](Scenario& s) -> double& {
          LengthLimit& limit = s.limits[k];
          return low ? *limit.min_length : *limit.max_length;
        },
        &kLimitRange);
  }
  End(i + 2);
  if (block == "time") {
    // the span's fields are the scenario's own t_start and t_end
    if (const NumberField<TimeSpan>* field = FindField(TimeBlock().front(), key)) {
      const bool start = key == "start";
      return Number([start](Scenario& s) -> double& { return start ? s.t_start : s.t_end; },
                    &field->range);
    }
  }
  if (block == "solver") {
    const NumberField<SolverOptions>* field = FindField(SolverBlock().front(), key);
    if (field != nullptr) {
      return Field(*field,
                   Locate<SolverOptions>([](Scenario& s) -> SolverOptions& { return s.solver; }));
    }
  }
  if (block == "output") {
    const NumberField<OutputRequest>* field = FindField(OutputBlock().front(), key);
    if (field != nullptr && (!field->given || field->given(scenario_.output))) {
      return Field(*field,
                   Locate<OutputRequest>([](Scenario& s) -> OutputRequest& { return s.output; }));
    }
  }
  Fail("names no numeric setting of the scenario");
}

void ParameterResolver::WaveformField(std::size_t i, Locate<Waveform> at,
                                      const InputRange* values) {
  // constant, the shape in the context of this waveform: its time fields are times, the rest
  // values of the signal
  const Waveform& w = at(const_cast<Scenario&>(scenario_));
  const WaveformShape& shape = WaveformShapes()[static_cast<std::size_t>(w.kind)];
  if (w.kind == WaveformKind::kTable && Key(i) == "points") {
    const std::size_t k = Index(i + 1, w.points.size(), "points");
    const std::size_t column = Index(i + 2, 2, "a [t, value] point");
    End(i + 3);
    return Number(
        [at, k, column](Scenario& s) -> double& {
          TablePoint& point = at(s).points[k];
          return column == 0 ? point.t : point.value;
        },
        column == 0 ? &kTimeRange : values);
  }
  const NumberField<Waveform>* field = FindField(shape, PathFrom(i));
  if (field == nullptr) {
    Fail("names no field of this " + std::string(shape.name) + " waveform (" +
         (w.kind == WaveformKind::kTable ? "points[k][0], points[k][1]" : FieldKeys(shape)) + ")");
  }
  Field(*field, at, field->values == FieldValues::kSignal ? values : nullptr);
}

}  // namespace musclesim
