// CheckSummaryPath (sweep_runner.h): the summary's path, before any point runs.
#include "musclesim/sweep/sweep_runner.h"

#include <filesystem>
#include <utility>
#include <system_error>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/file_roles.h"

namespace musclesim {

void CheckSummaryPath(const SweepSpec& spec, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) {
    // the summary in memory: nowhere to put each run's trajectory beside it
    if (spec.trajectories != TrajectoryPolicy::kNone) {
      throw InputError("trajectories: " + std::string(ToString(spec.trajectories)) +
                       " writes each run's trajectory beside the summary: give the summary a "
                       "file");
    }
    return;
  }
  std::error_code error;
  if (fs::is_directory(path, error)) {
    throw InputError(path + ": is a directory: name the summary's CSV file");
  }
  const fs::path directory = fs::path(path).parent_path();
  if (!directory.empty() && !fs::is_directory(directory, error)) {
    throw InputError(path + ": the directory " + directory.string() +
                     " does not exist: create it, or write the summary elsewhere");
  }
  CheckOutputFiles({{spec.source, "the sweep file"}, {spec.base, "the base scenario"}},
                   {{path, "the summary"}});
  if (spec.trajectories == TrajectoryPolicy::kNone) return;
  // each run's trajectory goes to FOLDER/INDEX.csv (PointRunner): no input may lie there
  const fs::path folder =
      fs::weakly_canonical(directory / (fs::path(path).stem().string() + "_trajectories"), error);
  for (const auto& [input, name] :
       {std::pair{spec.source, "the sweep file"}, std::pair{spec.base, "the base scenario"}}) {
    if (input.empty()) continue;
    const fs::path at = fs::weakly_canonical(input, error).parent_path();
    if (!error && at == folder) {
      throw InputError(path + ": trajectories: " + std::string(ToString(spec.trajectories)) +
                       " writes each run's trajectory into " + folder.string() + "/, where " +
                       name + " " + input +
                       " lies and would be overwritten: move it, or name the summary otherwise");
    }
  }
}

}  // namespace musclesim
