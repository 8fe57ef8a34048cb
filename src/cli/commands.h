// The verbs of `musclesim`. Each parses its own arguments, does one job and returns an
// exit code; errors are thrown and mapped to exit codes by main.
#pragma once

namespace musclesim::cli {

int RunCurves(int argc, char** argv);  // musclesim curves ...
int RunFit(int argc, char** argv);     // musclesim fit ...
int RunRun(int argc, char** argv);     // musclesim run ...

}  // namespace musclesim::cli
