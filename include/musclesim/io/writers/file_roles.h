// One guard for every command and Python function that writes files: no output may be an
// input, another output, or the temporary (.partial) name of either, so that a run never
// destroys what it reads or what it has just written; and an output that cannot be a file
// there is refused as bad input before the work, not as a failed write after it.
#pragma once

#include <string>
#include <vector>

namespace musclesim {

// A file a command reads or writes, and the words a message names it by ("-o", "the data
// file"). An empty path or "-" (standard input or output) takes part in no comparison.
struct FileRole {
  std::string path;
  std::string name;
};

// Throws InputError, before anything is written, when an output is a directory or lies in a
// directory that does not exist, when it is the same file as an input or as another output,
// or when the .partial name an output is written through is one of them. Files are the same when
// they share device and inode (hard and symbolic links included), or, where one does not exist yet,
// when their resolved paths are equal. An existing output that is not a regular file (/dev/null, a
// pipe) is written in place and is never an input's copy, so it is left out.
void CheckOutputFiles(const std::vector<FileRole>& inputs, const std::vector<FileRole>& outputs);

}  // namespace musclesim
