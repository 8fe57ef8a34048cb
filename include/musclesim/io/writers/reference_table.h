// The reference table of a described part (core/part_fields.h) in Markdown: a row per field
// of each variant, with its key, unit, default, accepted values and their reason, and its
// meaning. The tables in docs/guide/ are these, checked by tests/io/reference_table_test.cc.
#pragma once

#include <string>
#include <vector>

#include "musclesim/core/number_format.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

// `key` heads the column of the variants' names: the key that names one in a file ("type",
// "family").
template <typename Part>
std::string ReferenceTable(const std::vector<PartVariant<Part>>& variants,
                           const std::string& key = "type") {
  std::string table = "| " + key + " | law | key | unit | default | accepted | meaning |\n";
  table += "|---|---|---|---|---|---|---|\n";
  for (const PartVariant<Part>& variant : variants) {
    bool first = true;
    for (const NumberField<Part>& field : variant.fields) {
      std::string type = std::string("`") + variant.type + "`";
      if (std::string_view(variant.name) != variant.type) type.append(" (").append(variant.name).append(")");
      table.append("| ")
          .append(first ? type : "")
          .append(" | ")
          .append(first ? variant.law : "")
          .append(" | `")
          .append(field.key)
          .append("` | ")
          .append(field.range.unit)
          .append(" | ")
          .append(field.default_value ? FormatNumber(*field.default_value) : "required")
          .append(" | ")
          .append(field.range.Bounds())
          .append(": ")
          .append(field.range.why)
          .append(" | ")
          .append(field.doc)
          .append(" |\n");
      first = false;
    }
  }
  return table;
}

}  // namespace musclesim
