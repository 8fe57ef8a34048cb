// The verbs of `musclesim`, one function per verb named after it. Each parses its own
// arguments, calls the library and returns an exit code; errors are thrown and mapped to
// exit codes by main.
#pragma once

namespace musclesim::cli {

int CurvesCommand(int argc, char** argv);    // musclesim curves ...
int FitCommand(int argc, char** argv);       // musclesim fit ...
int IdentifyCommand(int argc, char** argv);  // musclesim identify ...
// musclesim identify on a data file of measured time series (identify_series_command.cc):
// whether argv names such a file, its part of identify --help, and the verb on it
bool NamesSeriesDataFile(int argc, char** argv);
const char* IdentifySeriesHelp();
int IdentifySeriesCommand(int argc, char** argv);
int PlotCommand(int argc, char** argv);   // musclesim plot ...
int RunCommand(int argc, char** argv);    // musclesim run ...
int SweepCommand(int argc, char** argv);  // musclesim sweep ...

}  // namespace musclesim::cli
