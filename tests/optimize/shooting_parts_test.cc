// The pieces of the shooting program (src/optimize/shooting_parts.h) on their own: a linear
// segment's effort against Simpson's rule on a fine grid, its derivatives and a control
// value's df/dp against central differences of networks built with that value moved.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "optimize/flat_actuator.h"
#include "optimize/shooting_parts.h"

namespace musclesim {
namespace {

// integral over [0, 1] of (a + (b - a) s)^q by composite Simpson, 2000 panels
double SimpsonEffort(double a, double b, int q) {
  const int n = 2000;
  const auto f = [&](double s) { return std::pow(a + (b - a) * s, q); };
  double sum = f(0.0) + f(1.0);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(static_cast<double>(i) / n);
  return sum / (3.0 * n);
}

TEST(SegmentEffort, IsTheIntegralOfTheControlsPowerWithItsDerivatives) {
  const double h = 1e-6;
  for (const int q : {2, 3}) {
    for (const auto& [a, b] : std::vector<std::pair<double, double>>{
             {0.0, 1.0}, {0.3, 0.3}, {0.9, 0.1}, {0.25, 0.75}, {1.0, 0.0}}) {
      const Effort effort = SegmentEffort(a, b, q);
      EXPECT_NEAR(effort.value, SimpsonEffort(a, b, q), 1e-13) << q << " " << a << " " << b;
      const double by_start =
          (SegmentEffort(a + h, b, q).value - SegmentEffort(a - h, b, q).value) / (2.0 * h);
      const double by_end =
          (SegmentEffort(a, b + h, q).value - SegmentEffort(a, b - h, q).value) / (2.0 * h);
      EXPECT_NEAR(effort.by_start, by_start, 1e-8) << q << " " << a << " " << b;
      EXPECT_NEAR(effort.by_end, by_end, 1e-8) << q << " " << a << " " << b;
    }
  }
}

TEST(HatWeight, RisesLinearlyToItsEndAndTheTwoHatsSumToOne) {
  const double t0 = 0.2, t1 = 0.7;
  for (const double t : {0.2, 0.3, 0.45, 0.69, 0.7}) {
    const double rising = (t - t0) / (t1 - t0);
    EXPECT_NEAR(HatWeight(t, t0, t1, true), rising, 1e-15);
    EXPECT_NEAR(HatWeight(t, t0, t1, false) + HatWeight(t, t0, t1, true), 1.0, 1e-15);
  }
  EXPECT_EQ(HatWeight(0.1, t0, t1, true), 0.0);  // outside: clamped
  EXPECT_EQ(HatWeight(0.9, t0, t1, true), 1.0);
}

// The flat actuator's network with its activation linear from `start` at t0 to `end` at t1.
NetworkSystem WithControl(const Scenario& base, double t0, double t1, double start, double end) {
  Scenario s = base;
  s.elements[0].activation = Waveform::Table({{t0, start}, {t1, end}});
  return s.Build();
}

TEST(ControlValueDerivative, IsTheCentralDifferenceOfTheRightHandSideInTheValue) {
  const Scenario base = optimize_test::FlatActuatorOnALoad();
  ASSERT_EQ(base.elements[0].name, "muscle");
  const double t0 = 0.02, t1 = 0.06, start = 0.3, end = 0.6, h = 1e-6;
  const NetworkSystem system = WithControl(base, t0, t1, start, end);
  const std::vector<double> y = {0.097, -0.05};  // the mass's position and velocity
  NetworkScratch scratch;
  for (const bool at_end : {false, true}) {
    const ControlValueDerivative derivative(system, 0, t0, t1, at_end);
    for (const double t : {0.02, 0.035, 0.05, 0.06}) {
      std::vector<double> dfdp(2), plus(2), minus(2);
      derivative.RightHandSide(t, y.data(), dfdp.data(), scratch);
      const double up = at_end ? end + h : start + h, down = at_end ? end - h : start - h;
      WithControl(base, t0, t1, at_end ? start : up, at_end ? up : end)
          .RightHandSide(t, y.data(), plus.data());
      WithControl(base, t0, t1, at_end ? start : down, at_end ? down : end)
          .RightHandSide(t, y.data(), minus.data());
      for (std::size_t k = 0; k < 2; ++k) {
        const double difference = (plus[k] - minus[k]) / (2.0 * h);
        EXPECT_NEAR(dfdp[k], difference, 1e-6 * std::max(1.0, std::abs(difference)))
            << "t = " << t << ", row " << k << (at_end ? ", end value" : ", start value");
      }
      // the element's tension moves by dT/du times the hat, as the acceleration says
      NetworkSystem::ElementPartials partial;
      derivative.Elements(t, y.data(), &partial, scratch);
      EXPECT_NEAR(partial.total, -dfdp[1] * 0.1, 1e-9 * std::max(1.0, std::abs(partial.total)));
    }
  }
}

}  // namespace
}  // namespace musclesim
