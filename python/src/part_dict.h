// A described part's numbers (core/part_fields.h) as a Python dict, the inverse of reading a
// dict as the part's map: each field at its key path ("velocity.eccentric.n" in nested dicts),
// an integer field as an int, an optional field only where the part has it.
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

// Adds the fields of `variant` of `part` to `out`, in their order.
template <typename Part>
void AddFields(const PartVariant<Part>& variant, const Part& part, pybind11::dict out) {
  for (const NumberField<Part>& field : variant.fields) {
    if (field.given && !field.given(part)) continue;
    std::string leaf;
    pybind11::dict map = MapOf(out, field.key, leaf);
    const double value = field.get(part);
    if (field.integer) {
      map[pybind11::str(leaf)] = static_cast<long>(value);
    } else {
      map[pybind11::str(leaf)] = value;
    }
  }
}

}  // namespace musclesim::python
