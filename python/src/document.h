// Python values as a Document (io/readers/document.h): a dict scenario, sweep or identification
// spec read by the file readers with no text in between.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include "musclesim/io/readers/document.h"

namespace musclesim::python {

// `value` as a document: a dict (str keys) as a map, a list or tuple as a list, None, bool,
// int, float and str as themselves, a NumPy scalar or array as the Python number or list it
// holds, an os.PathLike as its path. `where` names it in a TypeError for any other type, or
// a str holding a NUL character (ValueError).
Document DocumentFrom(const pybind11::handle& value, const std::string& where, int depth = 0);

}  // namespace musclesim::python
