// Private: reading a described part (core/part_fields.h) from its map: which variant the map
// names, the keys it may hold, each number against its range, nested fields in their own
// maps, each word among its names, its lists, texts and flags. The messages name file:line:column,
// key path, value and rule, as every reader's do.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/readers/coordinates_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

// Adds `key` to `keys` unless it is there.
inline void AddKey(std::vector<std::string>& keys, std::string key) {
  for (const std::string& k : keys) {
    if (k == key) return;
  }
  keys.push_back(std::move(key));
}

// Adds the keys of `variant`'s map to `keys`, each once, in order: its numbers', points',
// words', lists', texts', flags' and other keys' first steps (a list of numbers' key without its
// index).
template <typename Part>
void AddVariantKeys(const PartVariant<Part>& variant, std::vector<std::string>& keys) {
  for (const NumberField<Part>& field : variant.fields) {
    AddKey(keys, std::string(HeadKey(field.key)));
  }
  for (const PointField<Part>& point : variant.points) AddKey(keys, point.key);
  for (const WordField<Part>& word : variant.words) AddKey(keys, word.key);
  for (const ListField<Part>& list : variant.lists) AddKey(keys, std::string(HeadKey(list.key)));
  for (const TextField<Part>& text : variant.texts) AddKey(keys, text.key);
  for (const FlagField<Part>& flag : variant.flags) AddKey(keys, flag.key);
  for (const char* other : variant.other_keys) AddKey(keys, std::string(HeadKey(other)));
}

// The keys of the variants of `type`, each once, in order: "slack_length, stiffness,
// exponential, degroote2016" for a tendon.
template <typename Part>
std::vector<std::string> VariantKeys(const std::vector<PartVariant<Part>>& variants,
                                     std::string_view type) {
  std::vector<std::string> keys;
  for (const PartVariant<Part>& variant : variants) {
    if (type == variant.type) AddVariantKeys(variant, keys);
  }
  return keys;
}

// The keys a nested map of `variant` may hold: the next step of every field, list and other
// key below `prefix` ("velocity" gives v_max, n, epsilon, eccentric).
template <typename Part>
std::vector<std::string> NestedKeys(const PartVariant<Part>& variant, const std::string& prefix) {
  std::vector<std::string> keys;
  const auto add = [&](std::string_view key) {
    if (key.size() > prefix.size() && key.substr(0, prefix.size()) == prefix &&
        key[prefix.size()] == '.') {
      AddKey(keys, std::string(HeadKey(key.substr(prefix.size() + 1))));
    }
  };
  for (const NumberField<Part>& field : variant.fields) add(field.key);
  for (const ListField<Part>& list : variant.lists) add(list.key);
  for (const char* other : variant.other_keys) add(other);
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
    yaml::Fail(src, item, path,
               !given.empty()        ? given
               : of_type.size() == 2 ? "neither"
                                     : "none",
               rule);
  }
  return chosen;
}

// Reads `names` from the map `item` into `part`, in order, each required unless marked not
// (then absent is empty): the part's own a plain name (yaml::ReadPlainName), a reference any
// text (the network resolves it when built).
template <typename Part>
void ReadNames(const yaml::Source& src, const Document& item, const std::string& path,
               const std::vector<NameField<Part>>& names, Part& part) {
  for (const NameField<Part>& name : names) {
    if (!name.required && !item[name.key]) continue;
    if (name.is_own()) {
      name.set(part, yaml::ReadPlainName(src, item, path, name.key));
    } else {
      const Document& given = yaml::Required(src, item, path, name.key.c_str());
      name.set(part, yaml::ReadString(src, given, yaml::Join(path, name.key)));
    }
  }
}

// Reads the word fields of `variant` from the map `item` into `part`: each a name among its
// names, its default where absent.
template <typename Part>
void ReadWords(const yaml::Source& src, const Document& item, const std::string& path,
               const PartVariant<Part>& variant, Part& part) {
  for (const WordField<Part>& word : variant.words) {
    const Document& given = item[word.key];
    if (!given) {
      if (!word.optional) word.set(part, word.default_name);
      continue;
    }
    const std::string key_path = yaml::Join(path, word.key);
    const std::string name = yaml::ReadString(src, given, key_path);
    if (std::find(word.names.begin(), word.names.end(), name) == word.names.end()) {
      yaml::Fail(src, given, key_path, name, MustBeOneOf(word.names));
    }
    word.set(part, name);
  }
}

// Reads the point fields of `variant` from the map `item` into `part`, in `dimensions`
// coordinates; an optional one absent is the origin.
template <typename Part>
void ReadPoints(const yaml::Source& src, const Document& item, const std::string& path,
                const PartVariant<Part>& variant, Part& part, int dimensions) {
  for (const PointField<Part>& point : variant.points) {
    const Document& given = item[point.key];
    if (!given && !point.required) {
      point.set(part, FieldPoint{});
      continue;
    }
    point.set(part, ReadPoint(src, yaml::Required(src, item, path, point.key.c_str()),
                              yaml::Join(path, point.key), dimensions, point.range, point.prefix));
  }
}

template <typename Part>
void ReadLists(const yaml::Source& src, const Document& item, const std::string& path,
               const PartVariant<Part>& variant, Part& part);

// Reads every field of `variant` from the map `item` into `part`, in the order listed: a
// nested field ("velocity.eccentric.n") from its maps, whose keys are checked when each is
// first met; a map may be left out when its fields have defaults or are optional; a list's
// numbers ("range[0]", "range[1]") from a list of exactly as many. Then its points, in
// `dimensions` coordinates, its words, its lists of sub-parts, its texts and its flags.
// `signal` bounds the fields whose values are the signal's (nullptr: any number).
template <typename Part>
void ReadFields(const yaml::Source& src, const Document& item, const std::string& path,
                const PartVariant<Part>& variant, Part& part, const InputRange* signal = nullptr,
                int dimensions = 1) {
  std::vector<std::string> opened;  // the nested maps checked so far, by their prefixes
  for (const NumberField<Part>& field : variant.fields) {
    const bool may_be_absent = field.default_value || field.given;
    const Document* map = &item;
    std::string at = path;
    std::size_t begin = 0;  // of the field's key's step below `map`
    bool absent = false;
    for (std::size_t dot = field.key.find('.'); dot != std::string::npos;
         dot = field.key.find('.', begin)) {
      const std::string head = field.key.substr(begin, dot - begin);
      if (!(*map)[head] && may_be_absent) {
        absent = true;
        break;
      }
      map = &yaml::Required(src, *map, at, head.c_str());
      at = yaml::Join(at, head);
      const std::string prefix = field.key.substr(0, dot);
      if (std::find(opened.begin(), opened.end(), prefix) == opened.end()) {
        yaml::RequireMap(src, *map, at, NestedKeys(variant, prefix));
        opened.push_back(prefix);
      }
      begin = dot + 1;
    }
    const std::string leaf = field.key.substr(begin);
    const std::optional<ListElement> element = ElementOf(leaf);
    const std::string map_key = element ? std::string(element->list) : leaf;
    if (absent || (!(*map)[map_key] && may_be_absent)) {
      if (field.default_value) field.set(part, *field.default_value);
      continue;
    }
    const Document* value_node = &yaml::Required(src, *map, at, map_key.c_str());
    std::string key_path = yaml::Join(at, map_key);
    if (element) {
      // the list's shape once, at its first number
      if (element->index == 0) {
        const std::string list_key = field.key.substr(0, begin) + map_key;
        yaml::ReadNumbers(src, *value_node, key_path, ListLength(variant, list_key));
      }
      value_node = &(*value_node)[element->index];
      // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::string
      key_path.append("[").append(std::to_string(element->index)).append("]");
    }
    const Document& given = *value_node;
    if (field.word != nullptr && field.set_word && given.IsScalar() &&
        given.Scalar() == field.word) {
      field.set_word(part);
      continue;
    }
    const InputRange* range = field.values == FieldValues::kRange    ? &field.range
                              : field.values == FieldValues::kSignal ? signal
                                                                     : nullptr;
    if (field.integer || field.also) {
      const double value = yaml::ReadNumber(src, given, key_path);
      if (!FieldAccepts(field, value)) {
        yaml::Fail(src, given, key_path, yaml::Describe(given), FieldRule(field));
      }
      field.set(part, value);
      continue;
    }
    field.set(part, range != nullptr ? yaml::ReadNumberIn(src, given, key_path, *range)
                                     : yaml::ReadNumber(src, given, key_path));
  }
  ReadPoints(src, item, path, variant, part, dimensions);
  ReadWords(src, item, path, variant, part);
  ReadLists(src, item, path, variant, part);
  for (const TextField<Part>& text : variant.texts) {
    if (!item[text.key] && !text.required) continue;
    const Document& given = yaml::Required(src, item, path, text.key.c_str());
    const std::string key_path = yaml::Join(path, text.key);
    std::string value = yaml::ReadString(src, given, key_path);
    if (value.empty()) yaml::Fail(src, given, key_path, "\"\"", "must not be empty");
    text.set(part, std::move(value));
  }
  for (const FlagField<Part>& flag : variant.flags) {
    const Document& given = item[flag.key];
    flag.set(part,
             given ? yaml::ReadBool(src, given, yaml::Join(path, flag.key)) : flag.default_value);
  }
}

// Reads the list of sub-parts `list` at `node` into `part`: at least its fewest items, each a
// map of the item's fields.
template <typename Part>
void ReadList(const yaml::Source& src, const Document& node, const std::string& path,
              const ListField<Part>& list, Part& part) {
  if (!node.IsSequence() || node.size() < list.min_items) {
    yaml::Fail(src, node, path, yaml::Describe(node),
               std::string("must be a ") + (list.min_items > 0 ? "non-empty " : "") + "list of {" +
                   ItemKeys(list) + "}");
  }
  list.resize(part, node.size());
  for (std::size_t k = 0; k < node.size(); ++k) {
    const std::string at = path + "[" + std::to_string(k) + "]";
    const PartVariant<Part> item = OnlyVariant<Part>(list.item, "", list.item_fields(k));
    std::vector<std::string> keys;
    AddVariantKeys(item, keys);
    yaml::RequireMap(src, node[k], at, keys);
    ReadFields(src, node[k], at, item, part);
  }
}

// Reads the lists of sub-parts of `variant` from the map `item` into `part`, each from its
// nested maps (checked by ReadFields where a field opened them); one not required may be
// absent, with its maps.
template <typename Part>
void ReadLists(const yaml::Source& src, const Document& item, const std::string& path,
               const PartVariant<Part>& variant, Part& part) {
  for (const ListField<Part>& list : variant.lists) {
    const Document* map = &item;
    std::string at = path;
    std::size_t begin = 0;
    for (std::size_t dot = list.key.find('.'); map != nullptr && dot != std::string::npos;
         dot = list.key.find('.', begin)) {
      const std::string head = list.key.substr(begin, dot - begin);
      map = (*map)[head] || list.required ? &yaml::Required(src, *map, at, head.c_str()) : nullptr;
      at = yaml::Join(at, head);
      begin = dot + 1;
    }
    const std::string leaf = list.key.substr(begin);
    if (map == nullptr || (!(*map)[leaf] && !list.required)) continue;
    ReadList(src, yaml::Required(src, *map, at, leaf.c_str()), yaml::Join(at, leaf), list, part);
  }
}

}  // namespace musclesim
