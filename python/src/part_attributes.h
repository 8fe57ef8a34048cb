// A described part's fields (core/part_fields.h) as read-only attributes of its Python class:
// a number (an int for an integer field) or a name per field, its docstring the field's
// meaning, unit and accepted values. A key added to the description appears in Python with it.
#pragma once

#include <pybind11/pybind11.h>

#include <deque>
#include <string>
#include <string_view>
#include <utility>

#include "musclesim/core/part_fields.h"

namespace musclesim::python {

// `doc` as a docstring, its first letter capitalised, kept for the module's life (pybind11 may
// keep the pointer it is given).
inline const char* KeptDoc(std::string doc) {
  static std::deque<std::string> kept;
  if (!doc.empty() && doc[0] >= 'a' && doc[0] <= 'z')
    doc[0] = static_cast<char>(doc[0] - 'a' + 'A');
  return kept.emplace_back(std::move(doc)).c_str();
}

template <typename Part, typename Class>
void DefFieldAttributes(Class& cls, const PartVariant<Part>& variant) {
  for (const NumberField<Part>& field : variant.fields) {
    const char* doc = KeptDoc(std::string(field.doc) + " [" + field.range.unit + "]; " +
                              (field.integer ? "an integer " : "") + field.range.Bounds() + ".");
    if (field.integer) {
      cls.def_property_readonly(
          field.key.c_str(),
          [get = field.get](const Part& part) { return static_cast<long>(get(part)); }, doc);
    } else {
      cls.def_property_readonly(
          field.key.c_str(), [get = field.get](const Part& part) { return get(part); }, doc);
    }
  }
  for (const WordField<Part>& word : variant.words) {
    std::string names;
    for (std::string_view name : word.names) {
      names.append(names.empty() ? "'" : ", '").append(name).append("'");
    }
    cls.def_property_readonly(
        word.key.c_str(), [get = word.get](const Part& part) { return std::string(get(part)); },
        KeptDoc(std::string(word.doc) + ": one of " + names + "."));
  }
}

}  // namespace musclesim::python
