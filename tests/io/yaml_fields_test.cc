// The YAML field helpers every reader uses: each error names the key path, the value, the
// file:line:column and the rule. Positions are found in the text by the test itself.
#include "io/readers/yaml_fields.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "musclesim/core/input_ranges.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr const char* kText =
    "block:\n"
    "  number: 2.5\n"
    "  word: abc\n"
    "  count: 7\n"
    "  flag: true\n"
    "  list: [1, 2, 3]\n";

// "file:line:column" (1-based) of the first occurrence of `needle` in kText.
std::string PositionOf(const std::string& needle) {
  const std::string text = kText;
  const std::size_t at = text.find(needle);
  const std::size_t line_start = text.rfind('\n', at);
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n'));
  const std::size_t column = line_start == std::string::npos ? at + 1 : at - line_start;
  return "f.yaml:" + std::to_string(line) + ":" + std::to_string(column);
}

template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

class YamlFields : public ::testing::Test {
 protected:
  const yaml::Source source{"f.yaml"};
  const Document root = yaml::Parse("f.yaml", kText);
  const Document& block = root["block"];
};

TEST_F(YamlFields, ReadsEachKindOfValue) {
  EXPECT_EQ(yaml::ReadNumber(source, block["number"], "block.number"), 2.5);
  EXPECT_EQ(yaml::ReadString(source, block["word"], "block.word"), "abc");
  EXPECT_EQ(yaml::ReadInteger(source, block["count"], "block.count"), 7);
  EXPECT_TRUE(yaml::ReadBool(source, block["flag"], "block.flag"));
  EXPECT_EQ(yaml::ReadNumbers(source, block["list"], "block.list", 3),
            (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(yaml::ReadOptionalNumber(source, block, "block", "absent", 9.0), 9.0);
  EXPECT_EQ(yaml::ReadOptionalNumber(source, block, "block", "number", 9.0), 2.5);
}

TEST_F(YamlFields, ABadValueNamesPathValuePositionAndRule) {
  const std::string message =
      ErrorOf([&] { yaml::ReadNumber(source, block["word"], "block.word"); });
  EXPECT_THAT(message, HasSubstr("block.word = abc (" + PositionOf("abc") + ")"));
  EXPECT_THAT(ErrorOf([&] { yaml::ReadInteger(source, block["number"], "block.number"); }),
              HasSubstr("block.number = 2.5 (" + PositionOf("2.5") + ")"));
  EXPECT_THAT(ErrorOf([&] { yaml::ReadNumbers(source, block["list"], "block.list", 2); }),
              HasSubstr("block.list"));
}

TEST_F(YamlFields, UnknownAndMissingKeysAreNamed) {
  EXPECT_THAT(ErrorOf([&] {
                yaml::RequireMap(source, block, "block", {"number", "word"});
              }),
              HasSubstr("block.count (" + PositionOf("count") + "): unknown key"));
  EXPECT_THAT(ErrorOf([&] { yaml::Required(source, block, "block", "missing"); }),
              HasSubstr("block.missing"));
  EXPECT_EQ(yaml::Join("", "a"), "a");
  EXPECT_EQ(yaml::Join("a.b", "c"), "a.b.c");
}

TEST_F(YamlFields, ANumberOutsideItsRangeSaysTheRangeAndWhy) {
  const InputRange range{0.0, 1.0, "m", "a test range", false};
  EXPECT_THAT(ErrorOf([&] { yaml::ReadNumberIn(source, block["number"], "block.number", range); }),
              HasSubstr("block.number = 2.5 (" + PositionOf("2.5") +
                        "): must be from 0 to 1 [m]: a test range"));
  const InputRange wide{0.0, 10.0, "m", "a test range", false};
  EXPECT_EQ(yaml::ReadNumberIn(source, block["number"], "block.number", wide), 2.5);
}

TEST_F(YamlFields, AParameterErrorIsPlacedAtTheNodeItsPathReaches) {
  const std::string message = ErrorOf([&] {
    yaml::ValidateAt(source, block, "block",
                     [] { throw ParameterError("count", "7", "must be below 5"); });
  });
  EXPECT_THAT(message, HasSubstr("block.count = 7 (" + PositionOf("7") + "): must be below 5"));
}

TEST(YamlParse, AKeyGivenTwiceNamesBothLines) {
  const std::string message = ErrorOf([] { yaml::Parse("d.yaml", "a: 1\nb: 2\na: 3\n"); });
  EXPECT_THAT(message, HasSubstr("d.yaml:3:1"));
  EXPECT_THAT(message, HasSubstr("already given at line 1, column 1"));
}

}  // namespace
}  // namespace musclesim
