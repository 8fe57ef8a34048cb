#include "musclesim/model/tension.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "musclesim/errors.h"
#include "support/numeric.h"

namespace musclesim {
namespace {

ModelParams Example() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {2.0, 30.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{0.05, 90.0, 0.097}, {0.03, 400.0, 0.104}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

TEST(Tension, IsPassivePlusActive) {
  const TensionModel model(Example());
  for (double x : {0.08, 0.1, 0.11}) {
    for (double v : {-0.5, 0.0, 0.3}) {
      const TensionSample s = model.Evaluate(x, v, 0.6);
      EXPECT_DOUBLE_EQ(s.total, s.passive + s.active);
      EXPECT_DOUBLE_EQ(s.passive, PassiveTension(Example().passive, x).value);
      EXPECT_NEAR(s.active,
                  0.6 * 100.0 * model.active_length().Evaluate(x).value *
                      model.velocity().Evaluate(v).value, 1e-12);
    }
  }
}

TEST(Tension, IsometricAtOptimalLengthGivesActivationTimesFiso) {
  const TensionModel model(Example());
  const double x_opt = model.active_length().optimal_length();
  for (double u : {0.0, 0.25, 1.0}) {
    EXPECT_NEAR(model.Evaluate(x_opt, 0.0, u).active, u * 100.0, 1e-12);
  }
}

TEST(Tension, DerivativesMatchFiniteDifferences) {
  const TensionModel model(Example());
  for (double x : {0.09, 0.1, 0.11}) {  // away from the slack kink at 0.105
    for (double v : {-0.4, -0.002, 0.0, 0.001, 0.5}) {
      const double u = 0.7;
      const TensionSample s = model.Evaluate(x, v, u);
      const double by_x = testing::CentralDifference(
          [&](double y) { return model.Evaluate(y, v, u).total; }, x, 1e-7);
      const double by_v = testing::CentralDifference(
          [&](double w) { return model.Evaluate(x, w, u).total; }, v, 1e-8);
      const double by_u = testing::CentralDifference(
          [&](double a) { return model.Evaluate(x, v, a).total; }, u, 1e-6);
      EXPECT_NEAR(s.d_length, by_x, 1e-5 * std::max(1.0, std::abs(by_x))) << x << " " << v;
      EXPECT_NEAR(s.d_velocity, by_v, 1e-5 * std::max(1.0, std::abs(by_v))) << x << " " << v;
      EXPECT_NEAR(s.d_activation, by_u, 1e-7 * std::max(1.0, std::abs(by_u)));
    }
  }
}

TEST(Tension, ValidationNamesTheBlock) {
  ModelParams p = Example();
  p.velocity.n = 0;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("velocity.n = 0")));
  p = Example();
  p.f_iso = -1;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("f_iso = -1")));
  p = Example();
  p.active_length.gaussians[0].precision = 0;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(
                  ::testing::HasSubstr("active_length.gaussians[0].width = 0")));
}

}  // namespace
}  // namespace musclesim
