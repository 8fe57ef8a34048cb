// A model block's keys as parameter handles: the paper's curves (passive, velocity and its
// eccentric branch, active length and its Gaussians) and the other families' fields.
#include "scenario/parameter_resolver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/model/family_fields.h"
#include "musclesim/scenario/actuator_scenario.h"

namespace musclesim {

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
  if (family == CurveFamily::kMujoco && (key == "range" || key == "lengthrange")) {
    const std::size_t end = Index(i + 1, 2, key == "range" ? "range" : "lengthrange");
    End(i + 2);
    if (key == "range") {
      return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.range[end]; });
    }
    return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.lengthrange[end]; });
  }
  // the family's described fields (model/family_fields.h)
  const ModelFamily* described = nullptr;
  for (const ModelFamily& f : ModelFamilies()) {
    if (ToString(family) == std::string_view(f.type)) described = &f;
  }
  const NumberField<ModelParams>* field = FindField(*described, PathFrom(i));
  if (field == nullptr) {
    std::string keys = FieldKeys(*described);
    for (const char* other : described->other_keys) keys.append(", ").append(other);
    Fail("names no parameter of a " + std::string(described->type) + " model (" + keys + ")");
  }
  ModelValue([get = field->get](const ModelSpec& m) { return get(m.params); },
             [set = field->set](ModelSpec& m, double v) { set(m.params, v); });
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

}  // namespace musclesim
