// What `musclesim import` writes, and what it must never write: a refused import leaves no
// file anywhere, a failed one leaves every earlier file as it was, a name from the model file
// cannot write YAML into the scenario, and no output goes through a link planted in the
// output directory. The model files are written by each test; the program is the built one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_run.h"
#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

// A DeGrooteFregly2016Muscle named `name` (as the XML attribute holds it: entities allowed),
// with `extra` properties.
std::string Muscle(const std::string& name, const std::string& extra = "") {
  return "<DeGrooteFregly2016Muscle name=\"" + name +
         "\"><max_isometric_force>400</max_isometric_force>"
         "<optimal_fiber_length>0.1</optimal_fiber_length>" +
         extra + "<ignore_tendon_compliance>true</ignore_tendon_compliance>" +
         "</DeGrooteFregly2016Muscle>\n";
}

std::string Osim(const std::string& muscles) {
  return "<?xml version=\"1.0\"?>\n<OpenSimDocument Version=\"40600\"><Model name=\"m\">\n"
         "<ForceSet><objects>\n" +
         muscles + "</objects></ForceSet></Model></OpenSimDocument>\n";
}

std::vector<std::string> Listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ImportOutputs, ANameWithANewlineIsRefusedAndWritesNothing) {
  // the probe's name: a newline and a YAML key after it, which went into a header comment
  const std::string dir = testing::FreshDirectory("import_");
  const std::string model = dir + "/in/model.osim";
  fs::create_directory(dir + "/in");
  fs::create_directory(dir + "/out");
  std::ofstream(model) << Osim(Muscle("x&#10;sensitivities: [model.f_iso]"));
  const testing::CliOutcome out = testing::RunMusclesim("import " + model + " -o " + dir + "/out");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("name 'x\\x0Asensitivities: [model.f_iso]' (" + model + ":4)"));
  EXPECT_THAT(out.err, HasSubstr("holds the control character \\x0A at byte 2"));
  EXPECT_THAT(Listing(dir + "/out"), IsEmpty());
  EXPECT_THAT(Listing(dir + "/in"), ElementsAre("model.osim"));

  // MuJoCo's names likewise, a tab among them
  const std::string mjcf = dir + "/in/model.xml";
  std::ofstream(mjcf) << "<mujoco><actuator><muscle name=\"a&#9;b\" joint=\"j\" "
                         "lengthrange=\"0.1 0.2\" force=\"100\"/></actuator></mujoco>\n";
  const testing::CliOutcome tab = testing::RunMusclesim("import " + mjcf + " -o " + dir + "/out");
  EXPECT_EQ(tab.exit_code, 2) << tab.err;
  EXPECT_THAT(tab.err, HasSubstr("muscle name 'a\\x09b'"));
  EXPECT_THAT(Listing(dir + "/out"), IsEmpty());
}

TEST(ImportOutputs, AModelPathWithANewlineStaysInItsComment) {
  // the path is the user's, not the file's: written escaped on the scenario's first line
  const std::string dir = testing::FreshDirectory("import_");
  const std::string model = dir + "/odd\nname.osim";
  std::ofstream(model) << Osim(Muscle("muscle"));
  const testing::CliOutcome out = testing::RunMusclesim("import '" + model + "' -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  const std::string text = testing::ReadText(dir + "/muscle.yaml");
  EXPECT_THAT(text, HasSubstr("odd\\x0Aname.osim"));
  // and the scenario reads as one: its first line is its whole header's first comment
  EXPECT_EQ(text.find("\nname.osim"), std::string::npos);
}

TEST(ImportOutputs, ANegativeTendonSlackLengthIsRefusedAtItsLine) {
  const std::string dir = testing::FreshDirectory("import_");
  const std::string model = dir + "/model.osim";
  std::ofstream(model) << Osim(Muscle("neg", "<tendon_slack_length>-0.05</tendon_slack_length>"));
  const testing::CliOutcome out = testing::RunMusclesim("import " + model + " -o " + dir);
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("'neg' <tendon_slack_length> = -0.05 (" + model +
                                 ":4): must be "
                                 ">= 0"));
  EXPECT_THAT(Listing(dir), ElementsAre("model.osim"));
}

TEST(ImportOutputs, WhatIsNoModelFileIsRefusedAndNothingIsWritten) {
  const std::string dir = testing::FreshDirectory("import_");
  fs::create_directory(dir + "/out");
  std::ofstream(dir + "/scenario.yaml") << "name: x\n";
  std::ofstream(dir + "/other.xml") << "<other/>\n";
  std::ofstream(dir + "/empty.xml") << "<mujoco/>\n";
  ASSERT_EQ(::mkfifo((dir + "/pipe.osim").c_str(), 0600), 0);
  fs::create_directory(dir + "/folder.osim");
  const std::vector<std::string> before = Listing(dir);
  for (const std::string& input :
       {dir + "/scenario.yaml", dir + "/other.xml", dir + "/empty.xml", dir + "/pipe.osim",
        dir + "/folder.osim", std::string("/dev/zero"), dir + "/missing.osim"}) {
    // a FIFO is refused without waiting for a writer, a device without reading it
    const testing::CliOutcome out =
        testing::RunMusclesim("import " + input + " -o " + dir + "/out");
    EXPECT_EQ(out.exit_code, 2) << input << ": " << out.err;
    EXPECT_THAT(Listing(dir + "/out"), IsEmpty()) << input;
    EXPECT_EQ(Listing(dir), before) << input;
  }
  EXPECT_THAT(testing::RunMusclesim("import " + dir + "/pipe.osim").err,
              HasSubstr("is a FIFO (a named pipe), not a regular file"));
  EXPECT_THAT(testing::RunMusclesim("import /dev/zero").err,
              HasSubstr("/dev/zero: is a device, not a regular file"));
}

TEST(ImportOutputs, ALinkPlantedInTheOutputDirectoryIsRefusedAndItsTargetKept) {
  const std::string dir = testing::FreshDirectory("import_");
  fs::create_directory(dir + "/out");
  std::ofstream(dir + "/precious.txt") << "precious\n";
  fs::create_symlink("../precious.txt", dir + "/out/muscle.yaml");
  const std::string model = dir + "/model.osim";
  std::ofstream(model) << Osim(Muscle("first") + Muscle("muscle"));
  const testing::CliOutcome out = testing::RunMusclesim("import " + model + " -o " + dir + "/out");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("is a symbolic link to " + dir +
                                 "/out/../precious.txt, outside its directory"));
  EXPECT_EQ(testing::ReadText(dir + "/precious.txt"), "precious\n");
  // nothing written, the first muscle's file included
  EXPECT_THAT(Listing(dir + "/out"), ElementsAre("muscle.yaml"));
  EXPECT_TRUE(fs::is_symlink(dir + "/out/muscle.yaml"));
}

// `musclesim ARGUMENTS` allowed to write files of at most `kib` KiB: a longer write fails
// with EFBIG (the signal ignored), as on a full disk.
testing::CliOutcome RunWithFileSizeLimit(const std::string& arguments, int kib) {
  const std::string err = testing::TempPath("stderr.txt");
  const std::string command = "bash -c \"trap '' XFSZ; ulimit -f " + std::to_string(kib) +
                              "; exec " + MUSCLESIM_BINARY + " " + arguments + "\" >/dev/null 2>" +
                              err;
  const int status = std::system(command.c_str());
  return {WEXITSTATUS(status), testing::ReadText(err)};
}

TEST(ImportOutputs, AnImportThatFailsWritingLeavesTheEarlierFilesAsTheyWere) {
  // a rigid muscle (its scenario 1.2 KiB) and a compliant one (a network, 2.2 KiB)
  const std::string dir = testing::FreshDirectory("import_");
  const std::string model = dir + "/model.osim";
  const std::string compliant =
      "<tendon_slack_length>0.2</tendon_slack_length>"
      "<ignore_tendon_compliance>false</ignore_tendon_compliance>";
  std::ofstream(model) << Osim(Muscle("first") + Muscle("second"));
  ASSERT_EQ(testing::RunMusclesim("import " + model + " -o " + dir).exit_code, 0);
  const std::string first = testing::ReadText(dir + "/first.yaml");
  const std::string second = testing::ReadText(dir + "/second.yaml");
  // again, the first muscle changed and the second compliant, files limited to 2 KiB: the
  // first's new text fits, the second's does not
  std::string edited =
      Osim(Muscle("first", "<max_contraction_velocity>5</max_contraction_velocity>") +
           Muscle("second", compliant));
  const std::string rigid = "<ignore_tendon_compliance>true</ignore_tendon_compliance>";
  const std::size_t last = edited.rfind(rigid);
  edited.erase(last, rigid.size());
  std::ofstream(model) << edited;
  const testing::CliOutcome out = RunWithFileSizeLimit("import " + model + " -o " + dir, 2);
  EXPECT_EQ(out.exit_code, 1) << out.err;
  EXPECT_THAT(out.err, HasSubstr("second.yaml: write failed (File too large)"));
  EXPECT_EQ(testing::ReadText(dir + "/first.yaml"), first);
  EXPECT_EQ(testing::ReadText(dir + "/second.yaml"), second);
  EXPECT_THAT(Listing(dir), ElementsAre("first.yaml", "model.osim", "second.yaml"));
  // without the limit the same import writes both
  ASSERT_EQ(testing::RunMusclesim("import " + model + " -o " + dir).exit_code, 0);
  EXPECT_NE(testing::ReadText(dir + "/first.yaml"), first);
  EXPECT_THAT(testing::ReadText(dir + "/second.yaml"), HasSubstr("junction"));
}

TEST(ImportOutputs, ThousandsOfMusclesEachGetTheirFile) {
  // checking each output against every other was quadratic (10,000 muscles past 300 s); the
  // time is bench/import_scaling.sh's to measure, what is written this test's
  std::string muscles;
  for (int i = 0; i < 3000; ++i) muscles += Muscle(std::string("m").append(std::to_string(i)));
  const std::string dir = testing::FreshDirectory("import_");
  fs::create_directory(dir + "/out");
  std::ofstream(dir + "/many.osim") << Osim(muscles);
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + dir + "/many.osim -o " + dir + "/out");
  ASSERT_EQ(out.exit_code, 0) << out.err.substr(0, 400);
  EXPECT_EQ(Listing(dir + "/out").size(), 3000u);
  EXPECT_THAT(testing::ReadText(dir + "/out/m2999.yaml"), HasSubstr("name: \"m2999\""));
}

TEST(ImportOutputs, APathsNoteCountsItsPartsInTheirNumber) {
  const std::string dir = testing::FreshDirectory("import_");
  const std::string wrapped =
      "<GeometryPath><PathPointSet><objects><PathPoint name=\"o\"/></objects></PathPointSet>"
      "<PathWrapSet><objects><PathWrap name=\"w\"/></objects></PathWrapSet></GeometryPath>";
  std::ofstream(dir + "/model.osim") << Osim(Muscle("one", wrapped));
  const testing::CliOutcome out = testing::RunMusclesim("import " + dir + "/model.osim -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("its path (1 point, 1 wrap object) is not imported"));
}

}  // namespace
}  // namespace musclesim
