#include "musclesim/core/errors.h"

#include <utility>

namespace musclesim {

ParameterError::ParameterError(std::string path, std::string value, std::string rule)
    : std::invalid_argument(path + " = " + value + ": " + rule),
      path_(std::move(path)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

void Require(bool condition, std::string_view path, double value, std::string_view rule) {
  if (!condition) {
    throw ParameterError(std::string(path), FormatNumber(value), std::string(rule));
  }
}

}  // namespace musclesim
