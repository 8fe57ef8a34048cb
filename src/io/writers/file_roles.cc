#include "musclesim/io/writers/file_roles.h"

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/output_file.h"

namespace musclesim {

namespace {

namespace fs = std::filesystem;

bool Skipped(const std::string& path) { return path.empty() || path == "-"; }

bool IsExistingNonRegular(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  return !error && fs::exists(status) && !fs::is_regular_file(status);
}

// What makes two paths the same file: device and inode for one that exists (hard and
// symbolic links included), else the path with every link and ".." resolved; an existing
// file and one that does not exist are never the same. Empty where neither can be had.
std::string FileKey(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    return "inode " + std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
  }
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  return error ? std::string() : "path " + resolved.string();
}

std::string Partial(const std::string& path) { return path + ".partial"; }

}  // namespace

void CheckOutputFiles(const std::vector<FileRole>& inputs, const std::vector<FileRole>& outputs) {
  // each file's key found once, so that a command writing many files checks them in time
  // linear in their number
  std::vector<std::pair<std::string, const FileRole*>> input_keys;
  for (const FileRole& in : inputs) {
    if (!Skipped(in.path)) input_keys.push_back({FileKey(in.path), &in});
  }
  std::unordered_map<std::string, const FileRole*> written, partials;
  for (const FileRole& out : outputs) {
    if (Skipped(out.path)) continue;
    // told as "NAME PATH: rule", the output's name (a flag, a key) and path its fields
    const auto fail = [&out](const std::string& rule) {
      throw InputError(out.name + " " + out.path + ": ",
                       InputFault{std::nullopt, out.name, out.path, rule});
    };
    std::error_code error;
    if (fs::is_directory(out.path, error)) {
      fail("is a directory: name a file in it");
    }
    const fs::path directory = fs::path(out.path).parent_path();
    if (!directory.empty() && !fs::is_directory(directory, error)) {
      fail("the directory " + directory.string() +
           " does not exist: create it, or write elsewhere");
    }
    if (IsExistingNonRegular(out.path)) continue;
    if (const std::string outside = LinkOutsideItsDirectory(out.path); !outside.empty()) {
      fail("is a symbolic link to " + outside +
           ", outside its directory: musclesim writes no output through it (remove "
           "the link, or name another file)");
    }
    const std::string key = FileKey(out.path), partial = FileKey(Partial(out.path));
    for (const auto& [input, in] : input_keys) {
      if (input.empty()) continue;
      if (key == input) {
        fail("is " + in->name + " (" + in->path + "), an input: write the output elsewhere");
      }
      if (partial == input) {
        fail("is written through " + Partial(out.path) + ", which is " + in->name + " (" +
             in->path + "), an input: write the output elsewhere");
      }
    }
    const auto earlier = [](const std::unordered_map<std::string, const FileRole*>& files,
                            const std::string& k) -> const FileRole* {
      const auto found = files.find(k);
      return k.empty() || found == files.end() ? nullptr : found->second;
    };
    const FileRole* same = earlier(written, key);
    if (same == nullptr) same = earlier(written, partial);
    if (same == nullptr) same = earlier(partials, key);
    if (same != nullptr) {
      fail(same->name + " " + same->path + " names the same file: give each output its own");
    }
    if (!key.empty()) written.emplace(key, &out);
    if (!partial.empty()) partials.emplace(partial, &out);
  }
}

}  // namespace musclesim
