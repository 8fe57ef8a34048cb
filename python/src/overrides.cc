#include "overrides.h"

#include <cmath>

namespace musclesim::python {

namespace py = pybind11;

namespace {

// A C++ message ends at a NUL byte: text holding one would lose the rest of its error.
std::string WithoutNul(std::string text, const std::string& what) {
  if (text.find('\0') != std::string::npos) {
    throw py::value_error(what + ": holds a NUL character, which no key or value may hold");
  }
  return text;
}

}  // namespace

std::string OverrideText(const std::string& key, const pybind11::handle& given) {
  py::object value = py::reinterpret_borrow<py::object>(given);
  if (py::isinstance(value, py::module_::import("numpy").attr("generic"))) {
    value = value.attr("item")();  // np.float32(0.5) -> 0.5, np.int64(3) -> 3
  }
  std::string text;
  if (py::isinstance<py::bool_>(value)) {
    text = value.cast<bool>() ? "true" : "false";
  } else if (py::isinstance<py::int_>(value) || py::isinstance<py::str>(value)) {
    text = WithoutNul(py::str(value).cast<std::string>(), key);
  } else if (py::isinstance<py::float_>(value)) {
    const double number = value.cast<double>();
    // YAML's spellings of the non-finite numbers, so that the reader names the rule broken
    text = std::isnan(number)   ? ".nan"
           : std::isinf(number) ? (number > 0 ? ".inf" : "-.inf")
                                : py::repr(value).cast<std::string>();
  } else {
    const std::string type = py::str(py::type::of(value).attr("__name__"));
    throw py::type_error(key + ": the value must be a number, a bool or a str, not " + type);
  }
  return WithoutNul(key, "a key") + "=" + text;
}

std::vector<std::string> OverridesFrom(const py::handle& overrides) {
  std::vector<std::string> result;
  if (overrides.is_none()) return result;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides)) {
      result.push_back(OverrideText(py::str(key).cast<std::string>(), value));
    }
    return result;
  }
  if (py::isinstance<py::str>(overrides)) {
    throw py::type_error("set: expected a list of \"key=value\" strings or a dict, got one str");
  }
  for (const auto& item : overrides) {
    if (!py::isinstance<py::str>(item)) {
      throw py::type_error("set: every item must be a \"key=value\" string, got " +
                           py::repr(item).cast<std::string>());
    }
    result.push_back(WithoutNul(item.cast<std::string>(), "set"));
  }
  return result;
}

std::string PathText(const py::handle& path, const char* what) {
  if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__")) {
    throw py::type_error(std::string(what) + ": expected a path (str or pathlib.Path), not " +
                         py::str(py::type::of(path).attr("__name__")).cast<std::string>());
  }
  const py::object text = py::module_::import("os").attr("fspath")(path);
  if (!py::isinstance<py::str>(text)) {
    throw py::type_error(std::string(what) + ": expected a str path, not bytes");
  }
  return text.cast<std::string>();
}

}  // namespace musclesim::python
