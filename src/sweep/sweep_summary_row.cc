#include "sweep/sweep_summary_row.h"

#include <cmath>
#include <cstdlib>

namespace musclesim {

namespace {

bool IsDigits(const std::string& text) {
  return !text.empty() && text.size() <= 18 &&
         text.find_first_not_of("0123456789") == std::string::npos;
}

// A number as FormatFull writes it (finite), or an empty field when `empty_ok`.
bool IsNumber(const std::string& text, bool empty_ok) {
  if (text.empty()) return empty_ok;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

std::string_view ToString(RowStatus status) {
  switch (status) {
    case RowStatus::kOk: return "ok";
    case RowStatus::kFailed: return "failed";
    case RowStatus::kInvalid: return "invalid";
  }
  return "?";
}

std::optional<RowStatus> ParseRowStatus(std::string_view text) {
  for (const RowStatus s : {RowStatus::kOk, RowStatus::kFailed, RowStatus::kInvalid}) {
    if (text == ToString(s)) return s;
  }
  return std::nullopt;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

std::optional<std::vector<std::string>> SplitCsvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t i = 0;
  for (;;) {
    const std::size_t start = i;
    if (i < line.size() && line[i] == '"') {
      // a quoted field ends at a quote not doubled, which a comma or the end must follow
      for (++i;; ++i) {
        if (i >= line.size()) return std::nullopt;
        if (line[i] != '"') continue;
        if (i + 1 < line.size() && line[i + 1] == '"') {
          ++i;
          continue;
        }
        break;
      }
      ++i;
      if (i < line.size() && line[i] != ',') return std::nullopt;
    } else {
      i = std::min(line.find(',', i), line.size());
      if (line.substr(start, i - start).find('"') != std::string::npos) return std::nullopt;
    }
    fields.push_back(line.substr(start, i - start));
    if (i >= line.size()) return fields;
    ++i;  // the comma
  }
}

CheckedRow CheckRow(const SweepSpec& spec, long points, const std::string& line) {
  CheckedRow row;
  if (line.find('\r') != std::string::npos) {
    row.problem = "a carriage return (edited into the file?)";
    return row;
  }
  const std::optional<std::vector<std::string>> split = SplitCsvFields(line);
  if (!split) {
    row.problem = "broken quoting";
    return row;
  }
  const std::vector<std::string>& f = *split;
  const std::size_t axes = spec.axes.size(), metrics = spec.metrics.size();
  const std::size_t expected = 1 + axes + 1 + metrics + 4;
  if (f.size() != expected) {
    row.problem = std::to_string(f.size()) + " fields, expected " + std::to_string(expected);
    return row;
  }
  if (!IsDigits(f[0])) {
    row.problem = "index '" + f[0] + "' is not a number";
    return row;
  }
  const long index = std::strtol(f[0].c_str(), nullptr, 10);
  if (std::to_string(index) != f[0]) {
    row.problem = "index '" + f[0] + "' is not written as the sweep writes it";
    return row;
  }
  if (index >= points) {
    row.problem = "index " + f[0] + " is beyond the sweep's " + std::to_string(points) + " points";
    return row;
  }
  row.index = index;
  const std::vector<std::string> values = PointValues(spec, index);
  for (std::size_t k = 0; k < axes; ++k) {
    if (f[1 + k] != CsvField(values[k])) {
      row.problem =
          spec.axes[k].path + " = " + f[1 + k] + ", but point " + f[0] + " has " + values[k];
      return row;
    }
  }
  const std::optional<RowStatus> status = ParseRowStatus(f[1 + axes]);
  if (!status) {
    row.problem = "status '" + f[1 + axes] + "' is not ok, failed or invalid";
    return row;
  }
  row.status = *status;
  for (std::size_t m = 0; m < metrics; ++m) {
    if (!IsNumber(f[2 + axes + m], true)) {
      row.problem =
          std::string(ToString(spec.metrics[m])) + " '" + f[2 + axes + m] + "' is not a number";
      return row;
    }
  }
  const std::size_t steps = 2 + axes + metrics;
  if (!IsDigits(f[steps]) || !IsDigits(f[steps + 1]) || !IsNumber(f[steps + 2], false)) {
    row.problem = "steps, rhs_evals or wall_seconds is not a number";
    return row;
  }
  return row;
}

}  // namespace musclesim
