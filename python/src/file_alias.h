// Input errors that name a temporary file by the name the user knows: a dict scenario or
// sweep is read from a temporary file, its messages should say "<dict>", not /tmp/....
#pragma once

#include <string>

#include "musclesim/errors.h"

namespace musclesim::python {

// Runs `call`; an InputError it throws is re-thrown with every `path` in its message
// replaced by `display` (unchanged when the two are the same).
template <typename Call>
auto WithFileAlias(const std::string& path, const std::string& display, Call call) {
  try {
    return call();
  } catch (const InputError& e) {
    if (display == path || path.empty()) throw;
    std::string message = e.what();
    for (std::size_t at = message.find(path); at != std::string::npos;
         at = message.find(path, at + display.size())) {
      message.replace(at, path.size(), display);
    }
    throw InputError(message);
  }
}

}  // namespace musclesim::python
