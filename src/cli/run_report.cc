#include "cli/run_report.h"

#include <iostream>

#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/stats_json.h"

namespace musclesim::cli {

std::string RunOutputPath(const Arguments& args, const std::string& file,
                          const std::string& source) {
  const std::string output = args.Value("-o", file);
  if (output.empty()) {
    throw InputError(source + ": no output file: set output.file or pass -o PATH");
  }
  std::vector<FileRole> outputs = {{output, args.Has("-o") ? "-o" : "output.file"}};
  if (args.Has("--stats")) outputs.push_back({args.Value("--stats"), "--stats"});
  CheckOutputFiles({{source, "the scenario file"}}, outputs);
  return output;
}

int FinishRun(const Arguments& args, StreamedOutput& csv, const RunStats& stats,
              const RunOutcome& outcome) {
  if (args.Has("--stats")) {
    WriteOutput(args.Value("--stats"), FormatStatsJson(stats, outcome.sensitivities));
  }
  if (stats.status == RunStatus::kFailed) {
    const std::string& partial = csv.written_path();
    std::cerr << "musclesim run: " << outcome.label << ": solver failure: " << stats.message << "\n"
              << "musclesim run: the " << outcome.rows << " rows computed so far are in "
              << (partial == "-" ? std::string("standard output") : partial)
              << (csv.in_place() ? "" : "; " + outcome.output + " was left as it was") << "\n";
    return kExitSolverFailure;
  }
  csv.Commit();

  if (!args.Has("--quiet")) {
    for (const std::string& note : outcome.notes) std::cerr << "musclesim run: " << note << "\n";
    if (stats.status == RunStatus::kLimit) std::cerr << "musclesim run: " << stats.message << "\n";
    std::cerr << "musclesim run: " << outcome.label << ": " << ToString(stats.status)
              << " at t = " << FormatNumber(stats.final_time) << " s: " << stats.steps << " steps, "
              << stats.rhs_evals << " RHS evaluations, " << stats.wall_seconds * 1e3 << " ms, "
              << ToString(stats.linear_solver) << " linear solver, " << outcome.result << " -> "
              << outcome.output << "\n";
  }
  return kExitSuccess;
}

}  // namespace musclesim::cli
