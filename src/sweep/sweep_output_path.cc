// CheckSummaryPath (sweep_runner.h): the summary's path, before any point runs.
#include "musclesim/sweep/sweep_runner.h"

#include <filesystem>
#include <system_error>

#include "musclesim/core/errors.h"
#include "musclesim/io/file_roles.h"

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
}

}  // namespace musclesim
