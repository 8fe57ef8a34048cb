// musclesim.InputError and musclesim.ParameterError (musclesim/_errors.py): the library's
// exceptions raised in Python with their message, plus the parts a program wants without
// parsing it.
#include <regex>
#include <optional>
#include <string>

#include "bindings.h"
#include "musclesim/core/errors.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// The Python types, looked up once by BindErrors and kept for the interpreter's life.
PyObject* input_error_type = nullptr;
PyObject* parameter_error_type = nullptr;

struct MessageParts {
  std::optional<std::string> key;       // the dotted key path
  std::optional<std::string> location;  // "file:line:column"
};

// The key and the place an InputError's message names. The readers write them as
//   KEY = VALUE (FILE:LINE:COLUMN): RULE      (yaml_fields.cc Fail)
//   KEY (FILE:LINE:COLUMN): RULE              (a missing or unknown key)
//   FILE:LINE:COLUMN: YAML syntax error: ...
//   set KEY=VALUE: ...                        (an override that names no value)
//   ARGUMENT: row N: ...                      (data given as arrays: the argument's name)
//   --sensitivity PATH: ...                   (a sensitivity's parameter; from Python,
//   sensitivities PATH: ...                    Scenario.run's `sensitivities`)
//   FILE:LINE:COLUMN: KEY = VALUE ...         (an entry whose value the reader refers on)
//   FILE:LINE:COLUMN: axis PATH = VALUE ...   (a sweep's axis: key parameters.PATH)
// and a value given by an override is placed at "set" (no file position: location None);
// a dict's entries are placed at the dict's name ("<dict>", "identify_series"): location None.
MessageParts ParseInputMessage(const std::string& message) {
  MessageParts parts;
  static const std::regex located(R"(^(\(top level\)|\S+)(?: = .*?)? \(([^()]*)\): )");
  static const std::regex syntax(R"(^(.*:\d+:\d+): )");
  static const std::regex override_text(R"(^(?:set|override) ([^=:\s]+)=)");
  static const std::regex position(R"(.*:\d+:\d+$)");
  static const std::regex array_row(R"(^([A-Za-z_][\w.\[\]]*): row \d+: )");
  static const std::regex sensitivity(R"(^(?:--sensitivity|sensitivities) ([^:\s]+): )");
  static const std::regex placed_entry(R"(^([^\s:]+(?::\d+:\d+)?): (axis )?([^\s=()]+) = )");
  std::smatch match;
  if (std::regex_search(message, match, override_text) ||
      std::regex_search(message, match, array_row) ||
      std::regex_search(message, match, sensitivity)) {
    parts.key = match[1].str();
  } else if (std::regex_search(message, match, placed_entry)) {
    if (std::regex_match(match[1].str(), position)) parts.location = match[1].str();
    parts.key = (match[2].matched ? "parameters." : "") + match[3].str();
  } else if (std::regex_search(message, match, located)) {
    if (match[1].str() != "(top level)") parts.key = match[1].str();
    const std::string where = match[2].str();
    if (std::regex_match(where, position)) parts.location = where;
  } else if (std::regex_search(message, match, syntax)) {
    parts.location = match[1].str();
  }
  return parts;
}

py::object OptionalText(const std::optional<std::string>& text) {
  return text ? py::object(py::str(*text)) : py::object(py::none());
}

void RaiseInputError(const std::string& message) {
  const MessageParts parts = ParseInputMessage(message);
  py::object error = py::reinterpret_borrow<py::object>(input_error_type)(message);
  error.attr("key") = OptionalText(parts.key);
  error.attr("location") = OptionalText(parts.location);
  PyErr_SetObject(input_error_type, error.ptr());
}

void RaiseParameterError(const ParameterError& e) {
  py::object error = py::reinterpret_borrow<py::object>(parameter_error_type)(e.what());
  error.attr("path") = e.path();
  error.attr("value") = e.value();
  error.attr("rule") = e.rule();
  PyErr_SetObject(parameter_error_type, error.ptr());
}

}  // namespace

void BindErrors(py::module_& m) {
  // Python classes (musclesim/_errors.py, with their docstrings and attributes), so that the
  // type stubs describe them
  const py::module_ errors = py::module_::import("musclesim._errors");
  input_error_type = py::object(errors.attr("InputError")).release().ptr();
  parameter_error_type = py::object(errors.attr("ParameterError")).release().ptr();
  m.add_object("InputError", py::reinterpret_borrow<py::object>(input_error_type));
  m.add_object("ParameterError", py::reinterpret_borrow<py::object>(parameter_error_type));

  // the library's own check, for tests of the translation: a ParameterError built by it
  m.def(
      "_require",
      [](bool condition, const std::string& path, double value, const std::string& rule) {
        Require(condition, path, value, rule);
      },
      py::arg("condition"), py::arg("path"), py::arg("value"), py::arg("rule"),
      "The library's Require: raises ParameterError(path, value, rule) unless `condition`.");

  // tried before pybind11's own translators, which map std::invalid_argument to ValueError
  // and std::runtime_error to RuntimeError with the message (InputError and ParameterError
  // derive from them)
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      RaiseInputError(e.what());
    } catch (const ParameterError& e) {
      RaiseParameterError(e);
    }
  });
}

}  // namespace musclesim::python
