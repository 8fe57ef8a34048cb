#include "document.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

std::string Checked(std::string text, const std::string& where) {
  // a C++ message ends at a NUL byte: text holding one would lose the rest of its error
  if (text.find('\0') != std::string::npos) {
    throw py::value_error(where + ": holds a NUL character, which no key or value may hold");
  }
  return text;
}

}  // namespace

Document DocumentFrom(const py::handle& given, const std::string& where, int depth) {
  // a scenario nests a few levels; a dict or list that holds itself would never end
  constexpr int kMaxDepth = 100;
  if (depth > kMaxDepth) {
    throw py::value_error(where.substr(0, 200) + "...: nested deeper than " +
                          std::to_string(kMaxDepth) +
                          " levels (a scenario nests a few; a dict or list holding itself "
                          "never ends)");
  }
  py::object value = py::reinterpret_borrow<py::object>(given);
  if (value.is_none()) return Document();
  if (py::hasattr(value, "tolist") && !py::isinstance<py::str>(value)) {
    value = value.attr("tolist")();  // a NumPy scalar or array: its Python number or list
  }
  if (py::isinstance<py::bool_>(value)) return Document::Bool(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) {
    try {
      return Document::Integer(value.cast<long long>());
    } catch (const py::cast_error&) {
      return Document::Text(py::str(value).cast<std::string>());  // beyond 64 bits: the reader says
    }
  }
  if (py::isinstance<py::float_>(value)) return Document::Number(value.cast<double>());
  if (py::isinstance<py::str>(value))
    return Document::Text(Checked(value.cast<std::string>(), where));
  if (py::hasattr(value, "__fspath__")) {
    return Document::Text(
        Checked(py::module_::import("os").attr("fspath")(value).cast<std::string>(), where));
  }
  if (py::isinstance<py::dict>(value)) {
    std::vector<std::pair<std::string, Document>> entries;
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!py::isinstance<py::str>(key)) {
        throw py::type_error(where + ": a key must be a str, not " +
                             py::repr(key).cast<std::string>());
      }
      const std::string name = Checked(key.cast<std::string>(), where);
      entries.emplace_back(
          name, DocumentFrom(item, where.empty() ? name : where + "." + name, depth + 1));
    }
    return Document::Map(std::move(entries));
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::vector<Document> items;
    std::size_t i = 0;
    for (const py::handle item : value) {
      items.push_back(DocumentFrom(item, where + "[" + std::to_string(i++) + "]", depth + 1));
    }
    return Document::List(std::move(items));
  }
  throw py::type_error(where +
                       ": a value must be a number, a bool, a str, None, a list or a "
                       "dict, not " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

}  // namespace musclesim::python
