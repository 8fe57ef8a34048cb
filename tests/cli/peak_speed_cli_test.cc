// The peak speed of a run against v_max, on trajectories whose speeds are known by hand.
#include "musclesim/io/peak_speed.h"

#include <gtest/gtest.h>

namespace musclesim {
namespace {

std::vector<TrajectoryPoint> WithVelocities(const std::vector<double>& velocities) {
  std::vector<TrajectoryPoint> trajectory;
  double t = 0.0;
  for (double v : velocities) {
    TrajectoryPoint p{t, {}};
    p.sample.shortening_velocity = v;
    trajectory.push_back(p);
    t += 0.1;
  }
  return trajectory;
}

TEST(PeakSpeed, LengtheningCountsLikeShortening) {
  const PeakSpeed peak = FindPeakSpeed(WithVelocities({0.5, -2.5, 1.0, 0.0}), 2.0);
  EXPECT_EQ(peak.speed, 2.5);  // |-2.5|, the lengthening
  EXPECT_EQ(peak.v_max, 2.0);
  EXPECT_EQ(peak.ratio(), 1.25);
  EXPECT_TRUE(peak.beyond_v_max());
}

TEST(PeakSpeed, ReachingVmaxExactlyIsNotBeyond) {
  const PeakSpeed peak = FindPeakSpeed(WithVelocities({0.25, 1.0, -0.75}), 1.0);
  EXPECT_EQ(peak.speed, 1.0);
  EXPECT_EQ(peak.ratio(), 1.0);
  EXPECT_FALSE(peak.beyond_v_max());
}

TEST(PeakSpeed, EmptyTrajectoryHasNoSpeed) {
  const PeakSpeed peak = FindPeakSpeed({}, 1.0);
  EXPECT_EQ(peak.speed, 0.0);
  EXPECT_FALSE(peak.beyond_v_max());
}

}  // namespace
}  // namespace musclesim
