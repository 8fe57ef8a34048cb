#include "musclesim/io/readers/model_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "musclesim/core/errors.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr const char* kValid = R"(model:
  f_iso: 100.0
  passive: {k_p: 2.0, alpha: 30.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians:
      - {amplitude: 0.05, width: 90.0, center: 0.097}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
)";

std::string WriteTemp(const std::string& text) {
  static int counter = 0;
  return testing::WriteTempFile("model_" + std::to_string(++counter) + ".yaml", text);
}

// Replaces the first occurrence of `from` in the valid file by `to`.
std::string Edited(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string LoadError(const std::string& text) {
  const std::string path = WriteTemp(text);
  return testing::InputErrorOf(path, [&] { LoadModelSpec(path); });
}

TEST(ModelFile, ReadsAValidModel) {
  const ModelSpec m = LoadModelSpec(WriteTemp(kValid));
  EXPECT_EQ(m.params.f_iso, 100.0);
  EXPECT_EQ(m.params.passive.alpha, 30.0);
  EXPECT_EQ(m.params.active_length.optimal_max, 0.105);
  EXPECT_EQ(m.params.active_length.sigma, 1.0);  // the documented default
  ASSERT_EQ(m.params.active_length.gaussians.size(), 1u);
  EXPECT_EQ(m.params.active_length.gaussians[0].center, 0.097);
  EXPECT_EQ(m.params.velocity.n, 3);
  EXPECT_FALSE(m.fit.has_value());
}

TEST(ModelFile, RunsTheFitAtLoadTime) {
  const ModelSpec m = LoadModelSpec(
      WriteTemp(Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
                       "fit: {count: 2, target: indicator}")));
  ASSERT_TRUE(m.fit_result.has_value());
  EXPECT_EQ(m.params.active_length.gaussians.size(), 2u);
  EXPECT_GT(m.fit_result->relative_residual, 0.0);
}

TEST(ModelFile, ErrorsNameKeyValueLocationAndRule) {
  EXPECT_EQ(LoadError(Edited("n: 3", "n: 0")),
            "model.velocity.n = 0 (FILE:8:29): must be an integer from 1 to 1000 [-]: the power "
            "1/n; at 1000 it is 0.001, the curve a step");
  EXPECT_EQ(LoadError(Edited("k_p: 2.0", "k_p: -2.0")),
            "model.passive.k_p = -2.0 (FILE:3:18): must be from 0 to 1e+09 [N]: 1e9 N "
            "(100,000 tonnes-force) is beyond any actuator or rig, and sums of loads stay finite");
}

TEST(ModelFile, RejectsEveryBrokenRule) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {Edited("f_iso: 100.0", "f_iso: 0"),
       "model.f_iso = 0 (FILE:2:10): must be > 0 and <= 1e+09 [N]"},
      {Edited("f_iso: 100.0", "f_iso: 2e9"),
       "model.f_iso = 2e9 (FILE:2:10): must be > 0 and <= 1e+09 [N]"},
      {Edited("f_iso: 100.0", "f_iso: .nan"), "model.f_iso = .nan (FILE:2:10): must be > 0"},
      {Edited("f_iso: 100.0", "f_iso: lots"), "model.f_iso = lots (FILE:2:10): must be a number"},
      {Edited("alpha: 30.0", "alpha: 0.0"), "model.passive.alpha = 0"},
      {Edited("slack_length: 0.105", "slack_length: .inf"),
       "model.passive.slack_length = .inf (FILE:3:50): must be from -1000 to 1000 [m]"},
      {Edited("[0.095, 0.105]", "[0.105, 0.095]"),
       "model.active_length.optimal_range[1] = 0.095 (FILE:5:28): must be finite and greater"},
      {Edited("[0.095, 0.105]", "[0.095]"), "must be a list of exactly 2 numbers"},
      {Edited("optimal_range: [0.095, 0.105]", "optimal_range: [0.095, 0.105]\n    sigma: -1"),
       "model.active_length.sigma = -1 (FILE:6:12): must be finite and > 0"},
      {Edited("width: 90.0", "width: 0"),
       "model.active_length.gaussians[0].width = 0 (FILE:7:34): must be finite and > 0"},
      {Edited("amplitude: 0.05", "amplitude: -0.05"),
       "must be positive somewhere on optimal_range"},
      {Edited("n: 3", "n: 2.5"),
       "model.velocity.n = 2.5 (FILE:8:29): must be an integer from 1 to 1000"},
      {Edited("v_max: 1.0", "v_max: -1"), "model.velocity.v_max = -1"},
      {Edited("epsilon: 1.0e-3", "epsilon: 0"), "model.velocity.epsilon = 0"},
      {Edited("f_iso: 100.0", "f_iso: 100.0\n  fiso: 3"),
       "model.fiso (FILE:3:3): unknown key; allowed here: f_iso, passive, active_length, velocity"},
      {Edited("model:", "modle:"), "modle (FILE:1:1): unknown key"},
      {Edited("  f_iso: 100.0\n", ""), "model.f_iso (FILE:2:3): missing required key"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}\n    fit: {count: "
              "2}"),
       "model.active_length = gaussians and fit (FILE:5:5): give exactly one of gaussians"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}", "sigma: 1"),
       "model.active_length = neither (FILE:5:5): give exactly one"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "fit: {count: 2, target: polygon, points: [[0.1, 1]]}"),
       "model.active_length.fit.points = 1 points (FILE:6:46): a polygon needs at least 2 points"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "fit: {count: 2, target: polygon, points: [[0.1, 1], [0.09, 0], [0.11, 0]]}"),
       "model.active_length.fit.points[1][0] = 0.09 (FILE:6:58): polygon x must be strictly "
       "increasing"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "fit: {count: 2, target: circle}"),
       "model.active_length.fit.target = circle (FILE:6:29): must be one of indicator"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "fit: {count: 2, target: polygon}"),
       "model.active_length.fit.points = ~ (FILE:6:10): target polygon needs points"},
      {Edited("gaussians:\n      - {amplitude: 0.05, width: 90.0, center: 0.097}",
              "fit: {count: 2, nonnegative: maybe}"),
       "model.active_length.fit.nonnegative = maybe (FILE:6:34): must be true or false"},
      {"model: [1, 2]\n", "model = [1, 2] (FILE:1:8): must be a map of keys"},
      {"model: {f_iso: 1\n", "FILE:2:1: YAML syntax error"},
      {"", "FILE: the file is empty"},
      {"model: {? [a]: 1}\n", "model (FILE:1:11): a key is a list; keys must be plain names"},
  };
  for (const auto& [text, expected] : cases) {
    EXPECT_THAT(LoadError(text), HasSubstr(expected)) << text;
  }
}

TEST(ModelFile, MissingFileIsAnInputError) {
  EXPECT_THAT([] { LoadModelSpec("/nonexistent/model.yaml"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("cannot open the file")));
}

}  // namespace
}  // namespace musclesim
