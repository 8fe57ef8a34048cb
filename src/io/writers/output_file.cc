#include "musclesim/io/writers/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>
#include <vector>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace musclesim {

namespace {

namespace fs = std::filesystem;

bool UnderDevOrProc(const fs::path& path) {
  const std::string text = path.lexically_normal().string();
  return text.rfind("/dev/", 0) == 0 || text.rfind("/proc/", 0) == 0;
}

// A device or pipe (/dev/null, /dev/stdout, a FIFO), or a file reached through /dev or
// /proc (/dev/stdout -> /proc/self/fd/1 -> the file the shell redirected to), is written in
// place: renaming a file over it would replace the device or the link itself, or leave the
// shell's open file behind.
bool IsWrittenInPlace(const std::string& path) {
  std::error_code error;
  const auto status = fs::status(path, error);
  if (fs::exists(status) && !fs::is_regular_file(status)) return true;
  fs::path hop = fs::absolute(path, error);
  for (int i = 0; i < 40 && !error; ++i) {
    if (UnderDevOrProc(hop)) return true;
    if (!fs::is_symlink(fs::symlink_status(hop, error))) break;
    const fs::path target = fs::read_symlink(hop, error);
    hop = target.is_absolute() ? target : hop.parent_path() / target;
  }
  return false;
}

// The file a symbolic link at `path` leads to, every link of the chain followed by hand (a
// link whose target does not exist yet, a dangling link, leads to that target, which
// canonical() cannot resolve); `path` itself when it is no link.
fs::path FinalTarget(const std::string& path) {
  std::error_code error;
  fs::path hop = path;
  for (int i = 0; i < 40 && fs::is_symlink(fs::symlink_status(hop, error)); ++i) {
    const fs::path target = fs::read_symlink(hop, error);
    if (error) return path;
    hop = target.is_absolute() ? target : hop.parent_path() / target;
  }
  return hop;
}

fs::path DirectoryOf(const fs::path& file) {
  std::error_code error;
  const fs::path parent = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const fs::path resolved = fs::weakly_canonical(parent, error);
  return error ? parent.lexically_normal() : resolved;
}

// Where the text for `path` goes: a symbolic link's target when it lies in the link's own
// directory, so that the link stays a link (a rename onto the link's name would replace it
// with the file); a link to a file anywhere else is refused.
std::string Destination(const std::string& path) {
  if (const std::string outside = LinkOutsideItsDirectory(path); !outside.empty()) {
    throw std::runtime_error(path + ": is a symbolic link to " + outside +
                             ", outside its directory: musclesim does not write through it");
  }
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(FinalTarget(path), error);
  return error ? path : resolved.string();
}

// Creates `name` for writing, never through a link: a link or a regular file already there
// under this process's temporary name (left by a crash) is removed first, anything else
// (a directory) is an error.
int CreateFresh(const std::string& name) {
  constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  int fd = ::open(name.c_str(), kFlags, 0666);
  struct stat status {};
  if (fd < 0 && errno == EEXIST && ::lstat(name.c_str(), &status) == 0 &&
      (S_ISLNK(status.st_mode) || S_ISREG(status.st_mode)) && ::unlink(name.c_str()) == 0) {
    fd = ::open(name.c_str(), kFlags, 0666);
  }
  return fd;
}

// Writes all of `text` to `fd`; false with errno set on failure.
bool WriteAll(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t wrote = ::write(fd, text.data(), text.size());
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return false;
    text.remove_prefix(static_cast<std::size_t>(wrote));
  }
  return true;
}

// One output on its way: its text in a temporary file beside its destination.
struct Staged {
  std::string path, destination, temporary;
  bool in_place = false;
};

void RemoveTemporaries(const std::vector<Staged>& staged) {
  for (const Staged& s : staged) {
    if (!s.temporary.empty()) std::remove(s.temporary.c_str());
  }
}

// Writes `file`'s text where it will be renamed from (or in place); throws
// std::runtime_error naming its path.
Staged Stage(const OutputText& file) {
  Staged s{file.path, "", "", IsWrittenInPlace(file.path)};
  if (s.in_place) {
    std::ofstream out(file.path, std::ios::binary);
    out << file.text;
    out.flush();
    if (!out) throw std::runtime_error(file.path + ": write failed (" + std::strerror(errno) + ")");
    return s;
  }
  s.destination = Destination(file.path);
  // the temporary name is unique per process so that parallel writers cannot collide
  const std::string temporary = s.destination + ".tmp." + std::to_string(::getpid());
  const int fd = CreateFresh(temporary);
  if (fd < 0) {
    throw std::runtime_error(file.path + ": cannot write (" + std::strerror(errno) + ")");
  }
  const bool written = WriteAll(fd, file.text);
  const int saved = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    std::remove(temporary.c_str());
    throw std::runtime_error(file.path + ": write failed (" +
                             std::strerror(written ? errno : saved) + ")");
  }
  s.temporary = temporary;
  return s;
}

}  // namespace

std::string LinkOutsideItsDirectory(const std::string& path) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(path, error)) || IsWrittenInPlace(path)) return "";
  const fs::path target = FinalTarget(path);
  return DirectoryOf(target) == DirectoryOf(path) ? "" : target.string();
}

std::FILE* CreateFreshFile(const std::string& name) {
  const int fd = CreateFresh(name);
  if (fd < 0) return nullptr;
  std::FILE* file = ::fdopen(fd, "wb");
  if (file == nullptr) ::close(fd);
  return file;
}

void WriteOutput(const std::string& path, const std::string& content) {
  WriteOutputs({{path, content}});
}

void WriteOutputs(const std::vector<OutputText>& files) {
  // every file's text first, beside its destination; only when all are written are they
  // renamed into place, so that a failure leaves every earlier result as it was
  std::vector<Staged> staged;
  try {
    for (const OutputText& file : files) {
      if (file.path == "-") continue;
      staged.push_back(Stage(file));
    }
  } catch (...) {
    RemoveTemporaries(staged);
    throw;
  }
  for (std::size_t i = 0; i < staged.size(); ++i) {
    const Staged& s = staged[i];
    if (s.in_place) continue;
    std::error_code error;
    fs::rename(s.temporary, s.destination, error);
    if (error) {
      RemoveTemporaries({staged.begin() + static_cast<long>(i), staged.end()});
      throw std::runtime_error(s.path + ": cannot replace the file (" + error.message() + ")");
    }
  }
  for (const OutputText& file : files) {
    if (file.path == "-") std::cout << file.text << std::flush;
  }
}

StreamedOutput::StreamedOutput(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    written_path_ = path_;
    file_ = stdout;
    return;
  }
  const bool in_place = IsWrittenInPlace(path_);
  destination_ = in_place ? path_ : Destination(path_);
  written_path_ = in_place ? path_ : destination_ + ".partial";
  if (in_place) {
    file_ = std::fopen(written_path_.c_str(), "wb");
  } else {
    // never through a link planted at the partial name; a stale partial file is replaced
    file_ = CreateFreshFile(written_path_);
  }
  if (file_ == nullptr) {
    throw std::runtime_error(path_ + ": cannot write " + written_path_ + " (" +
                             std::strerror(errno) + ")");
  }
  owns_file_ = true;
}

StreamedOutput::~StreamedOutput() {
  if (file_ != nullptr) {
    std::fflush(file_);
    if (owns_file_) std::fclose(file_);
  }
}

void StreamedOutput::Write(std::string_view text) {
  if (file_ == nullptr) throw std::logic_error(path_ + ": written after Commit");
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    throw std::runtime_error(written_path_ + ": write failed (" + std::strerror(errno) + ")");
  }
}

void StreamedOutput::Close() {
  const bool flushed = std::fflush(file_) == 0;
  const int saved = errno;
  const bool closed = !owns_file_ || std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    throw std::runtime_error(written_path_ + ": write failed (" +
                             std::strerror(flushed ? errno : saved) + ")");
  }
}

void StreamedOutput::Commit() {
  Close();
  if (in_place()) return;
  std::error_code error;
  std::filesystem::rename(written_path_, destination_, error);
  if (error) {
    throw std::runtime_error(path_ + ": cannot replace the file (" + error.message() + ")");
  }
}

}  // namespace musclesim
