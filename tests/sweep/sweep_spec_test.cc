// A sweep file read through its description (SweepFileBlock): each key into its member,
// defaults where absent, the base relative to the sweep file, and each rule refused with the
// file, line, column, key, value and the rule its description or its reader states.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "musclesim/io/writers/reference_table.h"
#include "musclesim/sweep/sweep_file.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

// A base scenario beside the sweep file: the shipped concentric one.
std::string WriteBase() {
  std::ifstream in(std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/concentric.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  return WriteTempFile("base.yaml", text.str());
}

// A sweep of the base with `keys` and one axis of two values.
std::string SweepText(const std::string& keys) {
  const std::string base = std::filesystem::path(WriteBase()).filename().string();
  return "base: " + base + "\n" + keys +
         "parameters:\n  model.velocity.n: [2, 3]\nmetrics: [final_length, time_to_length]\n";
}

std::string Refusal(const std::string& keys) {
  const std::string path = WriteTempFile("sweep.yaml", SweepText(keys));
  return InputErrorOf(path, [&] { LoadSweep(path, 1); });
}

TEST(SweepSpec, EachKeyIsReadIntoItsMember) {
  const std::string path = WriteTempFile(
      "sweep.yaml", SweepText("mode: random\nsamples: 3\nseed: 42\n"
                              "metric_options: {window: [0.1, 0.2], target_length: 0.095}\n"
                              "trajectories: failed\noutput: out/summary.csv\n"));
  const SweepSpec spec = LoadSweep(path, 1).spec;
  EXPECT_EQ(spec.base, (std::filesystem::path(path).parent_path() /
                        std::filesystem::path(WriteBase()).filename())
                           .lexically_normal()
                           .string());
  EXPECT_EQ(spec.mode, SweepMode::kRandom);
  EXPECT_EQ(spec.samples, 3);
  EXPECT_EQ(spec.seed, 42u);
  EXPECT_EQ(spec.metric_options.window_start, 0.1);
  EXPECT_EQ(spec.metric_options.window_end, 0.2);
  EXPECT_EQ(spec.metric_options.target_length, 0.095);
  EXPECT_EQ(spec.trajectories, TrajectoryPolicy::kFailed);
  EXPECT_EQ(spec.output, "out/summary.csv");
}

TEST(SweepSpec, AbsentKeysTakeTheirDefaults) {
  const std::string path =
      WriteTempFile("sweep.yaml", SweepText("metric_options: {target_length: 0.095}\n"));
  const SweepSpec spec = LoadSweep(path, 1).spec;
  EXPECT_EQ(spec.mode, SweepMode::kGrid);
  EXPECT_EQ(spec.trajectories, TrajectoryPolicy::kNone);
  EXPECT_FALSE(spec.metric_options.window_start);
  EXPECT_FALSE(spec.metric_options.window_end);
  EXPECT_TRUE(spec.output.empty());
  // the table states them
  const std::string table = ReferenceTable(SweepFileBlock(), "block");
  EXPECT_THAT(table, HasSubstr("| `mode` | | grid | a name: grid, zip, random |"));
  EXPECT_THAT(table, HasSubstr("| `trajectories` | | none | a name: none, all, failed |"));
  EXPECT_THAT(table, HasSubstr("| `base` | | required | any text but the empty one |"));
  EXPECT_THAT(table, HasSubstr("| `samples` | - | optional | an integer from 1 to 1e+09: "));
}

TEST(SweepSpec, EachRuleIsRefusedAtItsKey) {
  const std::string target = "metric_options: {target_length: 0.095}\n";
  struct Case {
    std::string keys;
    std::string message;
  };
  const Case cases[] = {
      {"mode: spiral\n" + target, "mode = spiral (FILE:2:7): must be one of grid, zip, random"},
      {"mode: random\nsamples: 0\nseed: 1\n" + target,
       "samples = 0 (FILE:3:10): must be an integer from 1 to 1e+09 [-]: a sweep may have"},
      {"mode: random\nsamples: 2.5\nseed: 1\n" + target,
       "samples = 2.5 (FILE:3:10): must be an integer"},
      {"mode: random\nsamples: 3\nseed: -1\n" + target,
       "seed = -1 (FILE:4:7): must be an integer from 0 to 9007199254740992 [-]: beyond 2^53"},
      {"mode: random\nseed: 1\n" + target, "samples (FILE:1:1): missing required key"},
      {"mode: random\nsamples: 3\n" + target, "seed (FILE:1:1): missing required key"},
      {"samples: 3\n" + target,
       "samples = 3 (FILE:2:10): is for mode random only (this sweep is grid)"},
      {"metric_options: {window: [0.2, 0.1], target_length: 0.095}\n",
       "metric_options.window = [0.2, 0.1] (FILE:2:26): must be [start, end] with end > start"},
      {"metric_options: {window: [0.1], target_length: 0.095}\n",
       "metric_options.window = [0.1] (FILE:2:26): must be a list of exactly 2 numbers"},
      {"metric_options: {target_length: 0}\n",
       "metric_options.target_length = 0 (FILE:2:33): must be > 0 and <= 1000 [m]"},
      {"metric_options: {target: 0.1}\n", "metric_options.target (FILE:2:18): unknown key"},
      {"", "metrics[1] = time_to_length (FILE:4:25): needs metric_options.target_length"},
      {"trajectories: some\n" + target,
       "trajectories = some (FILE:2:15): must be one of none, all, failed"},
      {"output: ''\n" + target, "output = \"\" (FILE:2:9): must not be empty"},
      {"colour: red\n" + target, "colour (FILE:2:1): unknown key; allowed here:"},
  };
  for (const Case& c : cases) EXPECT_THAT(Refusal(c.keys), HasSubstr(c.message)) << c.keys;
}

}  // namespace
}  // namespace musclesim
