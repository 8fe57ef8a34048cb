// A part's numbers described once (in the manner of Drake's Serialize(Archive*)): each field's
// key, unit, range with its reason, default and meaning, and how it sets the part. The file
// readers, the parameter handles (--set, sweeps, sensitivities, identification), the closed-form
// derivatives, the parts' validation and the reference tables in the docs are derived from the
// descriptions (docs/layout.md, "How to add a key").
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "musclesim/core/enum_names.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

// Where a field's accepted values come from.
enum class FieldValues {
  kRange,   // its own `range`
  kSignal,  // the signal's the part carries (a waveform's value: a force's, a position's; an
            // activation's [0, 1], which the signal's validation checks): the reader's context
  kFinite,  // any finite number; the part's Validate states the rule (a pulse's period)
};

// One number of a part of type `Part`.
template <typename Part>
struct NumberField {
  std::string key;                      // below the part: "stiffness", or nested "exponential.k"
  InputRange range;                     // the values a file may give it, its unit and why
  std::optional<double> default_value;  // absent: the key is required, unless `given` is set
  const char* doc = "";                 // what it is, for the reference table
  std::function<double(const Part&)> get;
  // Sets it, keeping what the part's other keys mean (a De Groote tendon's slack length keeps
  // its strain): a file's fields are set in the order listed.
  std::function<void(Part&, double)> set;
  int partial = -1;  // the closed-form derivative's tag (the part's own enum); -1: none
  FieldValues values = FieldValues::kRange;
  bool integer = false;  // a count or an exponent: a whole number within `range`
  // An optional key with no default: whether the part has it (`get` then gives the value the
  // part uses in its place, an eccentric v_max the concentric one). Null: not optional.
  std::function<bool(const Part&)> given{};
  // A value outside `range` a file may give too, and what it means (a free node's mass 0: a
  // massless junction). A parameter handle keeps to `range`: the value changes the part's kind.
  std::optional<double> also{};
  const char* also_means = "";
  // A word a file may give in the number's place, what it means, and how it sets the part (an
  // output interval's `steps`: a row per step); `given` then tells the part lacks a number.
  const char* word = nullptr;
  const char* word_means = "";
  std::function<void(Part&)> set_word{};
};

// The rule a file's value of `field` must meet: its range's, for an integer field "must be an
// integer from 1 to 1000 [-]: why".
// With `also`: "...; or exactly 0, a massless junction ...".
template <typename Part>
std::string FieldRule(const NumberField<Part>& field) {
  std::string rule = !field.integer ? field.range.Rule()
                                    : "must be an integer " + field.range.Bounds() + " [" +
                                          field.range.unit + "]: " + field.range.why;
  if (field.also) rule += "; or exactly " + FormatNumber(*field.also) + ", " + field.also_means;
  return rule;
}

// Whether `value` is one `field` accepts: within its range and whole for an integer field,
// or its `also`.
template <typename Part>
bool FieldAccepts(const NumberField<Part>& field, double value) {
  return (field.range.Contains(value) && (!field.integer || value == std::floor(value))) ||
         (field.also && value == *field.also);
}

// The coordinates (x, y, z) of a point of a part; on a line x alone, in the plane x and y.
using FieldPoint = std::array<double, 3>;

// A point of a part: in a file one number on a line, a list of 2 or 3 in the plane or in
// space (the scenario's `dimensions`), each coordinate within `range`, those past them 0.
template <typename Part>
struct PointField {
  std::string key;
  InputRange range;         // of each coordinate
  bool required = true;     // else absent is the origin (at rest, for a velocity)
  const char* prefix = "";  // before each coordinate's name in messages: "v" gives [vx, vy]
  const char* doc = "";
  std::function<FieldPoint(const Part&)> get{};
  std::function<void(Part&, const FieldPoint&)> set{};
};

// Where coordinate c of a point field is reported: at its key for x ("position"), else
// indexed ("position[1]" is y).
inline std::string CoordinateKey(const std::string& key, std::size_t c) {
  return c == 0 ? key : key + "[" + std::to_string(c) + "]";
}

// A text of a part that is no name and no choice (the output's file path): any text but the
// empty one where given; absent leaves the part's own (its default, told in `doc`), unless
// it is required.
template <typename Part>
struct TextField {
  std::string key;
  const char* doc = "";
  std::function<std::string(const Part&)> get{};
  std::function<void(Part&, std::string)> set{};
  bool required = false;
};

// A yes/no of a part (an identification's nonnegative amplitudes): true or false in a file,
// absent its default.
template <typename Part>
struct FlagField {
  std::string key;
  bool default_value = false;
  const char* doc = "";
  std::function<bool(const Part&)> get{};
  std::function<void(Part&, bool)> set{};
};

// The flag field of the bool `member` of a Part.
template <typename Part>
FlagField<Part> MemberFlag(const char* key, bool Part::*member, bool fallback, const char* doc) {
  return {key, fallback, doc, [member](const Part& part) { return part.*member; },
          [member](Part& part, bool value) { part.*member = value; }};
}

// One name of a part, chosen from a list (a solver's method: bdf or adams).
template <typename Part>
struct WordField {
  std::string key;
  std::vector<std::string_view> names;  // the names a file may give, in the docs' order
  std::string_view default_name;        // what an absent key means
  const char* doc = "";
  std::function<std::string_view(const Part&)> get;
  // Sets it to one of `names`.
  std::function<void(Part&, std::string_view)> set;
  // Else absent leaves the part without it (a fit's preset `name`, for one target only, which
  // the part's Validate states); `default_name` is then unused.
  bool optional = false;
};

// The word field of the enum `member` of a Part, its names those of `table` (core/enum_names.h),
// which must outlive the field (a namespace-scope constexpr table: its get and set read it).
template <typename Part, typename Enum, std::size_t N>
WordField<Part> EnumField(const char* key, Enum Part::*member, const EnumName<Enum> (&table)[N],
                          const char* doc) {
  WordField<Part> field;
  field.key = key;
  for (const EnumName<Enum>& entry : table) field.names.push_back(entry.name);
  field.default_name = ToString(table, Part{}.*member);
  field.doc = doc;
  field.get = [member, &table](const Part& part) { return ToString(table, part.*member); };
  field.set = [member, &table, key](Part& part, std::string_view name) {
    part.*member = Parse(table, key, name);
  };
  return field;
}

// A name in a part: its own (`name`, which heads its CSV columns) or another part's that it
// refers to (an element's `from` node), which the network resolves when it is built.
template <typename Part>
struct NameField {
  std::string key;
  const char* refers_to = "";  // what a reference names ("a node"); "" for the part's own name
  const char* doc = "";
  std::function<std::string(const Part&)> get{};
  std::function<void(Part&, std::string)> set{};
  // Else absent leaves it empty: one of several a rule between keys chooses among (a
  // controller's `drives` or its `co_contraction`), which the part's reader states.
  bool required = true;

  bool is_own() const { return *refers_to == '\0'; }
};

// The name field of the string `member` of a Part; `refers_to` "" for the part's own name.
template <typename Part>
NameField<Part> MemberName(const char* key, std::string Part::*member, const char* refers_to,
                           const char* doc, bool required = true) {
  return {key,
          refers_to,
          doc,
          [member](const Part& part) { return part.*member; },
          [member](Part& part, std::string name) { part.*member = std::move(name); },
          required};
}

// The keys of `names`, in the order a part's map lists them: its own name, then `type` (when
// the part has one), then the names it refers to.
template <typename Part>
std::vector<std::string> NameKeys(const std::vector<NameField<Part>>& names, bool typed) {
  std::vector<std::string> keys;
  for (const NameField<Part>& name : names) {
    if (name.is_own()) keys.push_back(name.key);
  }
  if (typed) keys.emplace_back("type");
  for (const NameField<Part>& name : names) {
    if (!name.is_own()) keys.push_back(name.key);
  }
  return keys;
}

// A number of a list of numbers in a part ("lengthrange: [0.5, 1.5]") is a field whose key
// ends in its index: "lengthrange[1]". A list's fields come together, from index 0 on, and a
// file gives the list with exactly as many numbers.
struct ListElement {
  std::string_view list;  // the list's key: "lengthrange"
  std::size_t index = 0;
};

// The index "[i]" at the start of `text` and the rest after it; none when it has none.
inline std::optional<std::pair<std::size_t, std::string_view>> LeadingIndex(std::string_view text) {
  const std::size_t close = text.find(']');
  if (text.empty() || text.front() != '[' || close == std::string_view::npos || close < 2) {
    return std::nullopt;
  }
  std::size_t index = 0;
  for (const char c : text.substr(1, close - 1)) {
    if (c < '0' || c > '9') return std::nullopt;
    index = index * 10 + static_cast<std::size_t>(c - '0');
  }
  return std::pair{index, text.substr(close + 1)};
}

// The list and index of a field's key that ends in "[i]"; none for any other key.
inline std::optional<ListElement> ElementOf(std::string_view key) {
  const std::size_t open = key.rfind('[');
  if (open == std::string_view::npos || open == 0) return std::nullopt;
  const auto index = LeadingIndex(key.substr(open));
  if (!index || !index->second.empty()) return std::nullopt;
  return ListElement{key.substr(0, open), index->first};
}

// A list of sub-parts of a part, each a map of the same numbers (the paper's Gaussians, each
// {amplitude, width, center}). Its items' fields are the part's own, made for item k: their
// keys the item's ("width"), their get and set on the part's item k.
template <typename Part>
struct ListField {
  std::string key;            // "active_length.gaussians"
  const char* item = "";      // one item, in messages: "a Gaussian"
  const char* doc = "";       // what the list is, for the reference table
  bool required = true;       // else absent leaves the part's list as it is
  std::size_t min_items = 1;  // a file's list has at least these
  std::function<std::size_t(const Part&)> size{};
  std::function<void(Part&, std::size_t)> resize{};  // to n items, the new ones default
  std::function<std::vector<NumberField<Part>>(std::size_t)> item_fields{};
};

// The list field of the items `items(part)` (a generic lambda giving the part's vector, for a
// const part and a mutable one), each described by `fields` of its type.
template <typename Part, typename Item, typename Items>
ListField<Part> ItemList(const char* key, const char* item, const char* doc, Items items,
                         std::vector<NumberField<Item>> fields) {
  ListField<Part> list{key, item, doc};
  list.size = [items](const Part& part) { return items(part).size(); };
  list.resize = [items](Part& part, std::size_t n) { items(part).resize(n); };
  list.item_fields = [items, fields = std::move(fields)](std::size_t k) {
    std::vector<NumberField<Part>> of_item;
    for (const NumberField<Item>& field : fields) {
      NumberField<Part> outer = {
          field.key,
          field.range,
          field.default_value,
          field.doc,
          [items, k, get = field.get](const Part& part) { return get(items(part)[k]); },
          [items, k, set = field.set](Part& part, double v) { set(items(part)[k], v); },
          field.partial,
          field.values,
          field.integer};
      of_item.push_back(std::move(outer));
    }
    return of_item;
  };
  return list;
}

// "amplitude, width, center": the keys of an item of `list`.
template <typename Part>
std::string ItemKeys(const ListField<Part>& list) {
  std::string keys;
  for (const NumberField<Part>& field : list.item_fields(0)) {
    keys.append(keys.empty() ? "" : ", ").append(field.key);
  }
  return keys;
}

// One variant of a part (an element law, a kind of load): the `type` a file names and, when
// a type has several variants, the key whose presence selects this one.
template <typename Part>
struct PartVariant {
  const char* type = "";           // the file's `type:` value ("tendon")
  const char* name = "";           // in messages and tables ("exponential tendon")
  const char* selector = nullptr;  // a key only this variant of its type has; nullptr: the
                                   // type's only variant
  const char* selector_doc = "";   // the selector in a message: "stiffness (a linear tendon)"
  const char* law = "";            // its equation, for the table ("T = k (l - l0)")
  std::vector<NumberField<Part>> fields;
  std::vector<PointField<Part>> points;  // its points, read after the numbers
  std::vector<WordField<Part>> words;    // its names chosen from a list, read after the points
  std::vector<ListField<Part>> lists;    // its lists of sub-parts, read after the words
  std::vector<TextField<Part>> texts;    // its free texts (a path), read after the lists
  std::vector<FlagField<Part>> flags;    // its yes/no fields, read last
  std::vector<const char*> other_keys;   // keys read by the part's own reader (a table's points)
  std::function<bool(const Part&)> is;   // whether a part is of this variant
  std::function<void(Part&)> make;       // gives a part this variant's kind, before its fields
};

// The field of the number `member` of a Part.
template <typename Part>
NumberField<Part> MemberField(const char* key, double Part::*member, const InputRange& range,
                              std::optional<double> fallback, const char* doc, int partial = -1) {
  return {key,
          range,
          fallback,
          doc,
          [member](const Part& part) { return part.*member; },
          [member](Part& part, double v) { part.*member = v; },
          partial};
}

// The fields of a part's member block `member` (a model's passive curve) as the part's own,
// their keys below `prefix` ("passive"): the block described once, where it is read alone
// and where it is read inside the part.
template <typename Outer, typename Inner>
std::vector<NumberField<Outer>> NestedFields(const std::string& prefix, Inner Outer::*member,
                                             const std::vector<NumberField<Inner>>& fields) {
  std::vector<NumberField<Outer>> nested;
  for (const NumberField<Inner>& field : fields) {
    NumberField<Outer> outer{prefix + "." + field.key,
                             field.range,
                             field.default_value,
                             field.doc,
                             [member, get = field.get](const Outer& o) { return get(o.*member); },
                             [member, set = field.set](Outer& o, double v) { set(o.*member, v); },
                             field.partial,
                             field.values,
                             field.integer};
    if (field.given) {
      outer.given = [member, given = field.given](const Outer& o) { return given(o.*member); };
    }
    nested.push_back(std::move(outer));
  }
  return nested;
}

// A part of one variant only (a block of numbers such as a controller's gains): every part
// is of it, and making one changes nothing.
template <typename Part>
PartVariant<Part> OnlyVariant(const char* type, const char* law,
                              std::vector<NumberField<Part>> fields) {
  PartVariant<Part> variant;
  variant.type = type;
  variant.name = type;
  variant.law = law;
  variant.fields = std::move(fields);
  variant.is = [](const Part&) { return true; };
  variant.make = [](Part&) {};
  return variant;
}

// How many numbers the list `list` of `variant` has: its fields "list[i]".
template <typename Part>
std::size_t ListLength(const PartVariant<Part>& variant, std::string_view list) {
  std::size_t length = 0;
  for (const NumberField<Part>& field : variant.fields) {
    const std::string_view key = field.key;
    if (key.substr(0, list.size()) != list) continue;
    const auto index = LeadingIndex(key.substr(list.size()));
    if (index && index->second.empty()) ++length;
  }
  return length;
}

// Gives `part` what a file that leaves out every optional key of `variant` gives it: each
// number's default and each word's.
template <typename Part>
void SetDefaults(const PartVariant<Part>& variant, Part& part) {
  for (const NumberField<Part>& field : variant.fields) {
    if (field.default_value) field.set(part, *field.default_value);
  }
  for (const WordField<Part>& word : variant.words) {
    if (!word.optional) word.set(part, word.default_name);
  }
}

// The field of `variant` whose key is `key` ("exponential.k"); null when it has none.
template <typename Part>
const NumberField<Part>* FindField(const PartVariant<Part>& variant, std::string_view key) {
  for (const NumberField<Part>& field : variant.fields) {
    if (key == field.key) return &field;
  }
  return nullptr;
}

// The point field of `variant` whose key is `key`; null when it has none.
template <typename Part>
const PointField<Part>* FindPoint(const PartVariant<Part>& variant, std::string_view key) {
  for (const PointField<Part>& point : variant.points) {
    if (key == point.key) return &point;
  }
  return nullptr;
}

// The variant `part` is of among `variants`; null for none (an actuator among element laws).
template <typename Part>
const PartVariant<Part>* VariantOf(const std::vector<PartVariant<Part>>& variants,
                                   const Part& part) {
  for (const PartVariant<Part>& variant : variants) {
    if (variant.is(part)) return &variant;
  }
  return nullptr;
}

// "stiffness, rest_length": the keys of a variant, for messages.
template <typename Part>
std::string FieldKeys(const PartVariant<Part>& variant) {
  std::string keys;
  for (const NumberField<Part>& field : variant.fields) {
    keys.append(keys.empty() ? "" : ", ").append(field.key);
  }
  return keys;
}

// The first key of a field's path: "exponential" of "exponential.k", "range" of "range[1]".
inline std::string_view HeadKey(std::string_view key) {
  return key.substr(0, key.find_first_of(".["));
}

// An item field of one of `variant`'s lists that a key path names
// ("active_length.gaussians[1].width"): the list, the item's index (maybe past the part's
// items), and the field's key in the item ("width"), maybe none of its fields.
template <typename Part>
struct ListItemKey {
  const ListField<Part>* list = nullptr;
  std::optional<std::size_t> index;  // none: the list itself
  std::string leaf;
};

// The item field `key` names among `variant`'s lists; none when it is of no list. The list's
// key alone has no index, and with an index and no field below it the leaf is "".
template <typename Part>
std::optional<ListItemKey<Part>> FindListItem(const PartVariant<Part>& variant,
                                              std::string_view key) {
  for (const ListField<Part>& list : variant.lists) {
    if (key.substr(0, list.key.size()) != list.key) continue;
    std::string_view rest = key.substr(list.key.size());
    if (rest.empty()) return ListItemKey<Part>{&list, std::nullopt, ""};
    const auto index = LeadingIndex(rest);
    if (!index || (!index->second.empty() && index->second.front() != '.')) continue;
    rest = index->second;
    return ListItemKey<Part>{&list, index->first,
                             std::string(rest.empty() ? rest : rest.substr(1))};
  }
  return std::nullopt;
}

// Throws ParameterError(key, value, rule) unless `value` lies in `range` (NaN never does).
void RequireInRange(std::string_view key, double value, const InputRange& range);

// Throws ParameterError(key, value, rule) for the first field of `variant` outside its own
// range or not whole where it must be (fields whose values are the signal's or any finite
// number, and optional ones the part lacks, are left out), then for the first coordinate of
// a point outside its range: what a C++ caller meets, with the same rule a file's reader
// states.
template <typename Part>
void ValidateFields(const PartVariant<Part>& variant, const Part& part) {
  for (const NumberField<Part>& field : variant.fields) {
    if (field.values != FieldValues::kRange || (field.given && !field.given(part))) continue;
    const double value = field.get(part);
    if (!FieldAccepts(field, value)) Require(false, field.key, value, FieldRule(field));
  }
  for (const PointField<Part>& point : variant.points) {
    const FieldPoint x = point.get(part);
    for (std::size_t c = 0; c < x.size(); ++c) {
      RequireInRange(CoordinateKey(point.key, c), x[c], point.range);
    }
  }
}

}  // namespace musclesim
