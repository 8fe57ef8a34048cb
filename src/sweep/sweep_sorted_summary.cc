#include "sweep/sweep_sorted_summary.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

#include "musclesim/io/writers/output_file.h"

namespace musclesim {

namespace {

using Row = std::pair<long, std::string>;  // index, the row as written

long IndexOf(const std::string& line) { return std::strtol(line.c_str(), nullptr, 10); }

std::runtime_error IoError(const std::string& path, const char* what) {
  return std::runtime_error(path + ": " + what + " (" + std::strerror(errno) + ")");
}

// Temporary files removed however the merge ends.
struct TemporaryFiles {
  std::vector<std::string> paths;
  ~TemporaryFiles() {
    for (const std::string& p : paths) std::remove(p.c_str());
  }
};

// The merged summary on its way to `path`: a temporary file renamed over it by Commit (as
// WriteOutput does, but streamed), or standard output and devices written in place.
class MergedOutput {
 public:
  explicit MergedOutput(const std::string& path) : path_(path) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    const bool in_place = path == "-" || (std::filesystem::exists(status) &&
                                          !std::filesystem::is_regular_file(status));
    if (path == "-") {
      file_ = stdout;
      return;
    }
    written_ = in_place ? path : path + ".tmp." + std::to_string(::getpid());
    file_ = in_place ? std::fopen(written_.c_str(), "wb") : CreateFreshFile(written_);
    if (file_ == nullptr) throw IoError(path, "cannot write");
    owned_ = true;
  }
  ~MergedOutput() {
    if (owned_ && file_ != nullptr) std::fclose(file_);
    if (!committed_ && written_ != path_ && !written_.empty()) std::remove(written_.c_str());
  }
  void Write(const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
      throw IoError(path_, "write failed");
    }
  }
  void Commit() {
    const bool flushed = std::fflush(file_) == 0;
    if (owned_) {
      const bool closed = std::fclose(file_) == 0;
      file_ = nullptr;
      if (!flushed || !closed) throw IoError(path_, "write failed");
    } else if (!flushed) {
      throw IoError(path_, "write failed");
    }
    if (written_ != path_ && !written_.empty() &&
        std::rename(written_.c_str(), path_.c_str()) != 0) {
      throw IoError(path_, "cannot replace the file");
    }
    committed_ = true;
  }

 private:
  std::string path_, written_;
  std::FILE* file_ = nullptr;
  bool owned_ = false, committed_ = false;
};

}  // namespace

void WriteSortedSummary(const std::string& partial, int skip, const std::string& header,
                        const std::string& path, std::size_t budget_bytes) {
  std::ifstream in(partial, std::ios::binary);
  if (!in) throw IoError(partial, "cannot read");
  std::string line;
  for (int i = 0; i < skip; ++i) std::getline(in, line);

  // rows sorted in memory; each time they exceed the budget, as a run on disk
  std::vector<Row> rows;
  std::size_t bytes = 0;
  TemporaryFiles runs;
  const auto spill = [&] {
    std::sort(rows.begin(), rows.end());
    runs.paths.push_back(partial + ".sort" + std::to_string(runs.paths.size()));
    std::ofstream run(runs.paths.back(), std::ios::binary | std::ios::trunc);
    for (const Row& row : rows) run << row.second << '\n';
    run.flush();
    if (!run) throw IoError(runs.paths.back(), "write failed");
    rows.clear();
    bytes = 0;
  };
  while (std::getline(in, line)) {
    bytes += line.size() + sizeof(Row) + 32;  // the text, the pair, the heap block's overhead
    rows.emplace_back(IndexOf(line), std::move(line));
    if (bytes > budget_bytes) spill();
  }
  if (in.bad()) throw IoError(partial, "read failed");

  if (runs.paths.empty()) {
    std::sort(rows.begin(), rows.end());
    std::string text = header + "\n";
    for (const Row& row : rows) text.append(row.second).push_back('\n');
    WriteOutput(path, text);
    return;
  }
  if (!rows.empty()) spill();

  // merge the runs: the smallest index at the head of any run comes next
  std::vector<std::ifstream> streams;
  for (const std::string& run : runs.paths) streams.emplace_back(run, std::ios::binary);
  using Head = std::pair<Row, std::size_t>;  // a run's next row, the run
  std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heads;
  const auto advance = [&](std::size_t r) {
    std::string next;
    if (std::getline(streams[r], next)) heads.push({{IndexOf(next), std::move(next)}, r});
  };
  for (std::size_t r = 0; r < streams.size(); ++r) advance(r);
  MergedOutput out(path);
  out.Write(header + "\n");
  while (!heads.empty()) {
    const std::size_t r = heads.top().second;
    out.Write(heads.top().first.second + "\n");
    heads.pop();
    advance(r);
  }
  out.Commit();
}

}  // namespace musclesim
