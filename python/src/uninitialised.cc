// Objects made without their constructor: `Model.__new__(Model)`, or a subclass whose
// __init__ does not call the base's. pybind11 hands a method of such an object memory it
// allocates on the spot and never constructs (its "lazy allocation"), so a method would read
// garbage or crash. Every bound type's allocation hook instead raises TypeError, which is the
// only use pybind11 makes of that hook: constructors build their objects themselves.
#include <string>

#include "bindings.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

[[noreturn]] void* RefuseLazyAllocation(std::size_t) {
  throw py::type_error(
      "this musclesim object was made without its constructor (T.__new__(T), or a subclass "
      "whose __init__ does not call super().__init__()): create it by calling its class");
}

void GuardTypesIn(const py::handle scope) {
  // a module's __dict__ is a dict, a class's a mapping proxy: both have values()
  for (const py::handle value : scope.attr("__dict__").attr("values")()) {
    if (!PyType_Check(value.ptr())) continue;
    py::detail::type_info* info =
        py::detail::get_type_info(reinterpret_cast<PyTypeObject*>(value.ptr()));
    if (info == nullptr || info->operator_new == &RefuseLazyAllocation) continue;
    info->operator_new = &RefuseLazyAllocation;
    GuardTypesIn(value);  // types defined inside a class
  }
}

}  // namespace

void RefuseUninitialisedObjects(py::module_& m) { GuardTypesIn(m); }

}  // namespace musclesim::python
