#include "musclesim/io/readers/csv_table.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/input_file.h"

namespace musclesim {

namespace {

std::vector<std::string> SplitRow(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

int CsvTable::Find(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  return -1;
}

void CsvTable::Require(const std::vector<std::string>& names, const std::string& what) const {
  std::string missing;
  for (const std::string& name : names) {
    if (Find(name) < 0) missing += (missing.empty() ? "" : ", ") + name;
  }
  if (!missing.empty()) {
    throw InputError(InputFault{InputPlace{source}, "", std::nullopt,
                                "missing columns: " + missing + " (" + what + ")"});
  }
}

double CsvTable::Number(std::size_t row, int column) const {
  const std::string& text = rows[row][static_cast<std::size_t>(column)];
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  // ERANGE on underflow still gives the nearest double (subnormals musclesim itself writes);
  // only an overflow to +-HUGE_VAL is not the number written
  const bool overflow = errno == ERANGE && std::abs(value) == HUGE_VAL;
  if (text.empty() || end != text.c_str() + text.size() || overflow) {
    throw InputError(InputFault{InputPlace{source, static_cast<int>(lines[row])}, "", std::nullopt,
                                "column " + header[static_cast<std::size_t>(column)] + " = '" +
                                    text + "': must be a number"});
  }
  return value;
}

CsvTable ReadCsv(const std::string& path) {
  std::istringstream in(ReadInputFile(path, "a CSV file"));
  CsvTable table;
  table.source = path;
  std::string line;
  std::size_t number = 0;
  const auto next = [&] {
    while (std::getline(in, line)) {
      ++number;
      if (!line.empty() && line[0] != '#' && line != "\r") return true;
    }
    return false;
  };
  if (!next()) {
    throw InputError(InputFault{InputPlace{path}, "", std::nullopt, "empty file, no header"});
  }
  table.header = SplitRow(line);
  while (next()) {
    std::vector<std::string> fields = SplitRow(line);
    if (fields.size() != table.header.size()) {
      throw InputError(InputFault{InputPlace{path, static_cast<int>(number)}, "", std::nullopt,
                                  std::to_string(fields.size()) + " fields where the header has " +
                                      std::to_string(table.header.size())});
    }
    table.rows.push_back(std::move(fields));
    table.lines.push_back(number);
  }
  return table;
}

}  // namespace musclesim
