#include "sweep/sweep_summary.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "musclesim/core/errors.h"
#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_share.h"
#include "sweep/sweep_signature.h"
#include "sweep/sweep_sorted_summary.h"

namespace musclesim {

namespace {

constexpr const char* kDifferentSweep =
    " belongs to a different sweep (base scenario, axes or metrics changed): ";

std::runtime_error IoError(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what + " (" + std::strerror(errno) + ")");
}

// Opens `path` (creating it if absent) and takes its lock without waiting. Another process
// holding the lock is a running sweep (the kernel drops the lock of a process that died).
int OpenLocked(const std::string& path) {
  for (;;) {
    int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0 && errno == ENOENT) {
      fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
      if (fd < 0 && errno == EEXIST) continue;  // another sweep created it just now
    }
    if (fd < 0) throw IoError(path, "cannot open");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK) {
        throw InputError(path +
                         " is in use by a running sweep writing the same output (it "
                         "holds the file's lock); wait for it to end, stop it, or write this "
                         "sweep's summary to another file");
      }
      errno = error;
      throw IoError(path, "cannot lock");
    }
    // a sweep that finished may have removed the file between our open and our lock: then
    // the lock is on a file no longer there, and the path must be opened again
    struct stat opened {
    }, named{};
    if (::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 &&
        opened.st_dev == named.st_dev && opened.st_ino == named.st_ino) {
      return fd;
    }
    ::close(fd);
  }
}

}  // namespace

SummaryFile::SummaryFile(const SweepSpec& spec, std::string path, bool resume)
    : path_(std::move(path)),
      partial_path_(path_ + ".partial"),
      header_(SummaryHeader(spec)),
      points_(PointCount(spec)),
      done_(static_cast<std::size_t>(points_), false) {
  fd_ = OpenLocked(partial_path_);
  try {
    struct stat status {};
    if (::fstat(fd_, &status) != 0) throw IoError(partial_path_, "cannot read");
    const std::string signature = SweepSignature::Of(spec).Line();
    if (status.st_size == 0) {
      // new, or left empty by a sweep killed as it started
      Append(signature + "\n" + header_ + "\n");
    } else if (!resume) {
      throw InterruptedSweepError(partial_path_);
    } else {
      Resume(spec, signature);
    }
  } catch (...) {
    ::close(fd_);
    throw;
  }
  resumed_ = count_;
  unhanded_ = points_ - count_;
  if (spec.kept && spec.share_ranks > 1) {
    share_block_ = spec.share_block;
    share_ranks_ = spec.share_ranks;
    share_next_.resize(static_cast<std::size_t>(share_ranks_));
    share_left_.assign(static_cast<std::size_t>(share_ranks_), 0);
    for (int r = 0; r < share_ranks_; ++r)
      share_next_[static_cast<std::size_t>(r)] = r * share_block_;
    for (long i = 0; i < points_; ++i) {
      if (!done_[static_cast<std::size_t>(i)])
        ++share_left_[static_cast<std::size_t>(PointOwner(spec, i))];
    }
  }
}

SummaryFile::~SummaryFile() {
  if (fd_ < 0) return;
  try {
    Flush();  // leaving early (an error): keep the rows that did finish
  } catch (const std::exception&) {
    // the error on its way out says what went wrong
  }
  ::close(fd_);
}

void SummaryFile::Resume(const SweepSpec& spec, const std::string& signature) {
  std::ifstream in(partial_path_, std::ios::binary);
  std::string line;
  std::getline(in, line);
  const std::optional<SweepSignature> found = SweepSignature::Parse(line);
  if (!found) {
    throw InputError(partial_path_ + kDifferentSweep +
                     "its first line is not a sweep's signature (# sweep base=...), so it was "
                     "not written by this version of musclesim sweep; delete it to start again");
  }
  const std::string changed = found->Differences(*SweepSignature::Parse(signature));
  if (!changed.empty()) {
    throw InputError(partial_path_ + kDifferentSweep + changed +
                     " changed since it was written. Delete it to start again, or write this "
                     "sweep's summary to another file");
  }
  const off_t rows_start = static_cast<off_t>(signature.size() + 1 + header_.size() + 1);
  if (!std::getline(in, line) || line != header_) {
    throw InputError(partial_path_ + kDifferentSweep + "its header is not this sweep's (" +
                     header_ + ")");
  }
  if (in.eof()) {  // the header was cut short (a sweep killed as it started)
    if (::ftruncate(fd_, rows_start - 1) != 0) throw IoError(partial_path_, "cannot truncate");
    ::lseek(fd_, 0, SEEK_END);
    Append("\n");
    return;
  }

  // keep the rows that pass the checks, moving them up over the dropped ones; a last line
  // without its newline (cut short by a kill) is dropped silently, as expected
  off_t read_at = rows_start, write_at = rows_start;
  long line_number = 2, dropped = 0;
  for (; std::getline(in, line); ++line_number) {
    if (in.eof()) break;
    const off_t length = static_cast<off_t>(line.size() + 1);
    CheckedRow row = CheckRow(spec, points_, line);
    if (row.problem.empty() && done_[static_cast<std::size_t>(row.index)]) {
      row.problem = "a second row for point " + std::to_string(row.index);
    }
    if (!row.problem.empty()) {
      if (++dropped <= 5) {
        dropped_ += (dropped > 1 ? "; " : "") + std::string("line ") +
                    std::to_string(line_number + 1) + ": " + row.problem;
      }
      read_at += length;
      continue;
    }
    if (write_at != read_at) {
      const std::string text = line + "\n";
      if (::pwrite(fd_, text.data(), text.size(), write_at) != static_cast<ssize_t>(text.size())) {
        throw IoError(partial_path_, "write failed");
      }
    }
    read_at += length;
    write_at += length;
    done_[static_cast<std::size_t>(row.index)] = true;
    ++count_;
    failed_ += row.status == RowStatus::kFailed;
    invalid_ += row.status == RowStatus::kInvalid;
  }
  if (in.bad()) throw IoError(partial_path_, "read failed");
  if (::ftruncate(fd_, write_at) != 0) throw IoError(partial_path_, "cannot truncate");
  if (::lseek(fd_, 0, SEEK_END) < 0) throw IoError(partial_path_, "cannot seek");
  if (dropped > 0) {
    dropped_ = partial_path_ + ": dropped " + std::to_string(dropped) + " malformed row" +
               (dropped > 1 ? "s" : "") + " (" + dropped_ + (dropped > 5 ? "; ..." : "") +
               "); their points run again";
  }
}

void SummaryFile::Append(const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw IoError(partial_path_, "write failed");
    written += static_cast<std::size_t>(n);
  }
}

std::vector<long> SummaryFile::Hand(long max, int owner) {
  std::vector<long> indices;
  if (share_ranks_ == 1) {
    for (; next_ < points_ && static_cast<long>(indices.size()) < max; ++next_) {
      if (!done_[static_cast<std::size_t>(next_)]) indices.push_back(next_);
    }
    unhanded_ -= static_cast<long>(indices.size());
    return indices;
  }
  auto from = static_cast<std::size_t>(owner % share_ranks_);
  while (static_cast<long>(indices.size()) < max && unhanded_ > 0) {
    if (share_left_[from] == 0) {
      from = static_cast<std::size_t>(std::max_element(share_left_.begin(), share_left_.end()) -
                                      share_left_.begin());
      if (share_left_[from] == 0) break;
    }
    // the next point of `from`'s blocks: block b holds [b * block, (b + 1) * block)
    long& i = share_next_[from];
    for (; i < points_ && share_left_[from] > 0 && static_cast<long>(indices.size()) < max;) {
      if (!done_[static_cast<std::size_t>(i)]) {
        indices.push_back(i);
        --share_left_[from];
        --unhanded_;
      }
      ++i;
      if (i % share_block_ == 0) i += (share_ranks_ - 1) * share_block_;
    }
    if (i >= points_) share_left_[from] = 0;  // (never fewer than counted: a guard)
  }
  return indices;
}

void SummaryFile::Add(long index, const std::string& row, RowStatus status) {
  if (index < 0 || index >= points_ || done_[static_cast<std::size_t>(index)]) return;
  pending_.append(row).append("\n");
  done_[static_cast<std::size_t>(index)] = true;
  ++count_;
  failed_ += status == RowStatus::kFailed;
  invalid_ += status == RowStatus::kInvalid;
}

void SummaryFile::Flush() {
  if (pending_.empty()) return;
  Append(pending_);
  pending_.clear();
}

SweepOutcome SummaryFile::Close() {
  Flush();
  SweepOutcome outcome;
  outcome.points = points_;
  outcome.resumed = resumed_;
  outcome.ran = count_ - resumed_;
  outcome.failed = failed_;
  outcome.invalid = invalid_;
  outcome.interrupted = count_ < points_;
  if (!outcome.interrupted) {
    WriteSortedSummary(partial_path_, 2, header_, path_);
    ::unlink(partial_path_.c_str());
  }
  ::close(fd_);  // releases the lock
  fd_ = -1;
  return outcome;
}

}  // namespace musclesim
