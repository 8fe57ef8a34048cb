// Writing a described part's numbers (core/part_fields.h) as YAML flow-map text, in its
// fields' order, nested fields in their own maps: "tau_activation: 0.01, tau_deactivation:
// 0.04", "slack_length: 0.2, exponential: {k: 1, alpha: 30}": one level of nesting, each
// nested map's fields listed together, a list's numbers in a list. Each number is its getter's, as
// FormatNumber writes it (the shortest text that reads back as that double); a field derived from
// others (a De Groote tendon's strain) may be an ulp from the value it was made from.
#pragma once

#include <sstream>
#include <string>

#include "musclesim/core/number_format.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

template <typename Part>
std::string FlowFields(const PartVariant<Part>& variant, const Part& part) {
  std::ostringstream out;  // not operator+: GCC 12 warns falsely (-Wrestrict) on such chains
  std::string_view open;   // the nested map being written ("exponential"), or none
  bool in_list = false;    // a list of numbers is being written ("range: [0.5, 1.5]")
  for (const NumberField<Part>& field : variant.fields) {
    const std::string_view key = field.key;
    const std::string_view head = HeadKey(key);
    const bool nested = key.size() > head.size() && key[head.size()] == '.';
    const std::string_view inner = nested ? key.substr(head.size() + 1) : key;
    const std::optional<ListElement> element = ElementOf(inner);
    const bool continues_list = element && element->index > 0;
    if (in_list && !continues_list) out << "]";
    in_list = element.has_value();
    if (continues_list) {
      out << ", " << FormatNumber(field.get(part));
      continue;
    }
    if (!open.empty() && open != head) out << "}";
    if (&field != &variant.fields.front()) out << ", ";
    if (nested && open != head) out << head << ": {";
    out << (element ? element->list : inner) << (element ? ": [" : ": ")
        << FormatNumber(field.get(part));
    open = nested ? head : std::string_view();
  }
  if (in_list) out << "]";
  if (!open.empty()) out << "}";
  return out.str();
}

}  // namespace musclesim
