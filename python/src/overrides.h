// --set overrides from Python: a list of "key=value" strings, or a dict {key: value}.
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace musclesim::python {

// None: none. A dict's values are written as --set reads them (True/False as true/false,
// numbers with repr's round-trip digits, strings as they are).
std::vector<std::string> OverridesFrom(const pybind11::handle& overrides);

}  // namespace musclesim::python
