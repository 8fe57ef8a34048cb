// The reference table of a described part (core/part_fields.h) in Markdown: a row per field
// of each variant, with its key, unit, default, accepted values and their reason, and its
// meaning; a row per point and per word field, with the names a word accepts; a row per list
// of sub-parts and per field of its items; a row per text and per flag. The tables in
// docs/guide/ are these, checked by tests/io/reference_table_test.cc.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/number_format.h"
#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/signal_fields.h"

namespace musclesim {

// The accepted-values cell of `field`: its bounds and why, or where they come from.
template <typename Part>
std::string AcceptedCell(const NumberField<Part>& field) {
  switch (field.values) {
    case FieldValues::kRange:
      return (field.integer ? "an integer " : "") + field.range.Bounds() + ": " + field.range.why +
             (field.also ? "; or exactly " + FormatNumber(*field.also) + ", " + field.also_means
                         : "");
    case FieldValues::kSignal: return "the signal's range";
    case FieldValues::kFinite:
      return std::string("any finite number") +
             (field.word ? std::string(", or `") + field.word + "`, " + field.word_means : "") +
             "; the rule in its meaning";
  }
  return "";
}

// The accepted-values cell of a name field.
template <typename Part>
std::string AcceptedCell(const NameField<Part>& name) {
  return name.is_own() ? "a plain name of letters, digits, _ and -: it heads the CSV's columns"
                       : std::string("the name of ") + name.refers_to;
}

// The rows of the names every variant of a part has (an element's `name`, `from`, `to`), for
// the head of its table.
template <typename Owner>
std::string NameRows(const std::vector<NameField<Owner>>& names) {
  std::string rows;
  for (const NameField<Owner>& name : names) {
    rows.append("| every | | `").append(name.key).append("` | | ");
    rows.append(name.required ? "required | " : "optional | ");
    rows.append(AcceptedCell(name)).append(" | ").append(name.doc).append(" |\n");
  }
  return rows;
}

// The cells after the key of each of `signals` (dynamics/signal_fields.h), by key: its unit,
// whether it is required, the waveforms it accepts with its values' bounds, and its meaning.
template <typename Part>
std::vector<std::pair<std::string, std::string>> SignalCells(
    const std::vector<SignalField<Part>>& signals) {
  std::vector<std::pair<std::string, std::string>> cells;
  for (const SignalField<Part>& signal : signals) {
    const InputRange* values = signal.values(Part{});
    std::string accepted =
        signal.continuous ? "a waveform, constant, ramp, sine or table" : "a waveform of any shape";
    if (signal.per_coordinate) accepted += ", one per coordinate (`dimensions`)";
    if (!signal.accepted.empty()) {
      accepted += "; its values " + signal.accepted;
    } else if (values != nullptr) {
      accepted += "; its values " + values->Bounds() + " " + values->unit + ": " + values->why;
    }
    const std::string presence = signal.required_with != nullptr
                                     ? std::string("required with ") + signal.required_with
                                 : signal.required ? "required"
                                                   : "optional";
    cells.emplace_back(signal.key, std::string(signal.unit) + " | " + presence + " | " + accepted +
                                       " | " + signal.doc);
  }
  return cells;
}

// The rows of `signals` every part has (a controller's reference), after `first`, the type
// column's cell ("every").
template <typename Part>
std::string SignalRows(const std::vector<SignalField<Part>>& signals, const std::string& first) {
  std::string rows;
  for (const auto& [key, cells] : SignalCells(signals)) {
    rows.append("| ").append(first).append(" | | `").append(key).append("` | ");
    rows.append(cells).append(" |\n");
  }
  return rows;
}

// A reference table's head, `key` heading the column of the variants' names.
inline std::string ReferenceHeader(const std::string& key) {
  return "| " + key + " | law | key | unit | default | accepted | meaning |\n" +
         "|---|---|---|---|---|---|---|\n";
}

template <typename Part>
std::string ReferenceRows(const std::vector<PartVariant<Part>>& variants,
                          const std::vector<std::pair<std::string, std::string>>& other_cells = {});

// `key` heads the column of the variants' names: the key that names one in a file ("type",
// "family"). `name_rows` (NameRows) come first. An other key (one its part's reader reads)
// found in `other_cells` (SignalCells) has those cells, any other "its own rules".
template <typename Part>
std::string ReferenceTable(
    const std::vector<PartVariant<Part>>& variants, const std::string& key = "type",
    const std::string& name_rows = "",
    const std::vector<std::pair<std::string, std::string>>& other_cells = {}) {
  return ReferenceHeader(key) + name_rows + ReferenceRows(variants, other_cells);
}

// The rows of `variants`, as ReferenceTable renders them: a table may hold the rows of
// several parts (a file and the entries of its lists) under one header.
template <typename Part>
std::string ReferenceRows(const std::vector<PartVariant<Part>>& variants,
                          const std::vector<std::pair<std::string, std::string>>& other_cells) {
  std::string table;
  for (const PartVariant<Part>& variant : variants) {
    std::string type = std::string("`") + variant.type + "`";
    if (std::string_view(variant.name) != variant.type) {
      type.append(" (").append(variant.name).append(")");
    }
    // the first row names the variant and its law
    const auto row = [&table, &type, &variant](const std::string& cells) {
      table.append("| ").append(type).append(" | ").append(type.empty() ? "" : variant.law);
      table.append(" | ").append(cells).append(" |\n");
      type.clear();
    };
    for (const NumberField<Part>& field : variant.fields) {
      row(std::string("`") + field.key + "` | " + field.range.unit + " | " +
          (field.default_value ? FormatNumber(*field.default_value)
           : field.given       ? "optional"
                               : "required") +
          " | " + AcceptedCell(field) + " | " + field.doc);
    }
    for (const PointField<Part>& point : variant.points) {
      row(std::string("`") + point.key + "` | " + point.range.unit + " | " +
          (point.required ? "required" : "0") +
          " | a number on a line, a list of 2 or 3 in the plane or in space (`dimensions`), "
          "each " +
          point.range.Bounds() + ": " + point.range.why + " | " + point.doc);
    }
    for (const WordField<Part>& word : variant.words) {
      std::string names;
      for (std::string_view name : word.names) names.append(names.empty() ? "" : ", ").append(name);
      row(std::string("`") + word.key + "` | | " +
          (word.optional ? "optional" : std::string(word.default_name)) + " | a name: " + names +
          " | " + word.doc);
    }
    for (const ListField<Part>& list : variant.lists) {
      row(std::string("`") + list.key + "` | | " + (list.required ? "required" : "optional") +
          " | a " + (list.min_items > 0 ? "non-empty " : "") + "list of {" + ItemKeys(list) +
          "} | " + list.doc);
      for (const NumberField<Part>& field : list.item_fields(0)) {
        row(std::string("`") + list.key + "[k]." + field.key + "` | " + field.range.unit +
            " | required | " + AcceptedCell(field) + " | " + field.doc);
      }
    }
    for (const TextField<Part>& text : variant.texts) {
      row(std::string("`") + text.key + "` | | " + (text.required ? "required" : "optional") +
          " | any text but the empty one | " + text.doc);
    }
    for (const FlagField<Part>& flag : variant.flags) {
      row(std::string("`") + flag.key + "` | | " + (flag.default_value ? "true" : "false") +
          " | true or false | " + flag.doc);
    }
    for (const char* other : variant.other_keys) {
      std::string cells = "| | its own rules (above) | ";
      for (const auto& [described, its_cells] : other_cells) {
        if (described == other) cells = its_cells;
      }
      row(std::string("`") + other + "` | " + cells);
    }
  }
  return table;
}

}  // namespace musclesim
