// How numbers (and lists of names) become text, for every layer: messages and YAML print the
// shortest exact form, CSV and JSON columns a fixed 17 significant digits. Both read back to the
// same double; they differ only in how many digits they spend.
#pragma once

#include <string>
#include <vector>

namespace musclesim {

// The shortest text that reads back to the same double ("0.1", "1e-06"): for error
// messages, model YAML and plot scripts, where a reader wants the value as it was typed.
std::string FormatNumber(double value);

// Exactly as printf's %.17g ("0.10000000000000001"): for CSV and JSON columns, whose bytes
// must not depend on how short a value happens to be.
std::string FormatFull(double value);

// `value` to `digits` significant digits ("0.14", "2.4e-05", "inf", "n/a" for NaN): for
// text a person reads (reports, summaries, messages about results), never for text read back.
std::string FormatSignificant(double value, int digits);

// "a, b, c": names listed in a message, in their order.
std::string CommaSeparated(const std::vector<std::string>& names);

}  // namespace musclesim
