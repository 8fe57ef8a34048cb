// The written model block read back by LoadModelSpec: the same doubles, every part.
#include "musclesim/io/writers/model_yaml_writer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "musclesim/io/readers/model_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

ModelParams ReadBack(const ModelYamlDraft& draft) {
  return LoadModelSpec(testing::WriteTempFile("model.yaml", FormatModelYaml(draft))).params;
}

// Expects the component read back to hold exactly amplitude a, width factor b, center d.
void ExpectGaussian(const Gaussian& read, double a, double b, double d) {
  const auto [amplitude, width_factor, center] = read;
  EXPECT_EQ(amplitude, a);
  EXPECT_EQ(width_factor, b);
  EXPECT_EQ(center, d);
}

TEST(ModelYamlWriter, KnownPartsReadBackToTheSameDoubles) {
  // values that decimal notation cannot hold exactly, so that 17 digits are needed
  ModelYamlDraft draft;
  draft.header = {"a header: with a colon", "# and a hash"};
  draft.f_iso = {100.0 / 3.0, {"N, the maximum"}};
  draft.passive = {PassiveParams{0.1 + 0.2, 100.0 / 3.0, 0.105}, {"k_p = 0.3 +- 0.01 N"}};
  ActiveLengthParams active;
  active.optimal_min = 0.095;
  active.optimal_max = 0.105;
  active.sigma = 2.5;  // not the default: must be written
  active.gaussians = {Gaussian{0.1, 9000.0 / 7.0, 0.1}, Gaussian{1.0 / 3.0, 12345.678, 0.0975}};
  draft.active_length = {active, {"fitted"}};
  draft.gaussian_comments = {"first", "second"};
  draft.velocity = {VelocityParams{0.7, 4, 7e-4}, {"v_max = 0.7 +- 0.01 m/s", "other n: none"}};

  const ModelParams p = ReadBack(draft);
  EXPECT_EQ(p.f_iso, 100.0 / 3.0);
  EXPECT_EQ(p.passive.k_p, 0.1 + 0.2);
  EXPECT_EQ(p.passive.alpha, 100.0 / 3.0);
  EXPECT_EQ(p.passive.slack_length, 0.105);
  EXPECT_EQ(p.active_length.optimal_min, 0.095);
  EXPECT_EQ(p.active_length.optimal_max, 0.105);
  EXPECT_EQ(p.active_length.sigma, 2.5);
  ASSERT_EQ(p.active_length.gaussians.size(), 2u);
  ExpectGaussian(p.active_length.gaussians[0], 0.1, 9000.0 / 7.0, 0.1);
  ExpectGaussian(p.active_length.gaussians[1], 1.0 / 3.0, 12345.678, 0.0975);
  EXPECT_EQ(p.velocity.v_max, 0.7);
  EXPECT_EQ(p.velocity.n, 4);
  EXPECT_EQ(p.velocity.epsilon, 7e-4);
}

TEST(ModelYamlWriter, StandInsReadBackAsDocumented) {
  const ModelParams p = ReadBack(ModelYamlDraft{});
  // the values StandInModelParams documents
  EXPECT_EQ(p.f_iso, 1.0);
  EXPECT_EQ(p.passive.k_p, 0.0);
  EXPECT_EQ(p.passive.alpha, 1.0);
  EXPECT_EQ(p.passive.slack_length, 0.0);
  EXPECT_EQ(p.active_length.optimal_min, -1.0);
  EXPECT_EQ(p.active_length.optimal_max, 1.0);
  EXPECT_EQ(p.active_length.sigma, 1.0);
  ASSERT_EQ(p.active_length.gaussians.size(), 1u);
  ExpectGaussian(p.active_length.gaussians[0], 1.0, 1e-6, 0.0);
  EXPECT_EQ(p.velocity.v_max, 1e6);
  EXPECT_EQ(p.velocity.n, 1);
  EXPECT_EQ(p.velocity.epsilon, 1.0);
}

TEST(ModelYamlWriter, StandInsAreShortWithTheReasonOnTheirLine) {
  ModelYamlDraft draft;
  draft.header = {"made by hand"};
  draft.f_iso.comments = {"no data"};
  draft.passive.comments = {"no data", "none at all"};
  draft.active_length.comments = {"flat"};
  EXPECT_EQ(FormatModelYaml(draft),
            "# made by hand\n"
            "model:\n"
            "  f_iso: 1.0   # no data\n"
            "  passive: {k_p: 0.0, alpha: 1.0, slack_length: 0.0}   # no data; none at all\n"
            "  active_length:\n"
            "    # flat\n"
            "    optimal_range: [-1.0, 1.0]\n"
            "    gaussians: [{amplitude: 1.0, width: 1.0e-6, center: 0.0}]\n"
            "  velocity: {v_max: 1.0e6, n: 1, epsilon: 1.0}\n");
}

TEST(ModelYamlWriter, KnownPartsCarryTheirCommentsBelow) {
  ModelYamlDraft draft;
  draft.passive = {PassiveParams{2.0, 30.0, 0.105}, {"k_p = 2 +- 0.1 N"}};
  draft.velocity = {VelocityParams{1.0, 3, 0.001}, {"v_max = 1 +- 0 m/s", "other n: none"}};
  const std::string yaml = FormatModelYaml(draft);
  EXPECT_THAT(yaml, HasSubstr("  passive: {k_p: 2, alpha: 30, slack_length: 0.105}\n"
                              "  # k_p = 2 +- 0.1 N\n"));
  EXPECT_THAT(yaml, HasSubstr("  velocity: {v_max: 1, n: 3, epsilon: 0.001}\n"
                              "  # v_max = 1 +- 0 m/s\n"
                              "  # other n: none\n"));
}

TEST(ModelYamlWriter, GaussianCommentsMustMatchTheComponents) {
  ModelYamlDraft draft;
  ActiveLengthParams active;
  active.optimal_min = 0.095;
  active.optimal_max = 0.105;
  active.gaussians = {Gaussian{1.0, 100.0, 0.1}};
  draft.active_length.params = active;
  draft.gaussian_comments = {"one", "two"};
  EXPECT_THROW(FormatModelYaml(draft), std::invalid_argument);
}

TEST(ModelYamlWriter, GaussianIsAFlowMapWithSeventeenDigits) {
  EXPECT_EQ(FormatGaussianYaml(Gaussian{0.1, 2.0, -0.5}),
            "{amplitude: 0.10000000000000001, width: 2, center: -0.5}");
}

}  // namespace
}  // namespace musclesim
