// Runs gnuplot on a script held in memory: the script goes to gnuplot's standard input, so no
// file is written but the figure itself.
#pragma once

#include <string>

namespace musclesim {

// Runs `gnuplot` (found on PATH; no shell between, so no name is ever parsed as a command)
// with `script` on its standard input. Returns whether it exited with 0; `messages` receives
// the first 16 KiB of what it printed on standard error (its standard output, where a plot
// goes when its `set output` failed, is discarded). Throws std::runtime_error when gnuplot cannot
// be started (with the package to install when it is missing).
bool RunGnuplot(const std::string& script, std::string& messages);

}  // namespace musclesim
