// The guard that keeps an output from overwriting an input or another output: the same file
// found through a hard link, a symbolic link, "..", or a .partial name; files that differ
// and devices let through.
#include "musclesim/io/writers/file_roles.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "musclesim/core/errors.h"
#include "support/fresh_directory.h"

namespace musclesim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string FreshDirectory() { return testing::FreshDirectory("file_roles_"); }

std::string Touch(const std::string& path) {
  std::ofstream(path) << "x\n";
  return path;
}

// The message of the InputError the guard throws, or "" when it lets the files through.
std::string Refusal(const std::vector<FileRole>& inputs, const std::vector<FileRole>& outputs) {
  try {
    CheckOutputFiles(inputs, outputs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FileRoles, RefusesAnOutputThatIsAnInputByAnyName) {
  const std::string dir = FreshDirectory();
  const std::string input = Touch(dir + "/in.yaml");
  fs::create_hard_link(input, dir + "/hard.yaml");
  fs::create_symlink(input, dir + "/soft.yaml");
  fs::create_directories(dir + "/sub");
  for (const std::string& output :
       {input, dir + "/hard.yaml", dir + "/soft.yaml", dir + "/sub/../in.yaml"}) {
    EXPECT_THAT(Refusal({{input, "the scenario"}}, {{output, "-o"}}),
                HasSubstr("-o " + output + ": is the scenario (" + input + "), an input"));
  }
}

TEST(FileRoles, RefusesAnOutputWrittenThroughAnInput) {
  const std::string dir = FreshDirectory();
  const std::string input = Touch(dir + "/out.csv.partial");
  EXPECT_THAT(Refusal({{input, "the scenario"}}, {{dir + "/out.csv", "-o"}}),
              HasSubstr("is written through " + input + ", which is the scenario"));
}

TEST(FileRoles, RefusesTwoOutputsOfOneFileExistingOrNot) {
  const std::string dir = FreshDirectory();
  const std::string later = dir + "/not_yet.csv";
  fs::create_directories(dir + "/sub");
  EXPECT_THAT(Refusal({}, {{later, "-o"}, {dir + "/sub/../not_yet.csv", "--report"}}),
              HasSubstr("-o " + later + " names the same file"));
  EXPECT_THAT(Refusal({}, {{later, "-o"}, {later + ".partial", "--report"}}),
              HasSubstr("names the same file"));
  const std::string existing = Touch(dir + "/existing.csv");
  fs::create_symlink(existing, dir + "/link.csv");
  EXPECT_THAT(Refusal({}, {{existing, "-o"}, {dir + "/link.csv", "--stats"}}),
              HasSubstr("--stats " + dir + "/link.csv: -o " + existing + " names the same file"));
}

TEST(FileRoles, RefusesADirectoryAndAMissingOne) {
  const std::string dir = FreshDirectory();
  EXPECT_THAT(Refusal({}, {{dir, "-o"}}), HasSubstr("-o " + dir + ": is a directory"));
  EXPECT_THAT(Refusal({}, {{dir + "/none/out.csv", "-o"}}),
              HasSubstr("the directory " + dir + "/none does not exist"));
}

TEST(FileRoles, LetsDistinctFilesStandardStreamsAndDevicesThrough) {
  const std::string dir = FreshDirectory();
  const std::string input = Touch(dir + "/in.yaml");
  EXPECT_EQ(Refusal({{input, "the scenario"}, {"-", "standard input"}},
                    {{dir + "/a.csv", "-o"}, {dir + "/b.json", "--stats"}, {"-", "--report"}}),
            "");
  // a device is written in place and discards; two outputs may share it
  EXPECT_EQ(Refusal({{input, "the scenario"}}, {{"/dev/null", "-o"}, {"/dev/null", "--stats"}}),
            "");
  EXPECT_EQ(Refusal({{"", "nothing"}}, {{"", "-o"}, {"", "--stats"}}), "");
}

}  // namespace
}  // namespace musclesim
