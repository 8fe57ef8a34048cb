#include "musclesim/errors.h"

#include <charconv>
#include <cmath>

namespace musclesim {

ParameterError::ParameterError(std::string path, std::string value, std::string rule)
    : std::invalid_argument(path + " = " + value + ": " + rule),
      path_(std::move(path)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

std::string FormatNumber(double value) {
  // std::to_chars gives the shortest text that reads back to the same double
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

void Require(bool condition, std::string_view path, double value, std::string_view rule) {
  if (!condition) {
    throw ParameterError(std::string(path), FormatNumber(value), std::string(rule));
  }
}

}  // namespace musclesim
