// NumPy 2 changed the layout of an array's descriptor. pybind11 before 2.12 reads it with
// NumPy 1's layout: under NumPy 2 every array it makes has stride 0 (each row reads as the
// first) and nothing fails. A module built on such a pybind11 refuses to import there.
#include <string>

#include "bindings.h"

namespace musclesim::python {

namespace py = pybind11;

std::string NumpyRefusal(int pybind11_version_hex, const std::string& numpy_version) {
  constexpr int kFirstWithNumpy2 = 0x020C0000;  // pybind11 2.12
  const bool numpy2 = !numpy_version.empty() && numpy_version[0] != '0' &&
                      numpy_version.find('.') != std::string::npos &&
                      std::stoi(numpy_version.substr(0, numpy_version.find('.'))) >= 2;
  if (pybind11_version_hex >= kFirstWithNumpy2 || !numpy2) return "";
  const std::string built = std::to_string(pybind11_version_hex >> 24) + "." +
                            std::to_string((pybind11_version_hex >> 16) & 0xff);
  return "musclesim's module was built with pybind11 " + built +
         ", which cannot make NumPy 2 arrays (NumPy " + numpy_version +
         " is imported): every result would read as its first row. Rebuild it with pybind11 "
         ">= 2.12 (scripts/install-deps.sh installs it in build-deps/venv, which CMake finds), "
         "or use NumPy 1";
}

void RequireSupportedNumpy(py::module_& m) {
  const std::string version = py::module_::import("numpy").attr("__version__").cast<std::string>();
  if (const std::string refusal = NumpyRefusal(PYBIND11_VERSION_HEX, version); !refusal.empty()) {
    throw py::import_error(refusal);
  }
  // the rule itself, for the module's tests (python/tests/test_numpy_support.py)
  m.def("_numpy_refusal", &NumpyRefusal, py::arg("pybind11_version_hex"), py::arg("numpy_version"));
  m.attr("_pybind11_version_hex") = PYBIND11_VERSION_HEX;
}

}  // namespace musclesim::python
