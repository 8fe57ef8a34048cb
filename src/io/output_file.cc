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

// A device or pipe (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a file
// over it would replace the device itself.
bool IsExistingNonRegular(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  return std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

}  // namespace

void WriteOutput(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content << std::flush;
    return;
  }
  if (IsExistingNonRegular(path)) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed (" + std::strerror(errno) + ")");
    return;
  }
  // the temporary name is unique per process so that parallel writers cannot collide
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
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
  std::filesystem::rename(temporary, path, error);
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
  written_path_ = IsExistingNonRegular(path_) ? path_ : path_ + ".partial";
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
  std::filesystem::rename(written_path_, path_, error);
  if (error) {
    throw std::runtime_error(path_ + ": cannot replace the file (" + error.message() + ")");
  }
}

}  // namespace musclesim
