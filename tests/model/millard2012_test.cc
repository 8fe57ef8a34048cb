// Millard 2012's curves against OpenSim 4.6's own (bench/peers/reference/
// millard2012_curves.csv, written by bench/peers/reference_curves.py from each curve class's
// calcValue and calcDerivative), their rules, and the conversion to De Groote's family
// against departures computed here from the curves' closed forms.
#include "musclesim/model/millard2012.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/model/degroote2016.h"
#include "musclesim/model/degroote_conversion.h"
#include "support/numeric.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// the parameter sets of reference_curves.py's MILLARD_SETS, in its order
MillardCurves ReferenceSet(int set) {
  MillardCurves c;
  if (set == 1) c.active.minimum_value = 0.0;
  if (set == 2) {
    c.active = {0.5, 0.8, 1.7, 0.6, 0.05};
    c.velocity = {0.1, 0.3, 4.0, 0.05, 0.2, 1.6, 0.3, 0.7};
    c.passive = {0.1, 0.5, 0.5, 5.0, 0.4};
    c.tendon = {0.06, 30.0, 0.5, 0.8};
  }
  return c;
}

SegmentedBezierCurve Curve(const MillardCurves& c, int curve) {
  switch (curve) {
    case 0: return MillardCurve(c.active);
    case 1: return MillardCurve(c.velocity);
    case 2: return MillardCurve(c.passive);
    default: return MillardCurve(c.tendon);
  }
}

TEST(Millard2012Curves, AreOpenSimsWithTheirSlopesInsideAndOutsideTheirCorners) {
  const testing::PeerTable table = testing::ReadPeerTable("millard2012_curves.csv");
  const std::vector<double>& set = table.at("set");
  ASSERT_GT(set.size(), 1000u);
  std::map<int, int> rows_per_set;
  for (std::size_t k = 0; k < set.size(); ++k) {
    const int s = static_cast<int>(set[k]), curve = static_cast<int>(table.at("curve")[k]);
    const double x = table.at("x")[k];
    const CurvePoint point = Curve(ReferenceSet(s), curve).Evaluate(x);
    // OpenSim solves x(u) = x by Newton's method to 1e-14 or so; slopes divide two
    // polynomials' derivatives
    EXPECT_NEAR(point.value, table.at("value")[k], 1e-12) << s << " " << curve << " " << x;
    EXPECT_NEAR(point.slope, table.at("slope")[k], 1e-9 * std::max(1.0, std::abs(point.slope)))
        << s << " " << curve << " " << x;
    ++rows_per_set[s];
  }
  EXPECT_EQ(rows_per_set.size(), 3u);
}

TEST(Millard2012Curves, SlopesAreTheValuesDerivatives) {
  const MillardCurves c = ReferenceSet(2);
  for (int curve = 0; curve < 4; ++curve) {
    const SegmentedBezierCurve f = Curve(c, curve);
    for (int i = 1; i < 100; ++i) {
      const double x = f.first_x() + (f.last_x() - f.first_x()) * i / 100.0;
      const double fd =
          testing::CentralDifference([&](double y) { return f.Evaluate(y).value; }, x);
      EXPECT_NEAR(f.Evaluate(x).slope, fd, 1e-6 * std::max(1.0, std::abs(fd))) << curve << " " << x;
    }
  }
}

TEST(Millard2012Curves, PassThroughThePointsTheirPropertiesName) {
  const MillardCurves c = ReferenceSet(2);
  EXPECT_NEAR(MillardCurve(c.active).Evaluate(1.0).value, 1.0, 1e-15);
  EXPECT_NEAR(MillardCurve(c.active).Evaluate(0.5).value, 0.05, 1e-15);  // the floor
  EXPECT_NEAR(MillardCurve(c.velocity).Evaluate(0.0).value, 1.0, 1e-15);
  EXPECT_NEAR(MillardCurve(c.velocity).Evaluate(0.0).slope, 4.0, 1e-12);
  EXPECT_NEAR(MillardCurve(c.velocity).Evaluate(1.0).value, 1.6, 1e-15);
  EXPECT_NEAR(MillardCurve(c.passive).Evaluate(1.5).value, 1.0, 1e-15);
  EXPECT_NEAR(MillardCurve(c.passive).Evaluate(1.5).slope, 5.0, 1e-12);
  EXPECT_NEAR(MillardCurve(c.passive).Evaluate(1.1).value, 0.0, 1e-15);
  EXPECT_NEAR(MillardCurve(c.tendon).Evaluate(1.06).value, 1.0, 1e-14);  // on its line
  EXPECT_NEAR(MillardCurve(c.tendon).Evaluate(1.2).slope, 30.0, 1e-12);  // linear past the toe
}

std::string Refusal(const MillardCurves& c, int curve) {
  try {
    Curve(c, curve);
  } catch (const ParameterError& e) {
    return e.path() + " = " + e.value() + ": " + e.rule();
  }
  return "accepted";
}

TEST(Millard2012Curves, RefuseWhatOpenSimRefusesNamingTheProperty) {
  MillardCurves c;
  c.active.shallow_ascending_slope = 4.0;  // the plateau would rise above 1
  EXPECT_THAT(Refusal(c, 0), HasSubstr("shallow_ascending_slope = 4: must be >= 0 and below"));
  c = {};
  c.active.transition_norm_fiber_length = 0.4;
  EXPECT_THAT(Refusal(c, 0), HasSubstr("transition_norm_fiber_length = 0.4: must exceed"));
  c = {};
  c.velocity.max_eccentric_velocity_force_multiplier = 1.0;
  EXPECT_THAT(Refusal(c, 1),
              HasSubstr("max_eccentric_velocity_force_multiplier = 1: must be above 1"));
  c = {};
  c.velocity.concentric_slope_near_vmax = 0.0;
  EXPECT_THAT(Refusal(c, 1), HasSubstr("concentric_slope_near_vmax = 0"));
  c = {};
  c.passive.stiffness_at_one_norm_force = 4.0;  // one of three optional properties
  EXPECT_THAT(
      Refusal(c, 2),
      HasSubstr(
          "stiffness_at_one_norm_force = 4: is one of the optional stiffness_at_low_force, "));
  c = {};
  c.passive = {0.0, 0.5, 0.5, 1.5, 0.5};  // stiffness at one norm force below 1 / 0.5
  EXPECT_THAT(Refusal(c, 2), HasSubstr("stiffness_at_one_norm_force = 1.5: must exceed"));
  c = {};
  c.tendon.strain_at_one_norm_force = 0.0;
  EXPECT_THAT(Refusal(c, 3), HasSubstr("strain_at_one_norm_force = 0: must be > 0"));
  c = {};
  c.tendon.norm_force_at_toe_end = 1.0;
  c.tendon.stiffness_at_one_norm_force = 30.0;
  c.tendon.curviness = 0.5;
  EXPECT_THAT(Refusal(c, 3), HasSubstr("norm_force_at_toe_end = 1: must be in (0, 1)"));
}

// The root mean square and largest |f - g| on 4001 points: finer than the conversion's grid.
template <typename F, typename G>
std::pair<double, double> Compare(double a, double b, F f, G g) {
  double sum = 0.0, largest = 0.0;
  const int n = 4001;
  for (int i = 0; i < n; ++i) {
    const double x = a + (b - a) * i / (n - 1), d = std::abs(f(x) - g(x));
    sum += d * d;
    largest = std::max(largest, d);
  }
  return {std::sqrt(sum / n), largest};
}

TEST(MillardToDeGroote, KeepsTheStrainsAndWidensTheActiveCurveToItsLeastSquares) {
  const MillardCurves c = ReferenceSet(2);
  const DeGrooteConversion out = NearestDeGroote(c);
  EXPECT_EQ(out.passive_fiber_strain_at_one_norm_force, 0.5);
  EXPECT_EQ(out.tendon_strain_at_one_norm_force, 0.06);
  const SegmentedBezierCurve active = MillardCurve(c.active);
  const auto rms_at = [&](double width) {
    return Compare(
               0.5, 1.7, [&](double l) { return degroote2016::ActiveForceLength(l, width).value; },
               [&](double l) { return active.Evaluate(l).value; })
        .first;
  };
  const double w = out.active_force_width_scale;
  ASSERT_GT(w, 1.0);
  // a minimum: both neighbours worse
  EXPECT_LT(rms_at(w), rms_at(w - 1e-3));
  EXPECT_LT(rms_at(w), rms_at(w + 1e-3));
  EXPECT_NEAR(out.active.rms, rms_at(w), 1e-3 * rms_at(w));

  // the lengthening departure is largest at full lengthening: De Groote's plateau
  // (d1 asinh(d2 + d3) + d4 at v~ = 1, about 1.79) against Millard's 1.6
  const double degroote_at_one = degroote2016::ForceVelocity(1.0).value;
  EXPECT_NEAR(out.lengthening.largest, degroote_at_one - 1.6, 1e-12);
  EXPECT_EQ(out.lengthening.at, 1.0);
  const SegmentedBezierCurve tendon = MillardCurve(c.tendon);
  const auto [tendon_rms, tendon_largest] = Compare(
      0.0, 0.06, [](double e) { return 0.2 * std::expm1(std::log(6.0) * e / 0.06); },
      [&](double e) { return tendon.Evaluate(1.0 + e).value; });
  EXPECT_NEAR(out.tendon.largest, tendon_largest, 1e-5);
  EXPECT_NEAR(out.tendon.rms, tendon_rms, 1e-3 * tendon_rms);
}

}  // namespace
}  // namespace musclesim
