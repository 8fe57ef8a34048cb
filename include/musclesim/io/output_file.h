// Writing result files so that a failed run never destroys an earlier result: the text
// goes to a temporary file beside the target, which is renamed over it only when complete.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "musclesim/core/number_format.h"  // FormatFull, which the writers of files use

namespace musclesim {

// Writes `content` to `path` atomically; "-" writes to standard output, and an existing
// device or pipe (/dev/null, a FIFO) is written in place, never replaced. Throws
// std::runtime_error naming the path and the system's reason on failure.
void WriteOutput(const std::string& path, const std::string& content);

// A result file written while it is produced, so that a long run needs no memory for its
// text: the text goes to PATH.partial, which Commit() renames to PATH; until then PATH keeps
// what it held. "-" is standard output, and an existing device or pipe is written in place.
// If the writer is destroyed without Commit() (a failed or interrupted run), PATH.partial
// stays with everything written so far. Throws std::runtime_error naming the path and the
// system's reason when a file cannot be opened or written.
class StreamedOutput {
 public:
  explicit StreamedOutput(std::string path);
  ~StreamedOutput();
  StreamedOutput(const StreamedOutput&) = delete;
  StreamedOutput& operator=(const StreamedOutput&) = delete;

  void Write(std::string_view text);
  // Flushes, closes and moves PATH.partial to PATH.
  void Commit();
  // Where the text is until Commit(): PATH.partial, or PATH itself for "-" and devices.
  const std::string& written_path() const { return written_path_; }
  bool in_place() const { return written_path_ == path_; }
  // The file the output replaces when committed: the path, or a symbolic link's target.
  const std::string& destination() const { return destination_; }

 private:
  void Close();
  std::string path_;
  std::string written_path_;
  std::string destination_;
  std::FILE* file_ = nullptr;
  bool owns_file_ = false;  // false for standard output
};

}  // namespace musclesim
