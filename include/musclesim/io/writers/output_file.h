// Writing result files so that a failed run never destroys an earlier result: the text
// goes to a temporary file beside the target, which is renamed over it only when complete.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/core/number_format.h"  // FormatFull, which the writers of files use

namespace musclesim {

// Writes `content` to `path` atomically; "-" writes to standard output, and an existing
// device or pipe (/dev/null, a FIFO) is written in place, never replaced. A symbolic link at
// `path` is written through (it stays a link) only when its target lies in the link's own
// directory; a link to a file elsewhere is refused, and the temporary file is created anew,
// never through a link planted at its name. Throws std::runtime_error naming the path and
// the system's reason on failure.
void WriteOutput(const std::string& path, const std::string& content);

// One file's text, for WriteOutputs.
struct OutputText {
  std::string path;
  std::string text;
};

// Writes every file as WriteOutput does, all or none: each text goes to its temporary file
// first, and only when all are written are they renamed into place. A failure (a name too
// long, a full disk) removes the temporaries and leaves every file as it was.
void WriteOutputs(const std::vector<OutputText>& files);

// A new file at `name` opened for writing ("wb"), never through a link: a link or a regular
// file already there is removed first. nullptr (errno set) when it cannot be created.
std::FILE* CreateFreshFile(const std::string& name);

// The target of a symbolic link at `path` when it lies outside the link's own directory
// (the link chain followed to its end), which no output is written through; "" when `path`
// is no link, leads into its own directory, or is written in place (a device, /dev/stdout).
std::string LinkOutsideItsDirectory(const std::string& path);

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
