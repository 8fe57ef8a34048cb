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

void WriteOutput(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content << std::flush;
    return;
  }
  // a device or pipe (/dev/null, /dev/stdout, a FIFO) is written in place: renaming a file
  // over it would replace the device itself
  std::error_code status_error;
  const auto status = std::filesystem::status(path, status_error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
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

}  // namespace musclesim
