// What `musclesim run` says about a finished run, the same for a single actuator and a
// network: the stats file, the partial file on failure, the notes and the summary line.
#pragma once

#include <string>
#include <vector>

#include "cli/arguments.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/writers/stats_json.h"
#include "musclesim/solver/simulation.h"

namespace musclesim::cli {

// The CSV's path: -o PATH, else the scenario's output.file. Throws InputError naming
// `source` (the scenario file) when neither gives one.
std::string RunOutputPath(const Arguments& args, const std::string& file,
                          const std::string& source);

struct RunOutcome {
  std::string label;                           // the scenario's name, or its file
  std::string output;                          // the CSV's path as given ("-": standard output)
  long rows = 0;                               // rows written so far
  std::string result;                          // the summary's last item before " -> output"
  std::vector<std::string> notes;              // lines printed before the summary unless --quiet
  std::vector<SensitivityNote> sensitivities;  // a run with sensitivities: for --stats
};

// Writes --stats. On a solver failure, says where the rows computed so far are and returns
// kExitSolverFailure, `csv` left uncommitted; otherwise commits `csv`, prints (unless
// --quiet) the notes, the limit reached and the summary line, and returns kExitSuccess.
int FinishRun(const Arguments& args, StreamedOutput& csv, const RunStats& stats,
              const RunOutcome& outcome);

}  // namespace musclesim::cli
