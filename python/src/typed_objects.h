// Python containers whose signatures name their items. pybind11 names every py::dict `dict`
// (and py::list `list`, py::tuple `tuple`) in the signatures help() shows and the type stubs
// (musclesim/_musclesim.pyi, pybind11-stubgen) are made from; a type checker reads that as
// dict[Any, Any], and `mypy --strict` refuses such a bare generic in a stub. Each type here is
// the pybind11 type it derives from (the same checks when taken as an argument, the same
// object when returned); only the name in signatures differs. pybind11 2.10 (Debian 12) has
// no pybind11/typing.h, hence these.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace musclesim::python {
// Whether `object` is a NumPy array (the check of pybind11::array).
inline int IsNdarray(PyObject* object) {
  return pybind11::detail::npy_api::get().PyArray_Check_(object);
}
}  // namespace musclesim::python

// A class `Name` deriving from pybind11::Base, named `Hint` in signatures.
#define MUSCLESIM_TYPED_OBJECT(Name, Base, Check, Hint) \
  namespace musclesim::python {                         \
  class Name : public pybind11::Base {                  \
   public:                                              \
    PYBIND11_OBJECT_DEFAULT(Name, Base, Check)          \
  };                                                    \
  }                                                     \
  namespace pybind11::detail {                          \
  template <>                                           \
  struct handle_type_name<musclesim::python::Name> {    \
    static constexpr auto name = const_name(Hint);      \
  };                                                    \
  }

// {str: any value}: a block of keys as a file holds them, counters, a fit's result.
MUSCLESIM_TYPED_OBJECT(AnyDict, dict, PyDict_Check, "dict[str, typing.Any]")
// {str: float}: a sample of a network's values, estimates by path.
MUSCLESIM_TYPED_OBJECT(FloatDict, dict, PyDict_Check, "dict[str, float]")
// {column: 1-D NumPy array}: a run's or a fit's columns.
MUSCLESIM_TYPED_OBJECT(ArrayDict, dict, PyDict_Check, "dict[str, numpy.typing.NDArray[typing.Any]]")
// A NumPy array of float64, or of any dtype (a run's column: float64 or str).
MUSCLESIM_TYPED_OBJECT(FloatArray, array, musclesim::python::IsNdarray,
                       "numpy.typing.NDArray[numpy.float64]")
MUSCLESIM_TYPED_OBJECT(AnyArray, array, musclesim::python::IsNdarray,
                       "numpy.typing.NDArray[typing.Any]")
// A list of any values (arguments the pure-Python side has checked).
MUSCLESIM_TYPED_OBJECT(AnyList, list, PyList_Check, "list[typing.Any]")
// A list of str.
MUSCLESIM_TYPED_OBJECT(StrList, list, PyList_Check, "list[str]")
// A list of {str: any value}.
MUSCLESIM_TYPED_OBJECT(DictList, list, PyList_Check, "list[dict[str, typing.Any]]")
// A tuple of any length and values: pickled state.
MUSCLESIM_TYPED_OBJECT(AnyTuple, tuple, PyTuple_Check, "tuple[typing.Any, ...]")
