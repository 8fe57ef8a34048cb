// Input errors that name a temporary file by the name the user knows: a dict scenario or
// sweep is read from a temporary file, its messages should say "<dict>", not /tmp/....
#pragma once

#include <string>

#include "musclesim/core/errors.h"

namespace musclesim::python {

// `text` with every occurrence of `path` shown as `display`.
inline std::string Aliased(std::string text, const std::string& path, const std::string& display) {
  if (path.empty() || path == display) return text;
  for (std::size_t at = text.find(path); at != std::string::npos;
       at = text.find(path, at + display.size())) {
    text.replace(at, path.size(), display);
  }
  return text;
}

// Runs `call`; an InputError it throws is re-thrown with every `path` in its message
// replaced by `display`.
template <typename Call>
auto WithFileAlias(const std::string& path, const std::string& display, Call call) {
  try {
    return call();
  } catch (const InputError& e) {
    if (display == path || path.empty()) throw;
    throw InputError(Aliased(e.what(), path, display));
  }
}

}  // namespace musclesim::python
