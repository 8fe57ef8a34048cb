#include "musclesim/io/file_roles.h"

#include <filesystem>
#include <system_error>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

namespace fs = std::filesystem;

bool Skipped(const std::string& path) { return path.empty() || path == "-"; }

bool IsExistingNonRegular(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  return !error && fs::exists(status) && !fs::is_regular_file(status);
}

// Device and inode when both exist; otherwise the paths with every link and ".." resolved.
bool SameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  const fs::path resolved_a = fs::weakly_canonical(a, error);
  if (error) return false;
  const fs::path resolved_b = fs::weakly_canonical(b, error);
  return !error && resolved_a == resolved_b;
}

std::string Partial(const std::string& path) { return path + ".partial"; }

}  // namespace

void CheckOutputFiles(const std::vector<FileRole>& inputs, const std::vector<FileRole>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const FileRole& out = outputs[i];
    if (Skipped(out.path)) continue;
    const std::string said = out.name + " " + out.path + ": ";
    std::error_code error;
    if (fs::is_directory(out.path, error)) {
      throw InputError(said + "is a directory: name a file in it");
    }
    const fs::path directory = fs::path(out.path).parent_path();
    if (!directory.empty() && !fs::is_directory(directory, error)) {
      throw InputError(said + "the directory " + directory.string() +
                       " does not exist: create it, or write elsewhere");
    }
    if (IsExistingNonRegular(out.path)) continue;
    for (const FileRole& in : inputs) {
      if (Skipped(in.path)) continue;
      if (SameFile(out.path, in.path)) {
        throw InputError(said + "is " + in.name + " (" + in.path +
                         "), an input: write the output elsewhere");
      }
      if (SameFile(Partial(out.path), in.path)) {
        throw InputError(said + "is written through " + Partial(out.path) + ", which is " +
                         in.name + " (" + in.path + "), an input: write the output elsewhere");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      const FileRole& other = outputs[j];
      if (Skipped(other.path) || IsExistingNonRegular(other.path)) continue;
      if (SameFile(out.path, other.path) || SameFile(Partial(out.path), other.path) ||
          SameFile(out.path, Partial(other.path))) {
        throw InputError(said + other.name + " " + other.path +
                         " names the same file: give each output its own");
      }
    }
  }
}

}  // namespace musclesim
