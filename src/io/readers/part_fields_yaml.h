// Private: reading a described part (core/part_fields.h) from its map: which variant the map
// names, the keys it may hold, and each field against its range, nested fields in their own
// maps. The messages name file:line:column, key path, value and rule, as every reader's do.
#pragma once

#include <string>
#include <vector>

#include "io/readers/yaml_fields.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

// The keys of the variants of `type`, each once, in order: "slack_length, stiffness,
// exponential, degroote2016" for a tendon.
template <typename Part>
std::vector<std::string> VariantKeys(const std::vector<PartVariant<Part>>& variants,
                                     std::string_view type) {
  std::vector<std::string> keys;
  for (const PartVariant<Part>& variant : variants) {
    if (type != variant.type) continue;
    for (const NumberField<Part>& field : variant.fields) {
      const std::string head(HeadKey(field.key));
      bool seen = false;
      for (const std::string& key : keys) seen = seen || key == head;
      if (!seen) keys.push_back(head);
    }
    keys.insert(keys.end(), variant.other_keys.begin(), variant.other_keys.end());
  }
  return keys;
}

// The variant of `type` that the map `item` selects: its type's only one, or the one whose
// selector key it has (exactly one of them). Null when no variant has that type.
template <typename Part>
const PartVariant<Part>* SelectVariant(const yaml::Source& src, const Document& item,
                                       const std::string& path,
                                       const std::vector<PartVariant<Part>>& variants,
                                       std::string_view type) {
  std::vector<const PartVariant<Part>*> of_type;
  for (const PartVariant<Part>& variant : variants) {
    if (type == variant.type) of_type.push_back(&variant);
  }
  if (of_type.size() <= 1) return of_type.empty() ? nullptr : of_type.front();
  const PartVariant<Part>* chosen = nullptr;
  std::string given;  // the selectors given: "stiffness and exponential"
  std::string rule = "give exactly one of ";
  for (std::size_t v = 0; v < of_type.size(); ++v) {
    const PartVariant<Part>* variant = of_type[v];
    rule.append(v == 0                    ? ""
                : v + 1 == of_type.size() ? " or "
                                          : ", ")
        .append(variant->selector_doc);
    if (variant->selector != nullptr && item[variant->selector]) {
      given.append(given.empty() ? "" : " and ").append(variant->selector);
      chosen = variant;
    }
  }
  if (given.empty() || given.find(" and ") != std::string::npos) {
    yaml::Fail(src, item, path, given.empty() ? "neither" : given, rule);
  }
  return chosen;
}

// Reads every field of `variant` from the map `item` into `part`, in the order listed: a
// nested field ("exponential.k") from its map, whose keys are checked when it is first met.
// `signal` bounds the fields whose values are the signal's (nullptr: any number).
template <typename Part>
void ReadFields(const yaml::Source& src, const Document& item, const std::string& path,
                const PartVariant<Part>& variant, Part& part, const InputRange* signal = nullptr) {
  std::vector<std::string> opened;  // the nested maps checked so far
  for (const NumberField<Part>& field : variant.fields) {
    const std::string key = field.key;
    const std::string head(HeadKey(key));
    const Document* map = &item;
    std::string at = path;
    std::string leaf = key;
    if (head != key) {
      map = &yaml::Required(src, item, path, head.c_str());
      at = yaml::Join(path, head);
      leaf = key.substr(head.size() + 1);
      bool checked = false;
      for (const std::string& name : opened) checked = checked || name == head;
      if (!checked) {
        std::vector<std::string> allowed;
        for (const NumberField<Part>& other : variant.fields) {
          const std::string other_key = other.key;
          if (HeadKey(other_key) == head) allowed.push_back(other_key.substr(head.size() + 1));
        }
        yaml::RequireMap(src, *map, at, allowed);
        opened.push_back(head);
      }
    }
    const Document& node = (*map)[leaf];
    if (!node && field.default_value) {
      field.set(part, *field.default_value);
      continue;
    }
    const InputRange* range = field.values == FieldValues::kRange    ? &field.range
                              : field.values == FieldValues::kSignal ? signal
                                                                     : nullptr;
    const Document& given = yaml::Required(src, *map, at, leaf.c_str());
    field.set(part, range != nullptr ? yaml::ReadNumberIn(src, given, yaml::Join(at, leaf), *range)
                                     : yaml::ReadNumber(src, given, yaml::Join(at, leaf)));
  }
}

}  // namespace musclesim
