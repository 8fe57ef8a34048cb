// No verb writes through a symbolic link planted in its output directory that leads to a file
// outside it: each refuses (exit 2, naming the link and its target) before any work, and the
// file outside is left as it was. A link to a file in the same directory is still written
// through (it stays a link), as before.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_run.h"
#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Verb {
  std::string name;     // for messages
  std::string output;   // the file in out/ that a link takes the place of
  std::string command;  // after `musclesim`, run in the test's directory; {dir} is it
};

std::string Copied(const std::string& dir, const std::string& from, const std::string& name) {
  fs::copy_file(from, dir + "/" + name, fs::copy_options::overwrite_existing);
  return dir + "/" + name;
}

TEST(OutputLinks, EveryVerbRefusesALinkToAFileOutsideItsDirectory) {
  const std::string dir = testing::FreshDirectory("output_links_");
  fs::create_directory(dir + "/out");
  const std::string scenarios = std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/";
  const std::string data = std::string(MUSCLESIM_SOURCE_DIR) + "/data/";
  const std::string concentric = Copied(dir, scenarios + "concentric.yaml", "concentric.yaml");
  Copied(dir, scenarios + "isometric.yaml", "isometric.yaml");
  const std::string sweep = Copied(dir, scenarios + "stiffness_sweep.yaml", "sweep.yaml");
  const std::string fit = Copied(dir, scenarios + "fit_indicator.yaml", "fit.yaml");
  const std::string identify = Copied(dir, data + "synthetic.yaml", "synthetic.yaml");
  for (const char* csv :
       {"synthetic_passive.csv", "synthetic_active.csv", "synthetic_velocity.csv"}) {
    Copied(dir, data + csv, csv);
  }
  Copied(dir, scenarios + "antagonist_move.yaml", "antagonist_move.yaml");
  std::ofstream(dir + "/problem.yaml")
      << "base: antagonist_move.yaml\nintervals: 4\ncontrols:\n  - {actuator: flexor}\n"
         "output: {scenario: " +
             dir + "/out/o.yaml, summary: " + dir +
             "/out/o.json, "
             "trajectory: " +
             dir + "/out/o.csv}\n";
  ASSERT_EQ(testing::RunMusclesim("run " + concentric + " -o " + dir + "/run.csv").exit_code, 0);
  const std::string out = dir + "/out/";
  const std::vector<Verb> verbs = {
      {"run", "r.csv", "run " + concentric + " -o " + out + "r.csv"},
      {"run --stats", "s.json",
       "run " + concentric + " -o " + out + "r.csv --stats " + out + "s.json"},
      {"sweep", "sw.csv", "sweep " + sweep + " -o " + out + "sw.csv"},
      {"plot", "p.png", "plot " + dir + "/run.csv -o " + out + "p.png"},
      {"curves", "c.csv", "curves " + concentric + " --length 0.05:0.15:11 -o " + out + "c.csv"},
      {"identify", "m.yaml", "identify " + identify + " -o " + out + "m.yaml"},
      {"identify --report", "rep.md",
       "identify " + identify + " -o " + out + "m2.yaml --report " + out + "rep.md"},
      {"fit", "f.yaml", "fit " + fit + " -o " + out + "f.yaml"},
      {"optimize", "o.json", "optimize " + dir + "/problem.yaml --quiet"},
      {"import", "muscle.yaml", "import " + data + "opensim_hanging_mass.osim -o " + out},
  };
  for (const Verb& verb : verbs) {
    for (const auto& entry : fs::directory_iterator(dir + "/out")) fs::remove(entry.path());
    std::ofstream(dir + "/precious.txt") << "precious\n";
    fs::create_symlink("../precious.txt", out + verb.output);
    const testing::CliOutcome outcome = testing::RunMusclesim(verb.command);
    EXPECT_EQ(outcome.exit_code, 2) << verb.name << ": " << outcome.err;
    EXPECT_THAT(outcome.err, HasSubstr(out + verb.output)) << verb.name;
    EXPECT_THAT(outcome.err, HasSubstr("is a symbolic link to " + out +
                                       "../precious.txt, outside its directory"))
        << verb.name;
    EXPECT_EQ(testing::ReadText(dir + "/precious.txt"), "precious\n") << verb.name;
    EXPECT_TRUE(fs::is_symlink(out + verb.output)) << verb.name;
  }
}

TEST(OutputLinks, ALinkWithinItsDirectoryIsWrittenThroughAndStaysALink) {
  const std::string dir = testing::FreshDirectory("output_links_");
  fs::create_symlink("target.csv", dir + "/link.csv");
  const testing::CliOutcome outcome = testing::RunMusclesim(
      "run " + testing::ScenarioPath("concentric.yaml") + " -o " + dir + "/link.csv");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_THAT(testing::ReadText(dir + "/target.csv"), HasSubstr("t,length"));
}

}  // namespace
}  // namespace musclesim
