// Resolving a key path into a handle: the path split into steps, a single actuator's keys
// translated into its network's (scenario/actuator_scenario.h), then one block at a time,
// each knowing the keys its part has and the range the file reader checks them against.
#include "musclesim/scenario/parameter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/key_path.h"
#include "musclesim/core/number_format.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

namespace {

// `steps` written back the one way: "load[0].after" for "load[00]after".
std::string Canonical(const std::vector<KeyPathStep>& steps) {
  std::string path;
  for (const KeyPathStep& step : steps) {
    // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::string
    if (step.key.empty()) {
      path.append("[").append(std::to_string(step.index)).append("]");
    } else {
      if (!path.empty()) path += '.';
      path += step.key;
    }
  }
  return path;
}

// A length limit [m]: 0 (the element collapsed) to the longest length a file may give.
constexpr InputRange kLimitRange{0.0, 1e3, "m", "a kilometre is beyond any actuator"};

// A reference into the scenario (or a model block) from its parts' indices, for both Get
// (const) and Set.
template <typename T, typename In = Scenario>
using Locate = std::function<T&(In&)>;

}  // namespace

// Walks the steps of one path and fills the handle.
class ParameterResolver {
 public:
  ParameterResolver(const Scenario& scenario, std::string path)
      : scenario_(scenario), given_(std::move(path)) {}

  Parameter Resolve() {
    std::optional<std::vector<KeyPathStep>> steps = SplitKeyPath(given_);
    if (!steps || steps->empty() || steps->front().key.empty()) {
      throw ParameterError(given_, "", "is not a key path such as model.f_iso or load[0].value");
    }
    p_.path_ = Canonical(*steps);
    p_.network_path_ = p_.path_;
    if (scenario_.form == ScenarioForm::kActuator) {
      const std::optional<std::string> translated = NetworkKeyPath(p_.path_);
      if (!translated) Fail("names no key of a single-actuator scenario");
      p_.network_path_ = Canonical(*SplitKeyPath(*translated));
    }
    steps_ = *SplitKeyPath(p_.network_path_);
    Top();
    return std::move(p_);
  }

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

  void Top();
  void DeGrooteTendon(std::size_t i, std::size_t e);
  void Model(std::size_t i);
  void ModelField(std::size_t i, bool fitted);
  // A key of a model block of another family than the paper's (docs/model.md 14.1).
  void FamilyField(std::size_t i, CurveFamily family);
  void ModelNumber(Locate<double, ModelSpec> at, bool refits = false);
  void ModelValue(std::function<double(const ModelSpec&)> get,
                  std::function<void(ModelSpec&, double)> set, bool refits = false);
  void PassiveField(std::size_t i);
  void VelocityField(std::size_t i);
  void EccentricField(std::size_t i);
  void ActiveLengthField(std::size_t i);
  void GaussianField(std::size_t i);
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

void ParameterResolver::Top() {
  const std::string& top = Key(0);
  if (top == "models") return Model(1);
  if (top == "nodes") return Node(1);
  if (top == "elements") return Element(1);
  if (top == "loads") return Load(1);
  if (top == "controllers") return Controller(1);
  if (top == "gravity") return Gravity(1);
  if (top == "time" || top == "solver" || top == "output" || top == "limits") return Setting(0);
  Fail(
      "names no numeric value of the scenario (a model, node, element, load, controller, "
      "gravity, time, solver, output or limits key)");
}

void ParameterResolver::Gravity(std::size_t i) {
  if (scenario_.space.dimensions == 1) {
    Fail("names nothing in 1 dimension: on a line a weight is a load of type mass");
  }
  const std::size_t c = Coordinate(i, "gravity");
  End(i + 1);
  Number([c](Scenario& s) -> double& { return s.space.gravity[c]; }, &kGravityRange);
}

void ParameterResolver::Model(std::size_t i) {
  const auto found = scenario_.models.find(Key(i));
  if (Key(i).empty() || found == scenario_.models.end()) Fail("names no model block");
  p_.model_ = found->first;
  std::vector<KeyPathStep> rest(steps_.begin() + static_cast<long>(i) + 1, steps_.end());
  p_.model_path_ = Canonical(rest);
  const CurveFamily family = found->second.spec.params.family;
  if (family != CurveFamily::kPaper) return FamilyField(i + 1, family);
  ModelField(i + 1, found->second.spec.fit.has_value());
}

void ParameterResolver::FamilyField(std::size_t i, CurveFamily family) {
  fitted_ = false;
  const std::string& key = Key(i);
  const auto number = [&](Locate<double, ModelSpec> at) {
    End(i + 1);
    ModelNumber(std::move(at));
  };
  if (key == "f_iso") return number([](ModelSpec& m) -> double& { return m.params.f_iso; });
  if (key == "pennation_angle") {
    return number([](ModelSpec& m) -> double& { return m.params.pennation_angle; });
  }
  if (family == CurveFamily::kDeGroote2016) {
    using Field = double DeGrooteParams::*;
    static const std::pair<const char*, Field> kFields[] = {
        {"optimal_fiber_length", &DeGrooteParams::optimal_fiber_length},
        {"max_contraction_velocity", &DeGrooteParams::max_contraction_velocity},
        {"active_force_width_scale", &DeGrooteParams::active_force_width_scale},
        {"passive_fiber_strain_at_one_norm_force",
         &DeGrooteParams::passive_fiber_strain_at_one_norm_force},
        {"fiber_damping", &DeGrooteParams::fiber_damping}};
    for (const auto& [name, field] : kFields) {
      if (key != name) continue;
      const Field member = field;
      return number([member](ModelSpec& m) -> double& { return m.params.degroote2016.*member; });
    }
    Fail(
        "names no parameter of a degroote2016 model (f_iso, pennation_angle, "
        "optimal_fiber_length, max_contraction_velocity, active_force_width_scale, "
        "passive_fiber_strain_at_one_norm_force, fiber_damping)");
  }
  if (key == "range" || key == "lengthrange") {
    const std::size_t end = Index(i + 1, 2, key == "range" ? "range" : "lengthrange");
    End(i + 2);
    if (key == "range") {
      return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.range[end]; });
    }
    return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.lengthrange[end]; });
  }
  using Field = double MujocoMuscleParams::*;
  static const std::pair<const char*, Field> kFields[] = {{"lmin", &MujocoMuscleParams::lmin},
                                                          {"lmax", &MujocoMuscleParams::lmax},
                                                          {"vmax", &MujocoMuscleParams::vmax},
                                                          {"fpmax", &MujocoMuscleParams::fpmax},
                                                          {"fvmax", &MujocoMuscleParams::fvmax}};
  for (const auto& [name, field] : kFields) {
    if (key != name) continue;
    const Field member = field;
    return number([member](ModelSpec& m) -> double& { return m.params.mujoco.*member; });
  }
  Fail(
      "names no parameter of a mujoco model (f_iso, pennation_angle, range, lengthrange, lmin, "
      "lmax, vmax, fpmax, fvmax)");
}

void ParameterResolver::ModelField(std::size_t i, bool fitted) {
  fitted_ = fitted;
  const std::string& block = Key(i);
  if (block == "f_iso") {
    End(i + 1);
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.f_iso; });
  }
  if (block == "pennation_angle") {
    End(i + 1);
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.pennation_angle; });
  }
  if (block == "passive") return PassiveField(i + 1);
  if (block == "velocity") return VelocityField(i + 1);
  if (block == "active_length") return ActiveLengthField(i + 1);
  Fail("names no numeric parameter of a model block");
}

void ParameterResolver::ModelNumber(Locate<double, ModelSpec> at, bool refits) {
  p_.model_get_ = [at](const ModelSpec& m) { return at(const_cast<ModelSpec&>(m)); };
  p_.model_set_ = [at](ModelSpec& m, double v) { at(m) = v; };
  p_.refits_ = refits && fitted_;
}

void ParameterResolver::ModelValue(std::function<double(const ModelSpec&)> get,
                                   std::function<void(ModelSpec&, double)> set, bool refits) {
  p_.model_get_ = std::move(get);
  p_.model_set_ = std::move(set);
  p_.refits_ = refits && fitted_;
}

void ParameterResolver::PassiveField(std::size_t i) {
  End(i + 1);
  const std::string& key = Key(i);
  if (key == "k_p")
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.passive.k_p; });
  if (key == "alpha") {
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.passive.alpha; });
  }
  if (key == "slack_length") {
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.passive.slack_length; });
  }
  Fail("names no parameter of the passive curve (k_p, alpha, slack_length)");
}

void ParameterResolver::VelocityField(std::size_t i) {
  const std::string& key = Key(i);
  if (key == "eccentric") return EccentricField(i + 1);
  End(i + 1);
  if (key == "v_max") {
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.velocity.v_max; });
  }
  if (key == "epsilon") {
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.velocity.epsilon; });
  }
  if (key == "n") {
    p_.integer_ = true;
    return ModelValue([](const ModelSpec& m) { return static_cast<double>(m.params.velocity.n); },
                      [](ModelSpec& m, double v) { m.params.velocity.n = static_cast<int>(v); });
  }
  Fail("names no parameter of the velocity curve (v_max, n, epsilon, eccentric)");
}

void ParameterResolver::EccentricField(std::size_t i) {
  // each optional, its value when left out the one the curve takes (docs/model.md 9)
  End(i + 1);
  const std::string& key = Key(i);
  if (key == "v_max") {
    return ModelValue(
        [](const ModelSpec& m) {
          const VelocityParams& v = m.params.velocity;
          return v.eccentric.v_max.value_or(v.v_max);
        },
        [](ModelSpec& m, double v) { m.params.velocity.eccentric.v_max = v; });
  }
  if (key == "n") {
    p_.integer_ = true;
    return ModelValue(
        [](const ModelSpec& m) {
          const VelocityParams& v = m.params.velocity;
          return static_cast<double>(v.eccentric.n.value_or(v.n));
        },
        [](ModelSpec& m, double v) { m.params.velocity.eccentric.n = static_cast<int>(v); });
  }
  if (key == "limit") {
    return ModelValue(
        [](const ModelSpec& m) {
          return m.params.velocity.eccentric.limit.value_or(
              std::numeric_limits<double>::infinity());
        },
        [](ModelSpec& m, double v) { m.params.velocity.eccentric.limit = v; });
  }
  Fail("names no parameter of the eccentric branch (v_max, n, limit)");
}

void ParameterResolver::ActiveLengthField(std::size_t i) {
  const std::string& key = Key(i);
  if (key == "optimal_range") {
    const std::size_t end = Index(i + 1, 2, "optimal_range");
    End(i + 2);
    return ModelNumber(
        [end](ModelSpec& m) -> double& {
          ActiveLengthParams& a = m.params.active_length;
          return end == 0 ? a.optimal_min : a.optimal_max;
        },
        true);
  }
  if (key == "sigma") {
    End(i + 1);
    return ModelNumber([](ModelSpec& m) -> double& { return m.params.active_length.sigma; }, true);
  }
  if (key == "gaussians") return GaussianField(i + 1);
  if (key == "fit" && fitted_) {
    End(i + 2);
    const std::string& leaf = Key(i + 1);
    if (leaf == "count") {
      p_.integer_ = true;
      return ModelValue([](const ModelSpec& m) { return static_cast<double>(m.fit->count); },
                        [](ModelSpec& m, double v) { m.fit->count = static_cast<int>(v); }, true);
    }
    if (leaf == "optimal_length") {
      return ModelValue([](const ModelSpec& m) { return m.fit->optimal_length.value_or(0.0); },
                        [](ModelSpec& m, double v) { m.fit->optimal_length = v; }, true);
    }
  }
  Fail("names no numeric parameter of the active length curve");
}

void ParameterResolver::GaussianField(std::size_t i) {
  if (fitted_) Fail("is fitted when the model is built: change the fit's settings instead");
  const std::size_t count =
      scenario_.models.at(p_.model_).spec.params.active_length.gaussians.size();
  const std::size_t k = Index(i, count, "gaussians");
  End(i + 2);
  const std::string& leaf = Key(i + 1);
  using Member = double Gaussian::*;
  const Member member = leaf == "amplitude" ? &Gaussian::amplitude
                        : leaf == "width"   ? &Gaussian::precision
                        : leaf == "center"  ? &Gaussian::center
                                            : nullptr;
  if (member == nullptr) Fail("names no field of a Gaussian (amplitude, width, center)");
  ModelNumber(
      [k, member](ModelSpec& m) -> double& { return m.params.active_length.gaussians[k].*member; });
}

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
  // in 2 or 3 dimensions a coordinate is indexed (nodes[1].position[1] is y): x is the
  // scalar field, y and z the _yz ones
  const bool coordinates = (kind == NodeKind::kFixed && key == "fixed") ||
                           (kind == NodeKind::kPrescribed && key == "prescribed") ||
                           (kind == NodeKind::kFree && (key == "position" || key == "velocity"));
  const std::size_t c = coordinates ? Coordinate(i + 2, key) : 0;
  const std::size_t next = scenario_.space.dimensions > 1 && coordinates ? i + 3 : i + 2;
  if (kind == NodeKind::kPrescribed && key == "prescribed") {
    return WaveformField(
        next,
        [node, c](Scenario& s) -> Waveform& {
          return c == 0 ? node(s).motion : node(s).motion_yz[c - 1];
        },
        &kPositionRange);
  }
  End(next);
  if (kind == NodeKind::kFixed && key == "fixed") {
    return Number(
        [node, c](Scenario& s) -> double& {
          return c == 0 ? node(s).position : node(s).position_yz[c - 1];
        },
        &kPositionRange);
  }
  if (kind == NodeKind::kFree) {
    if (key == "mass")
      return Number([node](Scenario& s) -> double& { return node(s).mass; }, &kMassRange);
    if (key == "position") {
      return Number(
          [node, c](Scenario& s) -> double& {
            return c == 0 ? node(s).position : node(s).position_yz[c - 1];
          },
          scenario_.form == ScenarioForm::kActuator ? &kLengthRange : &kPositionRange);
    }
    if (key == "velocity") {
      return Number(
          [node, c](Scenario& s) -> double& {
            return c == 0 ? node(s).velocity : node(s).velocity_yz[c - 1];
          },
          &kSpeedRange);
    }
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
    if (key == "activation" && !element.excitation && !element.controlled) {
      return WaveformField(
          i + 2, [at](Scenario& s) -> Waveform& { return at(s).activation; }, nullptr);
    }
    if (key == "excitation" && element.excitation && !element.controlled) {
      return WaveformField(
          i + 2, [at](Scenario& s) -> Waveform& { return at(s).excitation->signal; }, nullptr);
    }
    if (key == "activation_dynamics" && element.excitation) {
      End(i + 3);
      const std::string& leaf = Key(i + 2);
      if (leaf != "tau_activation" && leaf != "tau_deactivation") {
        Fail("names no time constant (tau_activation, tau_deactivation)");
      }
      const bool rise = leaf == "tau_activation";
      return Number(
          [at, rise](Scenario& s) -> double& {
            ActivationDynamics& d = at(s).excitation->dynamics;
            return rise ? d.tau_activation : d.tau_deactivation;
          },
          &kActivationTimeConstantRange);
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
  // a spring's, tendon's or damper's own coefficient: its sensitivity has a closed form
  p_.element_ = static_cast<int>(e);
  std::vector<KeyPathStep> rest(steps_.begin() + static_cast<long>(i) + 1, steps_.end());
  p_.element_path_ = Canonical(rest);
  const auto coefficient = [&](double musclesim::Element::*member, const InputRange* range) {
    Number([at, member](Scenario& s) -> double& { return at(s).*member; }, range);
  };
  if (element.pushes_below_slack) return DeGrooteTendon(i, e);
  if (key == "exponential" && element.exponential()) {
    End(i + 3);
    if (Key(i + 2) == "k") return coefficient(&musclesim::Element::k, &kPositiveForceRange);
    if (Key(i + 2) == "alpha") return coefficient(&musclesim::Element::alpha, nullptr);
  }
  End(i + 2);
  switch (element.kind) {
    case ElementKind::kSpring:
      if (key == "stiffness") return coefficient(&musclesim::Element::stiffness, &kStiffnessRange);
      if (key == "rest_length")
        return coefficient(&musclesim::Element::rest_length, &kPositionRange);
      break;
    case ElementKind::kTendon:
      if (key == "slack_length")
        return coefficient(&musclesim::Element::slack_length, &kPositionRange);
      if (key == "stiffness" && !element.exponential()) {
        return coefficient(&musclesim::Element::stiffness, &kStiffnessRange);
      }
      break;
    case ElementKind::kDamper:
      if (key == "damping") return coefficient(&musclesim::Element::damping, &kDampingRange);
      break;
    case ElementKind::kActuator: break;
  }
  Fail("names no number of this " + std::string(ToString(element.kind)));
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

// De Groote's tendon's slack length: > 0, the law is normalised by it.
constexpr InputRange kDeGrooteSlackRange{
    0.0, kPositionRange.max, "m", "De Groote's tendon is normalised by its slack length", true};

void ParameterResolver::DeGrooteTendon(std::size_t i, std::size_t e) {
  // its YAML keys, each setting what the law holds (k = 0.2 F0, alpha = ln 6 / (strain l_s)):
  // its slack length keeps the strain, as a scenario read with it would
  const std::string& key = Key(i + 1);
  const auto number = [&](std::function<double(const musclesim::Element&)> get,
                          std::function<void(musclesim::Element&, double)> set,
                          const InputRange& range) {
    p_.get_ = [e, get](const Scenario& s) { return get(s.elements[e]); };
    p_.set_ = [e, set](Scenario& s, double v) { set(s.elements[e], v); };
    p_.range_ = range;
    p_.bounded_ = true;
  };
  if (key == "slack_length") {
    End(i + 2);
    return number([](const musclesim::Element& x) { return x.slack_length; },
                  [](musclesim::Element& x, double v) {
                    x.alpha *= x.slack_length / v;
                    x.slack_length = v;
                  },
                  kDeGrooteSlackRange);
  }
  if (key == "degroote2016") {
    End(i + 3);
    if (Key(i + 2) == "max_isometric_force") {
      return number([](const musclesim::Element& x) { return x.k / 0.2; },
                    [](musclesim::Element& x, double v) { x.k = 0.2 * v; }, kPositiveForceRange);
    }
    if (Key(i + 2) == "strain_at_one_norm_force") {
      return number(
          [](const musclesim::Element& x) { return std::log(6.0) / (x.alpha * x.slack_length); },
          [](musclesim::Element& x, double v) { x.alpha = std::log(6.0) / (v * x.slack_length); },
          kTendonStrainRange);
    }
  }
  Fail(
      "names no number of this De Groote tendon (slack_length, "
      "degroote2016.max_isometric_force, degroote2016.strain_at_one_norm_force)");
}

void ParameterResolver::Load(std::size_t i) {
  const std::size_t k = Index(i, scenario_.loads.size(), "loads");
  const std::string& key = Key(i + 1);
  const musclesim::Load& load = scenario_.loads[k].load;
  const Locate<musclesim::Load> at = [k](Scenario& s) -> musclesim::Load& {
    return s.loads[k].load;
  };
  if (load.kind == LoadKind::kForce) {
    return WaveformField(
        i + 1, [at](Scenario& s) -> Waveform& { return at(s).force; }, &kForceRange);
  }
  End(i + 2);
  const auto field = [&](double musclesim::Load::*member, const InputRange& range) {
    Number([at, member](Scenario& s) -> double& { return at(s).*member; }, &range);
  };
  if (load.kind == LoadKind::kSpring) {
    if (key == "stiffness") return field(&musclesim::Load::stiffness, kStiffnessRange);
    if (key == "anchor") return field(&musclesim::Load::anchor, kPositionRange);
  } else {
    if (key == "mass") return field(&musclesim::Load::mass, kMassRange);
    if (key == "gravity") return field(&musclesim::Load::gravity, kGravityRange);
  }
  Fail("names no number of this load");
}

void ParameterResolver::Controller(std::size_t i) {
  const std::size_t c = Index(i, scenario_.controllers.size(), "controllers");
  const std::string& key = Key(i + 1);
  const musclesim::Controller& controller = scenario_.controllers[c];
  const Locate<musclesim::Controller> at = [c](Scenario& s) -> musclesim::Controller& {
    return s.controllers[c];
  };
  if (key == "gains") {
    End(i + 3);
    const std::string& leaf = Key(i + 2);
    double PidGains::*member = leaf == "kp"   ? &PidGains::kp
                               : leaf == "ki" ? &PidGains::ki
                               : leaf == "kd" ? &PidGains::kd
                                              : nullptr;
    if (member == nullptr) Fail("names no gain (kp, ki, kd)");
    return Number([at, member](Scenario& s) -> double& { return at(s).gains.*member; },
                  &kGainRange);
  }
  if (key == "reference") {
    const bool tension = controller.measure.quantity == MeasuredQuantity::kTension;
    return WaveformField(
        i + 2, [at](Scenario& s) -> Waveform& { return at(s).reference; },
        tension ? &kForceRange : &kPositionRange);
  }
  if (key == "feedforward") {
    return WaveformField(
        i + 2, [at](Scenario& s) -> Waveform& { return at(s).feedforward; }, &kFeedforwardRange);
  }
  if (key == "co_contraction" && controller.co_contraction && Key(i + 2) == "level") {
    return WaveformField(
        i + 3, [at](Scenario& s) -> Waveform& { return at(s).co_contraction->level; }, nullptr);
  }
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
  if (block == "time" && (key == "start" || key == "end")) {
    const bool start = key == "start";
    return Number([start](Scenario& s) -> double& { return start ? s.t_start : s.t_end; },
                  &kTimeRange);
  }
  if (block == "solver") {
    if (key == "rtol") return Number([](Scenario& s) -> double& { return s.solver.rtol; }, nullptr);
    if (key == "atol") return Number([](Scenario& s) -> double& { return s.solver.atol; }, nullptr);
    if (key == "max_step") {
      return Number([](Scenario& s) -> double& { return s.solver.max_step; }, nullptr);
    }
    if (key == "max_steps") {
      p_.integer_ = true;
      p_.get_ = [](const Scenario& s) { return static_cast<double>(s.solver.max_steps); };
      p_.set_ = [](Scenario& s, double v) { s.solver.max_steps = static_cast<long>(v); };
      p_.range_ = InputRange{1.0, 1e12, "-", "a guard on the steps of one run"};
      p_.bounded_ = true;
      return;
    }
  }
  if (block == "output") {
    if (key == "interval" && !scenario_.output.every_step) {
      return Number([](Scenario& s) -> double& { return s.output.interval; }, nullptr);
    }
    if (key == "phase_tolerance" && scenario_.output.phase_tolerance) {
      return Number([](Scenario& s) -> double& { return *s.output.phase_tolerance; },
                    &kPhaseToleranceRange);
    }
  }
  Fail("names no numeric setting of the scenario");
}

void ParameterResolver::WaveformField(std::size_t i, Locate<Waveform> at,
                                      const InputRange* values) {
  // constant, the shape in the context of this waveform: its time fields are times, the rest
  // values of the signal
  const Waveform& w = at(const_cast<Scenario&>(scenario_));
  const std::string& key = Key(i);
  const auto field = [&](double Waveform::*member, const InputRange* range) {
    End(i + 1);
    Number([at, member](Scenario& s) -> double& { return at(s).*member; }, range);
  };
  switch (w.kind) {
    case WaveformKind::kConstant:
      if (key == "value") return field(&Waveform::value, values);
      break;
    case WaveformKind::kStep:
      if (key == "time") return field(&Waveform::time, &kTimeRange);
      if (key == "before") return field(&Waveform::before, values);
      if (key == "after") return field(&Waveform::after, values);
      break;
    case WaveformKind::kRamp:
      if (key == "start") return field(&Waveform::start, &kTimeRange);
      if (key == "end") return field(&Waveform::end, &kTimeRange);
      if (key == "from") return field(&Waveform::from, values);
      if (key == "to") return field(&Waveform::to, values);
      break;
    case WaveformKind::kSine:
      if (key == "offset") return field(&Waveform::offset, values);
      if (key == "amplitude") return field(&Waveform::amplitude, values);
      if (key == "frequency") return field(&Waveform::frequency, &kFrequencyRange);
      if (key == "phase") return field(&Waveform::phase, nullptr);
      break;
    case WaveformKind::kPulses:
      if (key == "start") return field(&Waveform::start, &kTimeRange);
      if (key == "period") return field(&Waveform::period, nullptr);
      if (key == "width") return field(&Waveform::width, nullptr);
      if (key == "low") return field(&Waveform::low, values);
      if (key == "high") return field(&Waveform::high, values);
      break;
    case WaveformKind::kTable:
      if (key == "points") {
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
      break;
  }
  Fail("names no field of this " + std::string(ToString(w.kind)) + " waveform");
}

double Parameter::Get(const Scenario& scenario) const {
  if (!model_.empty()) return model_get_(scenario.models.at(model_).spec);
  return get_(scenario);
}

void Parameter::Check(double value) const {
  Require(std::isfinite(value), path_, value, "must be finite");
  if (integer_) {
    // a model's integers are ints: the largest any of them accepts is far below 1e9
    Require(value == std::floor(value) && std::abs(value) <= (model_.empty() ? 1e15 : 1e9), path_,
            value, "must be an integer");
  }
  if (bounded_ && !range_.Contains(value)) {
    throw ParameterError(path_, FormatNumber(value), range_.Rule());
  }
}

void Parameter::Assign(Scenario& scenario, double value) const {
  if (model_.empty()) return set_(scenario, value);
  ModelSpec& spec = scenario.models.at(model_).spec;
  model_set_(spec, value);
  if (refits_) spec.fit_result.reset();
}

void Parameter::Set(Scenario& scenario, double value) const {
  SetParameters(scenario, {*this}, {value});
}

void SetParameters(Scenario& scenario, const std::vector<Parameter>& parameters,
                   const std::vector<double>& values) {
  for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i].Check(values[i]);
  Scenario saved = scenario;
  try {
    std::vector<std::string> blocks;
    bool others = false;  // a value outside the model blocks
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      parameters[i].Assign(scenario, values[i]);
      const std::string& block = parameters[i].model();
      others = others || block.empty();
      if (!block.empty() && std::find(blocks.begin(), blocks.end(), block) == blocks.end()) {
        blocks.push_back(block);
      }
    }
    for (const std::string& block : blocks) {
      try {
        scenario.RebuildModel(block);
      } catch (const ParameterError& error) {
        const std::string prefix =
            scenario.form == ScenarioForm::kActuator ? "model." : "models." + block + ".";
        throw ParameterError(prefix + error.path(), error.value(), error.rule());
      }
    }
    // a model's change breaks no rule of the network's: validate it when more than models move
    if (others) scenario.Validate();
  } catch (...) {
    scenario = std::move(saved);
    throw;
  }
}

Parameter FindParameter(const Scenario& scenario, const std::string& path) {
  return ParameterResolver(scenario, path).Resolve();
}

}  // namespace musclesim
