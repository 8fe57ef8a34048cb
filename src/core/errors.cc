#include "musclesim/core/errors.h"

#include <utility>

#include "musclesim/core/printable_text.h"

namespace musclesim {

// The path and the value come from files and callers: quoted escaped (printable_text.h).
ParameterError::ParameterError(std::string path, std::string value, std::string rule)
    : std::invalid_argument(PrintableText(path) + " = " + PrintableText(value) + ": " + rule),
      path_(std::move(path)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

InputError::InputError(const std::string& message) : std::runtime_error(PrintableText(message)) {}

void Require(bool condition, std::string_view path, double value, std::string_view rule) {
  if (!condition) {
    throw ParameterError(std::string(path), FormatNumber(value), std::string(rule));
  }
}

}  // namespace musclesim
