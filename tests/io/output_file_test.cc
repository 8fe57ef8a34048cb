#include "musclesim/io/writers/output_file.h"
#include "support/fresh_directory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace musclesim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string FreshDirectory() { return testing::FreshDirectory("output_file_"); }

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> Listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

std::string Big(std::size_t bytes) {
  std::string text;
  while (text.size() < bytes) text += "0.12345678901234567,0.5,isometric\n";
  return text;
}

TEST(OutputFile, WritesANewFileAndReplacesAnOldOneLeavingNothingElse) {
  const std::string dir = FreshDirectory(), path = dir + "/out.csv";
  WriteOutput(path, "first\n");
  EXPECT_EQ(ReadFile(path), "first\n");
  WriteOutput(path, "second, longer\n");
  EXPECT_EQ(ReadFile(path), "second, longer\n");
  WriteOutput(path, "");
  EXPECT_EQ(ReadFile(path), "");
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("out.csv"));
}

TEST(OutputFile, ATemporaryThatCannotBeCreatedLeavesTheOldFile) {
  const std::string dir = FreshDirectory(), path = dir + "/out.csv";
  WriteOutput(path, "old result\n");
  // the temporary's name is taken by a directory: opening it for writing fails
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  fs::create_directory(temporary);
  EXPECT_THAT([&] { WriteOutput(path, "new result\n"); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr(path + ": cannot write")));
  EXPECT_EQ(ReadFile(path), "old result\n");
}

// Limits the size of files this process writes, and restores the limit when it goes.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    // beyond the limit write() fails with EFBIG instead of raising SIGXFSZ
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

TEST(OutputFile, AWriteThatFailsHalfWayLeavesTheOldFileAndNoTemporary) {
  const std::string dir = FreshDirectory(), path = dir + "/out.csv";
  WriteOutput(path, "old result\n");
  {
    const FileSizeLimit limit(4096);  // the new text is 1 MB: the disk is "full" at 4 KiB
    EXPECT_THAT([&] { WriteOutput(path, Big(1 << 20)); },
                ::testing::ThrowsMessage<std::runtime_error>(HasSubstr(path + ": write failed")));
  }
  EXPECT_EQ(ReadFile(path), "old result\n");
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("out.csv"));
}

TEST(OutputFile, AMissingDirectoryIsAnErrorNamingThePath) {
  const std::string path = FreshDirectory() + "/no/such/dir/out.csv";
  EXPECT_THAT([&] { WriteOutput(path, "x"); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr(path + ": cannot write")));
  EXPECT_THAT([&] { StreamedOutput output(path); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr(path + ": cannot write")));
}

// A FIFO stands for every device or pipe: renaming a file over it would replace it. (A
// FIFO rather than /dev/null, so that a broken writer cannot replace a system device.) Its
// read end is opened first without blocking, so that a writer's open returns at once and a
// writer that never opens it leaves the test nothing to read rather than hanging; texts stay
// below the pipe's 64 KiB buffer, so nothing needs reading while they are written.
class Fifo {
 public:
  explicit Fifo(const std::string& dir) : path_(dir + "/pipe") {
    EXPECT_EQ(::mkfifo(path_.c_str(), 0600), 0);
    fd_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK);
    EXPECT_GE(fd_, 0);
  }
  ~Fifo() { ::close(fd_); }
  const std::string& path() const { return path_; }
  // Everything written to the FIFO so far.
  std::string Drain() {
    std::string text;
    char block[4096];
    for (ssize_t n; (n = ::read(fd_, block, sizeof block)) > 0;) text.append(block, n);
    return text;
  }

 private:
  std::string path_;
  int fd_ = -1;
};

TEST(OutputFile, DevicesAndPipesAreWrittenInPlace) {
  const std::string dir = FreshDirectory();
  Fifo fifo(dir);
  const std::string text = Big(16384);
  WriteOutput(fifo.path(), text);
  EXPECT_EQ(fifo.Drain(), text);
  EXPECT_TRUE(fs::is_fifo(fifo.path()));
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("pipe"));
}

TEST(OutputFile, StreamedOutputToAPipeIsInPlace) {
  const std::string dir = FreshDirectory();
  Fifo fifo(dir);
  {
    StreamedOutput output(fifo.path());
    EXPECT_TRUE(output.in_place());
    EXPECT_EQ(output.written_path(), fifo.path());
    output.Write("a,b\n");
    output.Write("1,2\n");
    output.Commit();
  }
  EXPECT_EQ(fifo.Drain(), "a,b\n1,2\n");
  EXPECT_TRUE(fs::is_fifo(fifo.path()));
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("pipe"));
}

TEST(OutputFile, DashIsStandardOutput) {
  ::testing::internal::CaptureStdout();
  WriteOutput("-", "whole\n");
  {
    StreamedOutput output("-");
    EXPECT_TRUE(output.in_place());
    output.Write("streamed\n");
    output.Commit();
  }
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "whole\nstreamed\n");
}

TEST(OutputFile, StreamedOutputIsPartialUntilCommitAndThePathKeepsItsOldText) {
  const std::string dir = FreshDirectory(), path = dir + "/run.csv";
  WriteOutput(path, "previous run\n");
  const std::string text = Big(300000);
  {
    StreamedOutput output(path);
    EXPECT_FALSE(output.in_place());
    EXPECT_EQ(output.written_path(), path + ".partial");
    output.Write(text.substr(0, 100000));
    output.Write(text.substr(100000));
    // before Commit: the text is in PATH.partial (at least what stdio has flushed), and
    // PATH is untouched
    EXPECT_TRUE(fs::exists(path + ".partial"));
    EXPECT_EQ(ReadFile(path), "previous run\n");
    output.Commit();
    EXPECT_THROW(output.Write("more"), std::logic_error);
  }
  EXPECT_EQ(ReadFile(path), text);
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("run.csv"));
}

TEST(OutputFile, StreamedOutputWithoutCommitKeepsEverythingInThePartialFile) {
  const std::string dir = FreshDirectory(), path = dir + "/run.csv";
  WriteOutput(path, "previous run\n");
  {
    StreamedOutput output(path);
    output.Write("t,length\n");
    output.Write("0,0.1\n");
  }  // a failed or interrupted run: destroyed without Commit
  EXPECT_EQ(ReadFile(path), "previous run\n");
  EXPECT_EQ(ReadFile(path + ".partial"), "t,length\n0,0.1\n");
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("run.csv", "run.csv.partial"));
}

TEST(OutputFile, StreamedOutputReplacesAStalePartialFile) {
  const std::string dir = FreshDirectory(), path = dir + "/run.csv";
  WriteOutput(path + ".partial", "rows of an earlier, failed run\n");
  {
    StreamedOutput output(path);
    output.Write("new\n");
    output.Commit();
  }
  EXPECT_EQ(ReadFile(path), "new\n");
  EXPECT_THAT(Listing(dir), ::testing::ElementsAre("run.csv"));
}

}  // namespace
}  // namespace musclesim

namespace musclesim {
namespace {

// A symbolic link named as the output is written through: its target gets the text and the
// link stays a link (a rename onto the link's name would have replaced it, leaving the
// target as it was).
TEST(OutputFileLinks, AnOutputNamedByASymbolicLinkWritesItsTarget) {
  const std::string dir = FreshDirectory();
  std::ofstream(dir + "/target.json") << "old\n";
  fs::create_symlink("target.json", dir + "/link.json");
  WriteOutput(dir + "/link.json", "written\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.json"));
  EXPECT_EQ(ReadFile(dir + "/target.json"), "written\n");

  fs::create_symlink("streamed.csv", dir + "/streamed_link.csv");  // a dangling link
  StreamedOutput streamed(dir + "/streamed_link.csv");
  streamed.Write("rows\n");
  streamed.Commit();
  EXPECT_TRUE(fs::is_symlink(dir + "/streamed_link.csv"));
  EXPECT_EQ(ReadFile(dir + "/streamed.csv"), "rows\n");
  EXPECT_FALSE(fs::exists(dir + "/streamed.csv.partial"));
}

// /dev/stdout is a link into /proc: written in place, never replaced by a file of its own.
TEST(OutputFileLinks, ALinkIntoProcIsWrittenInPlace) {
  const std::string dir = FreshDirectory();
  fs::create_symlink("/proc/self/fd/1", dir + "/stdout_link");
  StreamedOutput streamed(dir + "/stdout_link");
  EXPECT_TRUE(streamed.in_place());
  streamed.Commit();
  EXPECT_TRUE(fs::is_symlink(dir + "/stdout_link"));
}

}  // namespace
}  // namespace musclesim
