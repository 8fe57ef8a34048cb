// The dotted key paths of `--set` and of ParameterError: "model.velocity.n", "load[0].value".
#include "musclesim/core/key_path.h"

#include <gtest/gtest.h>

namespace musclesim {
namespace {

// The steps written back as text, one per step: "a", "[2]".
std::vector<std::string> Spelled(const std::string& path) {
  const auto steps = SplitKeyPath(path);
  if (!steps) return {"malformed"};
  std::vector<std::string> out;
  for (const KeyPathStep& step : *steps) {
    // appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict) on "[" + string
    std::string text = step.key;
    if (text.empty()) text.append("[").append(std::to_string(step.index)).append("]");
    out.push_back(text);
  }
  return out;
}

using Steps = std::vector<std::string>;

TEST(KeyPath, SplitsKeysAndIndices) {
  EXPECT_EQ(Spelled("model.velocity.n"), (Steps{"model", "velocity", "n"}));
  EXPECT_EQ(Spelled("load[0].value"), (Steps{"load", "[0]", "value"}));
  EXPECT_EQ(Spelled("a[2][13]"), (Steps{"a", "[2]", "[13]"}));
  EXPECT_EQ(Spelled("[1].x"), (Steps{"[1]", "x"}));
  // a dot on either side of an index is optional
  EXPECT_EQ(Spelled("gaussians[1]width"), (Steps{"gaussians", "[1]", "width"}));
  EXPECT_EQ(Spelled("load.[0]"), (Steps{"load", "[0]"}));
}

TEST(KeyPath, EmptyPathHasNoSteps) {
  const auto steps = SplitKeyPath("");
  ASSERT_TRUE(steps.has_value());
  EXPECT_TRUE(steps->empty());
}

TEST(KeyPath, OneTrailingDotIsIgnored) {
  EXPECT_EQ(Spelled("model."), (Steps{"model"}));
  EXPECT_EQ(Spelled("load[0]."), (Steps{"load", "[0]"}));
}

TEST(KeyPath, RejectsMalformedPaths) {
  for (const char* path :
       {"a..b", ".a", "load[]", "load[x]", "load[-1]", "load[0", "load[ 1]", "a.b..", "a[1]..b"}) {
    EXPECT_FALSE(SplitKeyPath(path).has_value()) << path;
  }
}

TEST(KeyPath, IndexBeyondTheLongestListIsMalformed) {
  // 2^64 - 1 and beyond do not fit std::size_t; 1e9 is above kMaxKeyPathIndex
  for (const char* path :
       {"load[99999999999999999999999]", "load[18446744073709551615]", "load[1000000000]"}) {
    EXPECT_FALSE(SplitKeyPath(path).has_value()) << path;
  }
  EXPECT_EQ(Spelled("load[999999999]"), (Steps{"load", "[999999999]"}));
}

}  // namespace
}  // namespace musclesim
