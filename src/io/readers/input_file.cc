#include "musclesim/io/readers/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

namespace {

// Closes the descriptor however the read ends.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string WhatItIs(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (a named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a regular file";
}

std::string Mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

std::string ReadInputFile(const std::string& path, const std::string& kind, std::size_t max_bytes) {
  const std::string shown = PrintableText(path);
  // non-blocking: opening a FIFO for reading would otherwise wait for a writer
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    throw InputError(shown + ": cannot open the file for reading (" + std::strerror(errno) + ")");
  }
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) {
    throw InputError(shown + ": cannot be read (" + std::strerror(errno) + "); give " + kind);
  }
  if (S_ISDIR(status.st_mode)) throw InputError(shown + ": is a directory; give " + kind);
  if (!S_ISREG(status.st_mode)) {
    throw InputError(shown + ": is " + WhatItIs(status.st_mode) + ", not a regular file; give " +
                     kind);
  }
  if (static_cast<std::size_t>(status.st_size) > max_bytes) {
    throw InputError(shown + ": holds " + Mebibytes(static_cast<std::size_t>(status.st_size)) +
                     ", more than the " + Mebibytes(max_bytes) + " " + kind + " may hold");
  }
  std::string text;
  text.reserve(static_cast<std::size_t>(status.st_size));
  char block[65536];
  for (;;) {
    const ssize_t got = ::read(file.fd, block, sizeof block);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(shown + ": cannot be read (" + std::strerror(errno) + ")");
    if (got == 0) break;
    text.append(block, static_cast<std::size_t>(got));
    // a file that grows while it is read is held to the same limit
    if (text.size() > max_bytes) {
      throw InputError(shown + ": holds more than the " + Mebibytes(max_bytes) + " " + kind +
                       " may hold");
    }
  }
  return text;
}

}  // namespace musclesim
