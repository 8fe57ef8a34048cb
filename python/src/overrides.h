// Overrides from Python (the command line's --set): a list of "key=value" strings, or a dict {key:
// value}.
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace musclesim::python {

// "key=value" as --set takes it: a bool as true/false, a float by its shortest exact text
// (repr), an int or a str as written; a NumPy scalar as the Python number it holds. Any
// other type is a TypeError naming the key.
std::string OverrideText(const std::string& key, const pybind11::handle& value);

// None: none. A dict's values as OverrideText writes them; a list's items must be
// "key=value" strings.
std::vector<std::string> OverridesFrom(const pybind11::handle& overrides);

// What messages call a value Python set (Scenario.set, overrides): "KEY = VALUE (set)".
inline const char* const kOverrideLabel = "set";

// A path given as str or os.PathLike (pathlib.Path), as text; TypeError otherwise.
std::string PathText(const pybind11::handle& path, const char* what);

}  // namespace musclesim::python
