// Error types shared by every layer (the command line maps them to its exit codes).
//
// A ParameterError says which parameter broke which rule, with the parameter named by its
// path inside the block being validated ("velocity.n", "gaussians[1].width"). Readers of
// files catch it and re-throw an InputError that adds the file, line and column.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "musclesim/core/number_format.h"  // FormatNumber, which Require's messages use

namespace musclesim {

// A parameter value that breaks a rule. `path` is relative to the validated struct. what()
// quotes the path and value with their control characters written as \xHH.
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string path, std::string value, std::string rule);

  const std::string& path() const { return path_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string path_;
  std::string value_;
  std::string rule_;
};

// Invalid user input, already located: the message is complete and printable as is (its
// control characters, quoted from a file, written as \xHH: core/printable_text.h).
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
};

// Throws ParameterError(path, value, rule) unless the condition holds.
void Require(bool condition, std::string_view path, double value, std::string_view rule);

// `value` after Validate(value) (found by argument-dependent lookup): what a validating
// factory returns.
template <typename T>
T Validated(T value) {
  Validate(value);
  return value;
}

}  // namespace musclesim
