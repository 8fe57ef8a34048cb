// musclesim.InputError and musclesim.ParameterError (musclesim/_errors.py): the library's
// exceptions raised in Python with their message and, as attributes, the fields they carry
// (nothing is parsed from the message).
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

// Text from an input may hold any bytes: those not UTF-8 become U+FFFD.
py::object Text(const std::string& text) {
  return py::reinterpret_steal<py::object>(
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace"));
}

py::object OptionalText(const std::optional<std::string>& text) {
  return text ? Text(*text) : py::object(py::none());
}

// The fault's fields as attributes (InputError in core/errors.h): `key` and `location` None
// where the fault names none.
void RaiseInputError(const InputError& e) {
  const InputFault& fault = e.fault();
  py::object error = py::reinterpret_borrow<py::object>(input_error_type)(e.what());
  const bool positioned = fault.place && fault.place->positioned();
  error.attr("key") = fault.key.empty() ? py::object(py::none()) : Text(fault.key);
  error.attr("location") = positioned ? Text(PlaceText(*fault.place)) : py::object(py::none());
  error.attr("file") = OptionalText(fault.place ? std::optional(fault.place->file) : std::nullopt);
  error.attr("line") =
      positioned ? py::object(py::int_(fault.place->line)) : py::object(py::none());
  const bool has_column = positioned && fault.place->column > 0;  // a CSV row has none
  error.attr("column") =
      has_column ? py::object(py::int_(fault.place->column)) : py::object(py::none());
  error.attr("value") = OptionalText(fault.value);
  error.attr("rule") = Text(fault.rule);
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
      RaiseInputError(e);
    } catch (const ParameterError& e) {
      RaiseParameterError(e);
    }
  });
}

}  // namespace musclesim::python
