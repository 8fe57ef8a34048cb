#include "musclesim/dynamics/waveform.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

Waveform Make(WaveformKind kind) {
  Waveform w;
  w.kind = kind;
  return w;
}

TEST(Waveform, StepSwitchesAtItsTime) {
  Waveform w = Make(WaveformKind::kStep);
  w.time = 0.05;
  w.before = 0.2;
  w.after = 0.9;
  EXPECT_EQ(w.Evaluate(0.0), 0.2);
  EXPECT_EQ(w.Evaluate(std::nextafter(0.05, 0.0)), 0.2);
  EXPECT_EQ(w.Evaluate(0.05), 0.9);
  EXPECT_THAT(w.Breakpoints(0.0, 1.0), ElementsAre(0.05));
  EXPECT_TRUE(w.Breakpoints(0.1, 1.0).empty());
}

TEST(Waveform, RampIsLinearBetweenItsEnds) {
  Waveform w = Make(WaveformKind::kRamp);
  w.start = 1.0;
  w.end = 3.0;
  w.from = 10.0;
  w.to = 30.0;
  EXPECT_EQ(w.Evaluate(0.0), 10.0);
  EXPECT_DOUBLE_EQ(w.Evaluate(1.5), 15.0);
  EXPECT_EQ(w.Evaluate(4.0), 30.0);
  EXPECT_THAT(w.Breakpoints(0.0, 5.0), ElementsAre(1.0, 3.0));
  EXPECT_EQ(w.Minimum(0.0, 5.0), 10.0);
  EXPECT_EQ(w.Maximum(0.0, 2.0), 20.0);
}

TEST(Waveform, SineHasNoBreakpoints) {
  Waveform w = Make(WaveformKind::kSine);
  w.offset = 1.0;
  w.amplitude = 2.0;
  w.frequency = 0.5;
  w.phase = 0.25;
  EXPECT_DOUBLE_EQ(w.Evaluate(0.3), 1.0 + 2.0 * std::sin(std::numbers::pi * 0.3 + 0.25));
  EXPECT_TRUE(w.Breakpoints(0.0, 10.0).empty());
}

TEST(Waveform, PulsesRiseAndFallEveryPeriod) {
  Waveform w = Make(WaveformKind::kPulses);
  w.start = 0.1;
  w.period = 0.2;
  w.width = 0.05;
  w.low = 0.0;
  w.high = 1.0;
  EXPECT_EQ(w.Evaluate(0.05), 0.0);
  EXPECT_EQ(w.Evaluate(0.12), 1.0);
  EXPECT_EQ(w.Evaluate(0.2), 0.0);
  EXPECT_EQ(w.Evaluate(0.32), 1.0);
  const std::vector<double> edges = w.Breakpoints(0.0, 0.6);
  ASSERT_EQ(edges.size(), 6u);
  const double expected[] = {0.1, 0.15, 0.3, 0.35, 0.5, 0.55};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(edges[i], expected[i], 1e-15);
}

// Binary fractions, so that every edge start + k period (+ width) is exact.
Waveform ExactPulses() {
  Waveform w = Make(WaveformKind::kPulses);
  w.start = 0.5;
  w.period = 1.0;
  w.width = 0.25;
  w.low = 0.0;
  w.high = 1.0;
  return w;
}

TEST(Waveform, PulsesTakeTheirNewValueExactlyAtEachEdge) {
  // like a step at its time, a pulse is high from its rise on and low from its fall on
  const Waveform w = ExactPulses();
  EXPECT_EQ(w.Evaluate(std::nextafter(0.5, 0.0)), 0.0);
  EXPECT_EQ(w.Evaluate(0.5), 1.0);
  EXPECT_EQ(w.Evaluate(std::nextafter(0.75, 0.0)), 1.0);
  EXPECT_EQ(w.Evaluate(0.75), 0.0);
  EXPECT_EQ(w.Evaluate(1.5), 1.0);
  EXPECT_EQ(w.Evaluate(1.75), 0.0);
  // at every breakpoint the value is already the one that follows it
  const std::vector<double> edges = w.Breakpoints(0.0, 3.0);
  EXPECT_THAT(edges, ElementsAre(0.5, 0.75, 1.5, 1.75, 2.5, 2.75));
  for (double edge : edges) {
    EXPECT_EQ(w.Evaluate(edge), w.Evaluate(std::nextafter(edge, 3.0))) << edge;
  }
}

TEST(Waveform, PulseBreakpointsFromInsideAPulseIncludeItsFall) {
  const Waveform w = ExactPulses();
  // from inside the second pulse (1.5 to 1.75): its fall, then the third pulse's edges
  EXPECT_THAT(w.Breakpoints(1.6, 3.0), ElementsAre(1.75, 2.5, 2.75));
  // from between pulses: only later edges
  EXPECT_THAT(w.Breakpoints(1.8, 3.0), ElementsAre(2.5, 2.75));
}

TEST(Waveform, TableInterpolatesAndHoldsItsEnds) {
  Waveform w = Make(WaveformKind::kTable);
  w.points = {{0.0, 1.0}, {1.0, 3.0}, {2.0, 2.0}};
  EXPECT_EQ(w.Evaluate(-1.0), 1.0);
  EXPECT_DOUBLE_EQ(w.Evaluate(0.25), 1.5);
  EXPECT_DOUBLE_EQ(w.Evaluate(1.5), 2.5);
  EXPECT_EQ(w.Evaluate(5.0), 2.0);
  EXPECT_THAT(w.Breakpoints(-1.0, 3.0), ElementsAre(0.0, 1.0, 2.0));
  EXPECT_EQ(w.Maximum(-1.0, 3.0), 3.0);
}

std::string Rejection(const Waveform& w, bool activation = false) {
  try {
    activation ? ValidateActivation(w) : Validate(w);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Waveform, RejectsBrokenShapes) {
  Waveform ramp = Make(WaveformKind::kRamp);
  ramp.start = 1.0;
  ramp.end = 1.0;
  EXPECT_THAT(Rejection(ramp), HasSubstr("end = 1: must be finite and greater than start"));
  Waveform pulses = Make(WaveformKind::kPulses);
  pulses.period = 0.0;
  EXPECT_THAT(Rejection(pulses), HasSubstr("period = 0: must be finite and > 0"));
  pulses.period = 1.0;
  pulses.width = 2.0;
  EXPECT_THAT(Rejection(pulses), HasSubstr("width = 2: must be > 0 and at most period"));
  Waveform table = Make(WaveformKind::kTable);
  table.points = {{0.0, 0.0}, {1.0, 0.5}, {0.5, 1.0}};
  EXPECT_THAT(Rejection(table), HasSubstr("points[2][0] = 0.5: table times must be strictly"));
}

TEST(Waveform, ActivationMustStayWithinUnitInterval) {
  Waveform step = Make(WaveformKind::kStep);
  step.after = 1.5;
  EXPECT_THAT(Rejection(step, true), HasSubstr("after = 1.5: activation must stay within [0, 1]"));
  Waveform sine = Make(WaveformKind::kSine);
  sine.offset = 0.5;
  sine.amplitude = 0.6;
  EXPECT_THAT(Rejection(sine, true), HasSubstr("amplitude = 0.6: activation must stay"));
  Waveform table = Make(WaveformKind::kTable);
  table.points = {{0.0, 0.0}, {1.0, -0.1}};
  EXPECT_THAT(Rejection(table, true), HasSubstr("points[1][1] = -0.1"));
  sine.amplitude = 0.5;
  EXPECT_EQ(Rejection(sine, true), "accepted");
}

TEST(Waveform, FactoriesMakeTheShapeTheyName) {
  const Waveform step = Waveform::Step(0.05, 0.2, 0.9);
  EXPECT_EQ(step.Evaluate(0.04), 0.2);
  EXPECT_EQ(step.Evaluate(0.05), 0.9);
  const Waveform ramp = Waveform::Ramp(1.0, 3.0, 10.0, 20.0);
  EXPECT_DOUBLE_EQ(ramp.Evaluate(2.5), 17.5);            // a quarter left of the ramp's 10 N rise
  const Waveform sine = Waveform::Sine(1.0, 2.0, 0.25);  // a quarter period at t = 1 s
  EXPECT_NEAR(sine.Evaluate(1.0), 3.0, 1e-15);
  const Waveform pulses = Waveform::Pulses(0.0, 1.0, 0.25, -1.0, 4.0);
  EXPECT_EQ(pulses.Evaluate(2.1), 4.0);
  EXPECT_EQ(pulses.Evaluate(2.3), -1.0);
  const Waveform table = Waveform::Table({{0.0, 0.0}, {2.0, 4.0}});
  EXPECT_DOUBLE_EQ(table.Evaluate(0.5), 1.0);
  EXPECT_EQ(Waveform::Constant(7.0).Evaluate(123.0), 7.0);
}

TEST(Waveform, FactoriesRejectBrokenShapes) {
  const auto path_of = [](auto make) {
    try {
      make();
    } catch (const ParameterError& e) {
      return e.path();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(path_of([] { Waveform::Ramp(1.0, 0.5, 0.0, 1.0); }), "end");
  EXPECT_EQ(path_of([] { Waveform::Pulses(0.0, 1.0, 2.0, 0.0, 1.0); }), "width");
  EXPECT_EQ(path_of([] { Waveform::Table({{1.0, 0.0}, {0.5, 1.0}}); }), "points[1][0]");
  EXPECT_EQ(path_of([] { Waveform::Constant(std::nan("")); }), "value");
  EXPECT_EQ(path_of([] { Waveform::Sine(0.0, 1.0, -1.0); }), "frequency");
}

}  // namespace
}  // namespace musclesim
