// Error types shared by every layer (the command line maps them to its exit codes).
//
// A ParameterError says which parameter broke which rule, with the parameter named by its
// path inside the block being validated ("velocity.n", "gaussians[1].width"). Readers of
// files catch it and re-throw an InputError that adds the file, line and column.
#pragma once

#include <optional>
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

// Where in an input a fault lies: its file, or the label of an input that has none ("--set",
// a dict's name, "row 3" of data given in memory), and the 1-based line and column when the
// place is known to that precision (0 when not: a CSV row has a line and no column).
struct InputPlace {
  std::string file;
  int line = 0;
  int column = 0;

  bool positioned() const { return line > 0; }
};

// "FILE:LINE:COLUMN", "FILE:LINE" without a column (a CSV row), or FILE alone.
std::string PlaceText(const InputPlace& place);

// What an input error says, as data: where, the key (a dotted path from the input's top;
// empty for the input as a whole or a fault of no key), the value as written when a value is
// at fault, and the rule broken.
struct InputFault {
  std::optional<InputPlace> place;
  std::string key;
  std::optional<std::string> value;
  std::string rule;
};

// Invalid user input, located. The message is formatted here from the fault (the forms
// below) and printable as is (its control characters, quoted from a file, written as \xHH:
// core/printable_text.h); programs read the fault's fields, never the message.
class InputError : public std::runtime_error {
 public:
  // "KEY = VALUE (PLACE): RULE"; without a value "KEY (PLACE): RULE"; "(top level)" for an
  // empty key; "PLACE: RULE" with neither key nor value.
  explicit InputError(const InputFault& fault);
  // A fault told after a head that says what it came through, the head ending in its
  // separator ("--set KEY=VALUE: ", "--sensitivity PATH: ", "FILE:3:5: axis KEY = VALUE "):
  // "HEAD" followed by the rule.
  InputError(const std::string& head, const InputFault& fault);
  // `inner` reached through `context` (a muscle of an import, a data file of an entry):
  // "CONTEXT: INNER", with inner's fault.
  InputError(const std::string& context, const InputError& inner);
  // A message its thrower composed (a file that cannot be read, a conversion's report): the
  // whole message is the rule, kept as it is when a caller adds fields it knows (WithFault).
  explicit InputError(const std::string& message);

  const InputFault& fault() const { return fault_; }
  // The same error told of `fault` (a place found afterwards, say), in the same form.
  InputError WithFault(const InputFault& fault) const;

 private:
  enum class Form { kStandard, kHeaded, kComposed };
  InputError(const InputFault& fault, Form form, std::string head, std::string context);

  InputFault fault_;
  Form form_;
  std::string head_;     // kHeaded's
  std::string context_;  // empty: none
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
