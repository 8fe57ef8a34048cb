// The data file of `musclesim identify` read through its blocks' descriptions: each key into its
// member, defaults where absent, paths relative to the file, and each rule refused with the
// file, line, column, key, value and the rule of the key's description.
#include "musclesim/io/readers/identify_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "musclesim/io/writers/reference_table.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

// The message of reading a data file of `text`, its path shown as FILE.
std::string Refusal(const std::string& text) {
  const std::string path = WriteTempFile("data.yaml", text);
  return InputErrorOf(path, [&] { LoadIdentifySpec(path); });
}

TEST(IdentifySpec, EachBlocksKeysAreReadIntoTheirMembers) {
  const std::string path = WriteTempFile("data.yaml",
                                         "passive: {csv: p.csv}\n"
                                         "active: {csv: sub/a.csv, count: 5, nonnegative: true}\n"
                                         "velocity: {csv: ../v.csv, f_iso: 120}\n");
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  const IdentifySpec spec = LoadIdentifySpec(path);
  EXPECT_EQ(spec.source, path);
  EXPECT_EQ(*spec.passive_csv, (dir / "p.csv").lexically_normal().string());
  EXPECT_EQ(*spec.active_csv, (dir / "sub/a.csv").lexically_normal().string());
  EXPECT_EQ(*spec.velocity_csv, (dir / "../v.csv").lexically_normal().string());
  EXPECT_EQ(spec.active_count, 5);
  EXPECT_TRUE(spec.active_nonnegative);
  ASSERT_TRUE(spec.velocity_f_iso);
  EXPECT_EQ(*spec.velocity_f_iso, 120.0);
  // where each CSV is named: its value's line and column
  EXPECT_EQ(PlaceText(spec.passive_csv_at), path + ":1:16");
  EXPECT_EQ(PlaceText(spec.active_csv_at), path + ":2:15");
  EXPECT_EQ(PlaceText(spec.velocity_csv_at), path + ":3:17");
}

TEST(IdentifySpec, AbsentKeysTakeTheirDescriptionsDefaults) {
  const std::string path = WriteTempFile("data.yaml", "active: {csv: a.csv}\n");
  const IdentifySpec spec = LoadIdentifySpec(path);
  EXPECT_FALSE(spec.passive_csv);
  EXPECT_FALSE(spec.velocity_csv);
  EXPECT_FALSE(spec.velocity_f_iso);
  EXPECT_EQ(spec.active_count, 3);
  EXPECT_FALSE(spec.active_nonnegative);
  // the table states those defaults
  const std::string table = ReferenceTable(IdentifyDataBlocks(), "block");
  EXPECT_THAT(table, HasSubstr("| `count` | - | 3 | an integer from 1 to 12: "));
  EXPECT_THAT(table, HasSubstr("| `nonnegative` | | false | true or false | "));
  EXPECT_THAT(table, HasSubstr("| `f_iso` | N | optional | > 0 and <= 1e+09: "));
  EXPECT_THAT(table, HasSubstr("| `csv` | | required | any text but the empty one | "));
}

TEST(IdentifySpec, EachRuleIsRefusedAtItsKey) {
  EXPECT_THAT(Refusal("active: {csv: a.csv, count: 0}\n"),
              HasSubstr("active.count = 0 (FILE:1:29): must be an integer from 1 to 12 [-]: "));
  EXPECT_THAT(Refusal("active: {csv: a.csv, count: 2.5}\n"),
              HasSubstr("active.count = 2.5 (FILE:1:29): must be an integer from 1 to 12"));
  EXPECT_THAT(Refusal("active: {csv: a.csv, nonnegative: maybe}\n"),
              HasSubstr("active.nonnegative = maybe (FILE:1:35): must be true or false"));
  EXPECT_THAT(Refusal("velocity: {csv: v.csv, f_iso: 0}\n"),
              HasSubstr("velocity.f_iso = 0 (FILE:1:31): must be > 0 and <= 1e+09 [N]"));
  EXPECT_THAT(Refusal("passive: {count: 2}\n"),
              HasSubstr("passive.count (FILE:1:11): unknown key"));
  EXPECT_THAT(Refusal("velocity: {f_iso: 100}\n"),
              HasSubstr("velocity.csv (FILE:1:11): missing required key"));
  EXPECT_THAT(Refusal("passive: {csv: \"\"}\n"),
              HasSubstr("passive.csv = \"\" (FILE:1:16): must not be empty"));
  EXPECT_THAT(Refusal("passive: {csv: [a, b]}\n"),
              HasSubstr("passive.csv = [a, b] (FILE:1:16): must be a text value"));
  EXPECT_THAT(Refusal("{}\n"), HasSubstr("give at least one of passive, active, velocity"));
  EXPECT_THAT(Refusal("activ: {csv: a.csv}\n"), HasSubstr("activ (FILE:1:1): unknown key"));
}

}  // namespace
}  // namespace musclesim
