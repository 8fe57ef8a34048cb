#include "musclesim/io/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
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

// Where a file written through a symbolic link goes: the link's target, so that the link
// stays a link (a rename onto the link's own name would replace it with the file).
std::string Destination(const std::string& path) {
  std::error_code error;
  fs::path hop = path;
  // follow the chain by hand: a link whose target does not exist yet (a dangling link) is
  // written at that target, which canonical() cannot resolve
  for (int i = 0; i < 40 && fs::is_symlink(fs::symlink_status(hop, error)); ++i) {
    const fs::path target = fs::read_symlink(hop, error);
    if (error) return path;
    hop = target.is_absolute() ? target : hop.parent_path() / target;
  }
  const fs::path resolved = fs::weakly_canonical(hop, error);
  return error ? path : resolved.string();
}

}  // namespace

void WriteOutput(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content << std::flush;
    return;
  }
  if (IsWrittenInPlace(path)) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed (" + std::strerror(errno) + ")");
    return;
  }
  const std::string destination = Destination(path);
  // the temporary name is unique per process so that parallel writers cannot collide
  const std::string temporary = destination + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    }
    out << content;
    out.flush();
    if (!out) {
      const std::string reason = std::strerror(errno);
      std::remove(temporary.c_str());
      throw std::runtime_error(path + ": write failed (" + reason + ")");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, destination, error);
  if (error) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace the file (" + error.message() + ")");
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
  file_ = std::fopen(written_path_.c_str(), "wb");
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
