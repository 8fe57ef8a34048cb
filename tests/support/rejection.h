// Test helper: what a check throws, as text, so that a test states each validation rule as
// the message it expects.
#pragma once

#include <string>

#include "musclesim/core/errors.h"

namespace musclesim::testing {

// The ParameterError message `check()` throws, or "accepted" when it throws nothing.
template <typename Check>
std::string Rejection(Check check) {
  try {
    check();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace musclesim::testing
