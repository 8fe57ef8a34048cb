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

std::string PlaceText(const InputPlace& place) {
  if (!place.positioned()) return place.file;
  const std::string line = place.file + ":" + std::to_string(place.line);
  return place.column > 0 ? line + ":" + std::to_string(place.column) : line;
}

namespace {

std::string FaultText(const InputFault& fault) {
  const std::string where = fault.place ? PlaceText(*fault.place) : std::string();
  if (fault.key.empty() && !fault.value) {
    return where.empty() ? fault.rule : where + ": " + fault.rule;
  }
  std::string text = fault.key.empty() ? "(top level)" : fault.key;
  if (fault.value) text += " = " + *fault.value;
  if (!where.empty()) text += " (" + where + ")";
  return text + ": " + fault.rule;
}

}  // namespace

InputError::InputError(const InputFault& fault, Form form, std::string head, std::string context)
    : std::runtime_error([&] {
        const std::string told = form == Form::kStandard ? FaultText(fault)
                                 : form == Form::kHeaded ? head + fault.rule
                                                         : fault.rule;
        return PrintableText(context.empty() ? told : context + ": " + told);
      }()),
      fault_(fault),
      form_(form),
      head_(std::move(head)),
      context_(std::move(context)) {}

InputError::InputError(const InputFault& fault) : InputError(fault, Form::kStandard, "", "") {}

InputError::InputError(const std::string& head, const InputFault& fault)
    : InputError(fault, Form::kHeaded, head, "") {}

InputError::InputError(const std::string& context, const InputError& inner)
    : InputError(inner.fault_, inner.form_, inner.head_,
                 inner.context_.empty() ? context : context + ": " + inner.context_) {}

InputError::InputError(const std::string& message)
    : InputError(InputFault{std::nullopt, "", std::nullopt, message}, Form::kComposed, "", "") {}

InputError InputError::WithFault(const InputFault& fault) const {
  InputFault kept = fault;
  if (form_ == Form::kComposed) kept.rule = fault_.rule;  // the message as its thrower wrote it
  return InputError(kept, form_, head_, context_);
}

void Require(bool condition, std::string_view path, double value, std::string_view rule) {
  if (!condition) {
    throw ParameterError(std::string(path), FormatNumber(value), std::string(rule));
  }
}

}  // namespace musclesim
