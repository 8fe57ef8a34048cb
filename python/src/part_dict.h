// A described part's numbers (core/part_fields.h) as a Python dict, the inverse of reading a
// dict as the part's map: each field at its key path ("velocity.eccentric.n" in nested dicts),
// an integer field as an int, an optional field only where the part has it, a list of
// sub-parts as a list of dicts.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "musclesim/core/part_fields.h"

namespace musclesim::python {

// The dict at `key`'s map in `out` (made where missing); `leaf` gets the key's last step.
inline pybind11::dict MapOf(pybind11::dict out, const std::string& key, std::string& leaf) {
  std::size_t begin = 0;
  for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', begin)) {
    const pybind11::str head(key.substr(begin, dot - begin));
    if (!out.contains(head)) out[head] = pybind11::dict();
    out = out[head].cast<pybind11::dict>();
    begin = dot + 1;
  }
  leaf = key.substr(begin);
  return out;
}

// Adds the fields of `variant` of `part` to `out`, in their order; a list's numbers
// ("range[0]", "range[1]") as a tuple at the list's key.
template <typename Part>
void AddFields(const PartVariant<Part>& variant, const Part& part, pybind11::dict out) {
  for (std::size_t f = 0; f < variant.fields.size(); ++f) {
    const NumberField<Part>& field = variant.fields[f];
    if (field.given && !field.given(part)) continue;
    std::string leaf;
    pybind11::dict map = MapOf(out, field.key, leaf);
    if (const std::optional<ListElement> element = ElementOf(leaf)) {
      // the list whole at its first number: the fields after it are its others
      const std::string list_key =
          field.key.substr(0, field.key.size() - leaf.size()) + std::string(element->list);
      const std::size_t length = ListLength(variant, list_key);
      pybind11::tuple numbers(length);
      for (std::size_t i = 0; i < length; ++i) numbers[i] = variant.fields[f + i].get(part);
      map[pybind11::str(std::string(element->list))] = numbers;
      f += length - 1;
      continue;
    }
    const double value = field.get(part);
    if (field.integer) {
      map[pybind11::str(leaf)] = static_cast<long>(value);
    } else {
      map[pybind11::str(leaf)] = value;
    }
  }
}

// Adds the items of each list of sub-parts of `variant` of `part` to `out`: a list of
// dicts at the list's key path.
template <typename Part>
void AddLists(const PartVariant<Part>& variant, const Part& part, pybind11::dict out) {
  for (const ListField<Part>& list : variant.lists) {
    std::string leaf;
    pybind11::dict map = MapOf(out, list.key, leaf);
    pybind11::list items;
    for (std::size_t k = 0; k < list.size(part); ++k) {
      pybind11::dict item;
      AddFields(OnlyVariant<Part>(list.item, "", list.item_fields(k)), part, item);
      items.append(item);
    }
    map[pybind11::str(leaf)] = items;
  }
}

}  // namespace musclesim::python
