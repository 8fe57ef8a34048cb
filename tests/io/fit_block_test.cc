// The paper's active_length.fit block read through its description (FitBlock): each key into
// its member, defaults where absent, each rule refused at its key with file:line:column, and
// the handles of its numbers bounded and whole as the description says.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/io/writers/reference_table.h"
#include "musclesim/model/fit_fields.h"
#include "musclesim/scenario/parameter.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// A paper model whose active length curve is fitted with `fit`.
std::string Model(const std::string& fit) {
  return "f_iso: 100.0\n"
         "passive: {slack_length: 0.1, k_p: 2.0, alpha: 50.0}\n"
         "active_length:\n"
         "  optimal_range: [0.095, 0.105]\n"
         "  sigma: 1.0\n"
         "  fit: " +
         fit +
         "\n"
         "velocity: {v_max: 0.5, n: 2, epsilon: 1.0e-3}\n";
}

FitSpec Fit(const std::string& fit) {
  const ModelSpec spec = ParseModelSpec("m.yaml", Model(fit));
  EXPECT_TRUE(spec.fit.has_value());
  return spec.fit.value_or(FitSpec{});
}

std::string Refusal(const std::string& fit) {
  try {
    ParseModelSpec("m.yaml", Model(fit));
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read)";
}

TEST(FitBlock, EachKeyIsReadIntoItsMember) {
  const FitSpec preset =
      Fit("{count: 3, target: preset, name: thelen2003, optimal_length: 0.1, nonnegative: true}");
  EXPECT_EQ(preset.count, 3);
  EXPECT_EQ(preset.target, FitTargetKind::kPreset);
  EXPECT_EQ(preset.preset, ForceLengthPreset::kThelen2003);
  EXPECT_EQ(preset.optimal_length, 0.1);
  EXPECT_TRUE(preset.nonnegative);
  const FitSpec polygon =
      Fit("{count: 2, target: polygon, points: [[0.09, 0], [0.1, 1], [0.11, 0]]}");
  EXPECT_EQ(polygon.target, FitTargetKind::kPolygon);
  ASSERT_EQ(polygon.points.size(), 3u);
  EXPECT_EQ(polygon.points[1].x, 0.1);
  EXPECT_EQ(polygon.points[1].y, 1.0);
}

TEST(FitBlock, AbsentKeysTakeTheirDefaults) {
  const FitSpec fit = Fit("{count: 2}");
  EXPECT_EQ(fit.target, FitTargetKind::kIndicator);
  EXPECT_FALSE(fit.preset);
  EXPECT_FALSE(fit.optimal_length);
  EXPECT_FALSE(fit.nonnegative);
  const std::string table = ReferenceTable(FitBlock(), "block");
  EXPECT_THAT(table, HasSubstr("| `target` | | indicator | a name: indicator, polygon, samples, "
                               "preset |"));
  EXPECT_THAT(table, HasSubstr("| `name` | | optional | a name: degroote2016, thelen2003, "));
  EXPECT_THAT(table, HasSubstr("| `count` | - | required | an integer from 1 to 12: "));
}

TEST(FitBlock, EachRuleIsRefusedAtItsKey) {
  // the block's map starts at line 6, column 8
  struct Case {
    std::string fit;
    std::string message;
  };
  const Case cases[] = {
      {"{count: 0}",
       "model.active_length.fit.count = 0 (m.yaml:6:16): must be an integer from "
       "1 to 12 [-]: past a dozen"},
      {"{count: 2.5}", "model.active_length.fit.count = 2.5 (m.yaml:6:16): must be an integer"},
      {"{target: indicator}", "model.active_length.fit.count (m.yaml:6:8): missing required key"},
      {"{count: 2, target: spline}",
       "model.active_length.fit.target = spline (m.yaml:6:27): must be one of indicator, "
       "polygon, samples, preset"},
      {"{count: 2, target: preset, name: hill, optimal_length: 0.1}",
       "model.active_length.fit.name = hill (m.yaml:6:41): must be one of degroote2016, "
       "thelen2003, gordon1966, mujoco"},
      {"{count: 2, target: preset, name: thelen2003, optimal_length: 0}",
       "model.active_length.fit.optimal_length = 0 (m.yaml:6:69): must be > 0 and <= 1000 [m]"},
      {"{count: 2, nonnegative: maybe}",
       "model.active_length.fit.nonnegative = maybe (m.yaml:6:32): must be true or false"},
      {"{count: 2, colour: red}", "model.active_length.fit.colour (m.yaml:6:19): unknown key"},
      {"{count: 2, target: polygon}", "model.active_length.fit.points"},
  };
  for (const Case& c : cases) EXPECT_THAT(Refusal(c.fit), HasSubstr(c.message)) << c.fit;
}

TEST(FitBlock, ItsHandlesAreTheDescribedNumbers) {
  std::string text = testing::ReadFile(testing::FixturePath("actuator.yaml"));
  const std::string gaussians = "gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]";
  text.replace(text.find(gaussians), gaussians.size(), "fit: {count: 2, target: indicator}");
  Scenario s = LoadScenario(testing::WriteTempFile("fitted.yaml", text));
  const Parameter count = s.parameter("model.active_length.fit.count");
  EXPECT_TRUE(count.is_integer());
  EXPECT_EQ(count.Get(s), 2.0);
  EXPECT_THROW(count.Check(13.0), ParameterError);  // the description's range, 1 to 12
  EXPECT_THROW(count.Check(2.5), ParameterError);
  count.Set(s, 3.0);
  EXPECT_EQ(s.models.at("model").spec.params.active_length.gaussians.size(), 3u);  // refitted
  EXPECT_THROW(s.parameter("model.active_length.fit.target"), ParameterError);     // a word
}

}  // namespace
}  // namespace musclesim
