// A model block's keys as parameter handles: each family's described fields and lists of
// sub-parts (model/family_fields.h), and a fitted paper model's fit settings.
#include "scenario/parameter_resolver.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/model/family_fields.h"
#include "musclesim/model/fit_fields.h"
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
  if (family == CurveFamily::kPaper && Key(i) == "active_length" && Key(i + 1) == "fit") {
    return FitField(i + 2);
  }
  // the family's described fields (model/family_fields.h)
  const ModelFamily* described = nullptr;
  for (const ModelFamily& f : ModelFamilies()) {
    if (ToString(family) == std::string_view(f.type)) described = &f;
  }
  const std::string key_path = PathFrom(i);
  if (const std::optional<ListItemKey<ModelParams>> item = FindListItem(*described, key_path)) {
    return ListItemField(*item);
  }
  const NumberField<ModelParams>* field = FindField(*described, key_path);
  for (const NumberField<ModelParams>& f : described->fields) {
    if (field == nullptr && f.key.rfind(key_path + ".", 0) == 0)
      Fail("names a block, not one number");
  }
  if (field == nullptr) RequireListIndex(*described, key_path);
  if (field == nullptr) {
    std::string keys = FieldKeys(*described);
    for (const ListField<ModelParams>& list : described->lists) keys.append(", ").append(list.key);
    for (const char* other : described->other_keys) keys.append(", ").append(other);
    Fail("names no parameter of a " + std::string(described->type) + " model (" + keys + ")");
  }
  p_.integer_ = field->integer;
  // a fitted model's Gaussians are fitted again for a new L_opt or sigma
  ModelValue([get = field->get](const ModelSpec& m) { return get(m.params); },
             [set = field->set](ModelSpec& m, double v) { set(m.params, v); },
             key_path.rfind("active_length.", 0) == 0);
}

void ParameterResolver::RequireListIndex(const PartVariant<ModelParams>& family,
                                         const std::string& key_path) const {
  const std::optional<ListElement> element = ElementOf(key_path);
  const std::string list = element ? std::string(element->list) : key_path;
  const std::size_t length = ListLength(family, list);
  if (length == 0) return;
  const std::string name = list.substr(list.rfind('.') + 1);  // "optimal_range"
  if (!element) Fail("needs an index of " + name);
  Fail("indexes past the end of " + name + " (" + std::to_string(length) + ")");
}

void ParameterResolver::ModelValue(std::function<double(const ModelSpec&)> get,
                                   std::function<void(ModelSpec&, double)> set, bool refits) {
  p_.model_get_ = std::move(get);
  p_.model_set_ = std::move(set);
  p_.refits_ = refits && fitted_;
}

void ParameterResolver::FitField(std::size_t i) {
  if (!fitted_) Fail("names no numeric parameter of the active length curve");
  End(i + 1);
  // the fit's numbers as its block describes them (model/fit_fields.h); a change refits
  const NumberField<FitSpec>* field = FindField(FitBlock().front(), Key(i));
  if (field == nullptr) Fail("names no numeric parameter of the active length curve");
  p_.integer_ = field->integer;
  p_.range_ = field->range;
  p_.bounded_ = true;
  ModelValue([get = field->get](const ModelSpec& m) { return get(*m.fit); },
             [set = field->set](ModelSpec& m, double v) { set(*m.fit, v); }, true);
}

void ParameterResolver::ListItemField(const ListItemKey<ModelParams>& key) {
  const ListField<ModelParams>& list = *key.list;
  if (fitted_) Fail("is fitted when the model is built: change the fit's settings instead");
  const std::string name = list.key.substr(list.key.rfind('.') + 1);  // "gaussians"
  if (!key.index) Fail("needs an index of " + name);
  const std::size_t count = list.size(scenario_.models.at(p_.model_).spec.params);
  if (*key.index >= count) {
    Fail("indexes past the end of " + name + " (" + std::to_string(count) + ")");
  }
  if (key.leaf.empty()) Fail("names a block, not one number");
  for (const NumberField<ModelParams>& field : list.item_fields(*key.index)) {
    if (field.key != key.leaf) continue;
    return ModelValue([get = field.get](const ModelSpec& m) { return get(m.params); },
                      [set = field.set](ModelSpec& m, double v) { set(m.params, v); });
  }
  Fail(std::string("names no field of ") + list.item + " (" + ItemKeys(list) + ")");
}

}  // namespace musclesim
