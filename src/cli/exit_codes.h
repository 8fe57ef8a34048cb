// Documented exit codes of the `musclesim` command (docs/guide/other-commands.md).
#pragma once

namespace musclesim {

enum ExitCode : int {
  kExitSuccess = 0,
  kExitFailure = 1,        // anything not covered below (I/O, internal)
  kExitInvalidInput = 2,   // a file, flag or value broke a documented rule
  kExitSolverFailure = 3,  // the integrator could not continue
  kExitInterrupted = 130,  // SIGINT or SIGTERM: stopped, partial results kept
};

}  // namespace musclesim
