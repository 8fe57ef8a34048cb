// The quintic Bezier corners of Millard's curves: where they start and end, their joins, the
// lines outside, and the corners refused (an S, a crossing outside the points).
#include "musclesim/model/quintic_bezier.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace musclesim {
namespace {

TEST(QuinticBezier, ACornerRunsFromItsFirstPointToItsLastWithTheirSlopes) {
  // from (0, 0) slope 0 to (1, 1) slope 2: the tangents cross at (0.5, 0)
  const SegmentedBezierCurve curve({MakeBezierCorner(0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 0.5)}, 0.0, 2.0);
  EXPECT_EQ(curve.Evaluate(0.0).value, 0.0);
  EXPECT_EQ(curve.Evaluate(1.0).value, 1.0);
  EXPECT_NEAR(curve.Evaluate(1e-9).slope, 0.0, 1e-6);
  EXPECT_NEAR(curve.Evaluate(1.0 - 1e-9).slope, 2.0, 1e-6);
  // outside, the lines of the end slopes
  EXPECT_EQ(curve.Evaluate(-3.0).value, 0.0);
  EXPECT_EQ(curve.Evaluate(2.0).value, 3.0);
  EXPECT_EQ(curve.Evaluate(2.0).slope, 2.0);
  // inside, below the chord and above the tangents' corner (convex)
  const double mid = curve.Evaluate(0.5).value;
  EXPECT_GT(mid, 0.0);
  EXPECT_LT(mid, 0.5);
}

TEST(QuinticBezier, CornersJoinWithoutAStepOrAKink) {
  const SegmentedBezierCurve curve({MakeBezierCorner(0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 0.6),
                                    MakeBezierCorner(1.0, 0.5, 1.0, 2.0, 1.0, 0.0, 0.6)},
                                   0.0, 0.0);
  for (const double h : {1e-6, 1e-8}) {
    // the slope there is 1: the values 2h apart, to rounding
    EXPECT_NEAR(curve.Evaluate(1.0 + h).value - curve.Evaluate(1.0 - h).value, 2.0 * h, 1e-12);
    EXPECT_NEAR(curve.Evaluate(1.0 - h).slope, curve.Evaluate(1.0 + h).slope, 1e3 * h);
  }
  EXPECT_EQ(curve.Evaluate(1.0).value, 0.5);
  EXPECT_NEAR(curve.Evaluate(1.0).slope, 1.0, 1e-14);
}

TEST(QuinticBezier, RefusesWhatIsNoCorner) {
  // an S: the tangents cross at (0.5, 1.5), between the points in x but farther from the first
  // than the points are apart
  EXPECT_THROW(MakeBezierCorner(0.0, 0.0, 3.0, 1.0, 1.0, -1.0, 0.5), std::invalid_argument);
  // a crossing left of both points: x(u) would turn back
  EXPECT_THROW(MakeBezierCorner(0.0, 0.0, -1.0, 1.0, 3.0, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(SegmentedBezierCurve({}, 0.0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace musclesim
