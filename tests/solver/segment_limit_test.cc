// A segment of a path in the plane or in space that shortens to NetworkSystem::kMinSegmentLength
// (1e-6 m) ends the run with status `limit` at that time, naming the element (docs/model.md
// 12.5): also when it passes through zero length within one step, where its length (never
// negative) is above the level at both of the step's ends. Each case's time comes from a
// closed form of the motion.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "musclesim/solver/simulation.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr double kStiffness = 100.0, kMass = 1.0, kDamping = 0.1;  // N/m, kg, N s/m
constexpr double kAmplitude = 0.1;                                 // [m]

SolverOptions Tight() {
  SolverOptions options;
  options.rtol = 1e-10;
  options.atol = 1e-13;
  return options;
}

NetworkRunResult RunFor(const NetworkSystem& system, double t_end) {
  NetworkRunRequest request;
  request.t_end = t_end;
  request.output_interval = 0.01;
  Simulation simulation;
  return simulation.Run(system, Tight(), request);
}

// A bob on a spring of rest length 0 and a damper to a pivot, released at rest `kAmplitude`
// from it along `direction` (a unit vector): it moves on that line through the pivot, its
// distance the damped oscillator's |x(t)|.
NetworkSystem ThroughThePivot(int dimensions, const Coordinates& direction) {
  Coordinates start{};
  for (int c = 0; c < 3; ++c) start[c] = kAmplitude * direction[c];
  return NetworkSystem({Node::Fixed("pivot", Coordinates{}), Node::Free("bob", kMass, start)},
                       {Element::Spring("spring", "pivot", "bob", kStiffness, 0.0),
                        Element::Damper("damper", "pivot", "bob", kDamping)},
                       {}, {}, Space{dimensions, {}});
}

// The first time the damped oscillator x'' = -(c x' + k x) / m from (kAmplitude, 0) reaches
// |x| = level: x = A e^(-zeta w t) (cos(wd t) + zeta / sqrt(1 - zeta^2) sin(wd t)), solved by
// bisection on its first quarter period.
double FirstReach(double level) {
  const double w = std::sqrt(kStiffness / kMass),
               zeta = kDamping / (2.0 * std::sqrt(kStiffness * kMass));
  const double wd = w * std::sqrt(1.0 - zeta * zeta);
  const auto x = [&](double t) {
    return kAmplitude * std::exp(-zeta * w * t) *
           (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
  };
  double lo = 0.0, hi = std::numbers::pi / wd;  // x falls from A to -A e^(...) on it
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (x(mid) > level ? lo : hi) = mid;
  }
  return hi;
}

TEST(SegmentLimit, ABobSwingingThroughItsPivotInThePlaneEndsTheRunThere) {
  const NetworkRunResult run = RunFor(ThroughThePivot(2, {1.0, 0.0, 0.0}), 1.0);
  EXPECT_EQ(run.stats.status, RunStatus::kLimit) << run.stats.message;
  EXPECT_THAT(run.stats.message, HasSubstr("segment 0 of spring's path shortened to 1e-06 m"));
  // the crossing on the step's interpolant, whose error is the solver's (rtol 1e-10 of
  // 0.1 m over a speed of 1 m/s: ~1e-11 s)
  EXPECT_NEAR(run.stats.final_time, FirstReach(NetworkSystem::kMinSegmentLength), 1e-9);
  EXPECT_NEAR(run.times.back(), run.stats.final_time, 0.0);
}

TEST(SegmentLimit, ABobSwingingThroughItsPivotInSpaceEndsTheRunThere) {
  const double d = 1.0 / std::sqrt(3.0);
  const NetworkRunResult run = RunFor(ThroughThePivot(3, {d, -d, d}), 1.0);
  EXPECT_EQ(run.stats.status, RunStatus::kLimit) << run.stats.message;
  EXPECT_THAT(run.stats.message, HasSubstr("of spring's path shortened to 1e-06 m"));
  EXPECT_NEAR(run.stats.final_time, FirstReach(NetworkSystem::kMinSegmentLength), 1e-9);
}

TEST(SegmentLimit, ABobPassingItsPivotCloseByRunsToTheEnd) {
  // the same swing with 1 mm/s of sideways speed: a spring of rest length 0 in the plane is
  // linear (F = -k r), so the bob runs on the ellipse (A cos w t, (v/w) sin w t) and passes
  // the pivot at v/w = 1e-4 m, far above the level: its dips inside steps are no crossing
  NetworkSystem system(
      {Node::Fixed("pivot", Coordinates{}),
       Node::Free("bob", kMass, Coordinates{kAmplitude, 0.0, 0.0}, Coordinates{0.0, 1e-3, 0.0})},
      {Element::Spring("spring", "pivot", "bob", kStiffness, 0.0),
       Element::Damper("damper", "pivot", "bob", kDamping)},
      {}, {}, Space{2, {}});
  const NetworkRunResult run = RunFor(system, 1.0);
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  EXPECT_EQ(run.stats.final_time, 1.0);
}

TEST(SegmentLimit, ANodeRunningIntoAFixedViaPointEndsTheRunThere) {
  // a spring from the pivot over a fixed via point at (0.05, 0) to the bob at (0.1, 0), rest
  // length 0.05 m: along the line the bob oscillates about the via point, x = 0.05 +
  // 0.05 cos(w t), undamped, and the segment from the via point to the bob, 0.05 cos(w t),
  // reaches 1e-6 m at w t = acos(1e-6 / 0.05)
  Element spring = Element::Spring("spring", "pivot", "bob", kStiffness, 0.05);
  spring.via = {ViaPoint::Fixed({0.05, 0.0, 0.0})};
  const NetworkSystem system(
      {Node::Fixed("pivot", Coordinates{}), Node::Free("bob", kMass, Coordinates{0.1, 0.0, 0.0})},
      {spring}, {}, {}, Space{2, {}});
  const NetworkRunResult run = RunFor(system, 1.0);
  EXPECT_EQ(run.stats.status, RunStatus::kLimit) << run.stats.message;
  EXPECT_THAT(run.stats.message, HasSubstr("segment 1 of spring's path shortened to 1e-06 m"));
  const double w = std::sqrt(kStiffness / kMass);
  EXPECT_NEAR(run.stats.final_time, std::acos(NetworkSystem::kMinSegmentLength / 0.05) / w, 1e-9);
}

}  // namespace
}  // namespace musclesim
