#include "overrides.h"

namespace musclesim::python {

namespace py = pybind11;

std::vector<std::string> OverridesFrom(const py::handle& overrides) {
  std::vector<std::string> result;
  if (overrides.is_none()) return result;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides)) {
      std::string text;
      if (py::isinstance<py::bool_>(value)) {
        text = value.cast<bool>() ? "true" : "false";
      } else if (py::isinstance<py::str>(value)) {
        text = value.cast<std::string>();
      } else {
        text = py::repr(value).cast<std::string>();  // round-trip digits for floats
      }
      result.push_back(py::str(key).cast<std::string>() + "=" + text);
    }
    return result;
  }
  if (py::isinstance<py::str>(overrides)) {
    throw py::type_error("overrides: expected a list of \"key=value\" strings or a dict, got a str");
  }
  for (const auto& item : overrides) {
    if (!py::isinstance<py::str>(item)) {
      throw py::type_error("overrides: every item must be a \"key=value\" string, got " +
                           py::repr(item).cast<std::string>());
    }
    result.push_back(item.cast<std::string>());
  }
  return result;
}

}  // namespace musclesim::python
