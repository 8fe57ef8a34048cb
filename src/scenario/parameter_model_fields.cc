// A model block's keys as parameter handles: each family's described fields
// (model/family_fields.h), the paper's L_opt, Gaussians and fit, and MuJoCo's lists of two.
#include "scenario/parameter_resolver.h"

#include <algorithm>
#include <cmath>
#include <functional>

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
  fitted_ = found->second.spec.fit.has_value();
  FamilyField(i + 1, found->second.spec.params.family);
}

void ParameterResolver::FamilyField(std::size_t i, CurveFamily family) {
  const std::string& key = Key(i);
  if (family == CurveFamily::kMujoco && (key == "range" || key == "lengthrange")) {
    const std::size_t end = Index(i + 1, 2, key == "range" ? "range" : "lengthrange");
    End(i + 2);
    if (key == "range") {
      return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.range[end]; });
    }
    return ModelNumber([end](ModelSpec& m) -> double& { return m.params.mujoco.lengthrange[end]; });
  }
  // the paper's L_opt and Gaussians, listed or fitted
  if (family == CurveFamily::kPaper && key == "active_length" && Key(i + 1) != "sigma") {
    return ActiveLengthField(i + 1);
  }
  // the family's described fields (model/family_fields.h)
  const ModelFamily* described = nullptr;
  for (const ModelFamily& f : ModelFamilies()) {
    if (ToString(family) == std::string_view(f.type)) described = &f;
  }
  const std::string key_path = PathFrom(i);
  const NumberField<ModelParams>* field = FindField(*described, key_path);
  for (const NumberField<ModelParams>& f : described->fields) {
    if (field == nullptr && f.key.rfind(key_path + ".", 0) == 0)
      Fail("names a block, not one number");
  }
  if (field == nullptr) {
    std::string keys = FieldKeys(*described);
    for (const char* other : described->other_keys) keys.append(", ").append(other);
    Fail("names no parameter of a " + std::string(described->type) + " model (" + keys + ")");
  }
  p_.integer_ = field->integer;
  // a fitted model's Gaussians are fitted again for a new L_opt or sigma
  ModelValue([get = field->get](const ModelSpec& m) { return get(m.params); },
             [set = field->set](ModelSpec& m, double v) { set(m.params, v); },
             key == "active_length");
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
