// The ranges of the model's parameters whose ends come from the arithmetic: values outside
// them are refused with the reason, instead of producing NaN or undefined behaviour.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/model/tension.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

ModelParams Model() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {1.0, 100.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{2.0, 4000.0, 0.1}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

std::string RuleBroken(const ModelParams& p) {
  try {
    TensionModel model(p);
  } catch (const ParameterError& e) {
    return e.path() + ": " + e.rule();
  }
  return "accepted";
}

TEST(ModelRanges, EpsilonWhoseSquareUnderflowsIsRefused) {
  ModelParams p = Model();
  p.velocity.epsilon = 1e-200;  // eps^2 = 0 in double: g(0) would be 0 * inf = NaN
  EXPECT_THAT(RuleBroken(p), HasSubstr("velocity.epsilon: must be between 1e-12 v_max"));
  p.velocity.epsilon = 1e200;  // eps^2 = inf: dg/dv would be inf / inf
  EXPECT_THAT(RuleBroken(p), HasSubstr("velocity.epsilon"));
  // the ends themselves are accepted and give finite curves
  for (double eps : {1e-12, 1.0}) {
    p.velocity.epsilon = eps;
    ASSERT_EQ(RuleBroken(p), "accepted");
    const TensionSample s = TensionModel(p).Evaluate(0.1, 0.0, 1.0);
    EXPECT_TRUE(std::isfinite(s.total) && std::isfinite(s.d_velocity)) << eps;
  }
}

TEST(ModelRanges, GaussianTooNarrowToResolveIsRefused) {
  ModelParams p = Model();
  p.active_length.gaussians[0].precision = 1e60;  // once a float-to-integer overflow (UBSan)
  EXPECT_THAT(RuleBroken(p), HasSubstr("active_length.gaussians[0].width: gives a spread"));
  // a spread of 1e-7 m on a 1 cm range is still resolved: 4e-6 of it is 4e-8 m
  p.active_length.gaussians[0].precision = 1.0 / 1e-14;
  p.active_length.gaussians[0].center = 0.1;
  EXPECT_EQ(RuleBroken(p), "accepted");
}

TEST(ModelRanges, CurvatureAboveItsMaximumIsRefused) {
  ModelParams p = Model();
  p.velocity.n = kMaxVelocityExponent + 1;
  EXPECT_THAT(RuleBroken(p), HasSubstr("velocity.n"));
}

}  // namespace
}  // namespace musclesim
