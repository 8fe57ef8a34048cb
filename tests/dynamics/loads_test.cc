#include "musclesim/dynamics/loads.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "musclesim/core/errors.h"
#include "support/rejection.h"

namespace musclesim {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A sine force, a step force, two springs and two hanging masses, each term's force written
// out by hand from docs/model.md section 6.
std::vector<Load> Mixed() {
  return {Load::Force(Waveform::Sine(30.0, 5.0, 2.0, 0.25)),
          Load::Spring(200.0, 0.12),
          Load::Mass(2.0),
          Load::Force(Waveform::Step(0.4, -3.0, 7.0)),
          Load::Spring(50.0, 0.08),
          Load::Mass(0.5, 1.62)};
}

double MixedForce(double t, double x) {
  const double sine = 30.0 + 5.0 * std::sin(2.0 * std::numbers::pi * 2.0 * t + 0.25);
  const double step = t < 0.4 ? -3.0 : 7.0;
  const double springs = 200.0 * (0.12 - x) + 50.0 * (0.08 - x);
  const double weights = 2.0 * 9.81 + 0.5 * 1.62;
  return sine + step + springs + weights;
}

TEST(Loads, ForceIsTheSumOfEveryTerm) {
  const LoadSet loads(Mixed());
  for (double t : {0.0, 0.13, 0.399, 0.4, 0.75}) {
    for (double x : {0.05, 0.1, 0.14}) {
      // the set sums the springs' pulls before adding them, the hand sum after: a few
      // roundings of ~60 N terms, 1e-13 N
      EXPECT_NEAR(loads.Force(t, x), MixedForce(t, x), 1e-13 * 100.0) << t << " " << x;
    }
  }
}

TEST(Loads, SpringSlopeIsMinusTheSumOfStiffnesses) {
  const LoadSet loads(Mixed());
  EXPECT_EQ(loads.ForceSlope(), -250.0);
  // the force is linear in x: its secant over any interval is the slope (rounding of a
  // ~20 N difference over 0.1 m: 1e-12 N/m)
  EXPECT_NEAR((loads.Force(0.2, 0.15) - loads.Force(0.2, 0.05)) / 0.1, -250.0, 1e-12 * 250.0);
  EXPECT_EQ(LoadSet({Load::Constant(4.0), Load::Mass(1.0)}).ForceSlope(), 0.0);
}

TEST(Loads, HangingMassesAddTheirMassAndNothingElseDoes) {
  EXPECT_EQ(LoadSet(Mixed()).AddedMass(), 2.5);
  EXPECT_EQ(LoadSet({Load::Constant(4.0), Load::Spring(10.0, 0.1)}).AddedMass(), 0.0);
  EXPECT_EQ(LoadSet({}).AddedMass(), 0.0);
  EXPECT_EQ(LoadSet({}).Force(0.3, 0.1), 0.0);
}

TEST(Loads, BreakpointsOfEveryForceMergedSortedAndUnique) {
  const LoadSet loads({Load::Force(Waveform::Step(0.3, 0.0, 1.0)), Load::Spring(10.0, 0.1),
                       Load::Force(Waveform::Ramp(0.1, 0.3, 0.0, 5.0)),
                       Load::Force(Waveform::Table({{0.05, 0.0}, {0.2, 1.0}, {0.9, 1.0}}))});
  EXPECT_THAT(loads.Breakpoints(0.0, 1.0), ElementsAre(0.05, 0.1, 0.2, 0.3, 0.9));
  // only those strictly inside the interval
  EXPECT_THAT(loads.Breakpoints(0.1, 0.3), ElementsAre(0.2));
  EXPECT_TRUE(LoadSet({Load::Constant(1.0), Load::Mass(1.0)}).Breakpoints(0.0, 1.0).empty());
}

TEST(Loads, FactoriesFillTheirKindAndFields) {
  const Load constant = Load::Constant(40.0);
  EXPECT_EQ(constant.kind, LoadKind::kForce);
  EXPECT_EQ(constant.force.kind, WaveformKind::kConstant);
  EXPECT_EQ(constant.force.value, 40.0);
  const Load step = Load::Force(Waveform::Step(0.05, 0.0, 55.0));
  EXPECT_EQ(step.kind, LoadKind::kForce);
  EXPECT_EQ(step.force.Evaluate(0.05), 55.0);
  const Load spring = Load::Spring(1e5, 0.1);
  EXPECT_EQ(spring.kind, LoadKind::kSpring);
  EXPECT_EQ(spring.stiffness, 1e5);
  EXPECT_EQ(spring.anchor, 0.1);
  const Load mass = Load::Mass(12.0);
  EXPECT_EQ(mass.kind, LoadKind::kMass);
  EXPECT_EQ(mass.mass, 12.0);
  EXPECT_EQ(mass.gravity, 9.81);                     // the default
  EXPECT_EQ(Load::Mass(1.0, -1.62).gravity, -1.62);  // a weight may pull the actuator shorter
}

TEST(Loads, FactoriesRejectEachRule) {
  using testing::Rejection;
  EXPECT_THAT(Rejection([] { Load::Spring(-1.0, 0.1); }),
              HasSubstr("stiffness = -1: must be from 0 to 1e+12 [N/m]"));
  EXPECT_THAT(Rejection([] { Load::Spring(10.0, INFINITY); }),
              HasSubstr("anchor = inf: must be from -1000 to 1000 [m]"));
  EXPECT_THAT(Rejection([] { Load::Mass(0.0); }),
              HasSubstr("mass = 0: must be from 1e-09 to 1e+09 [kg]"));
  EXPECT_THAT(Rejection([] { Load::Mass(1.0, NAN); }),
              HasSubstr("gravity = nan: must be from -1000 to 1000 [m/s^2]"));
  EXPECT_THAT(Rejection([] { Load::Constant(NAN); }), HasSubstr("value = nan: must be finite"));
  EXPECT_EQ(Rejection([] { Load::Spring(0.0, 0.1); }), "accepted");  // a slack spring is allowed
}

TEST(Loads, SetNamesTheOffendingLoadByIndex) {
  Load broken = Load::Spring(10.0, 0.1);
  broken.stiffness = -5.0;  // filled field by field, as a reader does, then validated
  try {
    LoadSet({Load::Constant(1.0), broken});
    FAIL() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "load[1].stiffness");
  }
}

}  // namespace
}  // namespace musclesim
