// Thelen 2003's curves against OpenSim 4.6's Thelen2003Muscle (bench/peers/reference/
// thelen2003_curves.csv: the muscle's multipliers and tendon force read off realised states,
// bench/peers/reference_curves.py), their rules, and their conversion to De Groote's family.
#include "musclesim/model/thelen2003.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/model/degroote2016.h"
#include "musclesim/model/degroote_conversion.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// reference_curves.py's THELEN_SETS, in its order
ThelenCurves ReferenceSet(int set) {
  ThelenCurves c;
  if (set == 1) c = {0.05, 0.5, 0.3, 4.0, 0.3, 1.6, 0.9};
  return c;
}

double Curve(const ThelenCurves& c, int curve, double x) {
  switch (curve) {
    case 0: return thelen2003::ActiveForceLength(c, x);
    case 1: return thelen2003::PassiveForceLength(c, x);
    case 2: return thelen2003::ForceVelocity(c, x);
    default: return thelen2003::TendonForceLength(c, x);
  }
}

TEST(Thelen2003Curves, AreOpenSimsThelen2003Muscle) {
  const testing::PeerTable table = testing::ReadPeerTable("thelen2003_curves.csv");
  std::map<int, int> rows_per_curve;
  for (std::size_t k = 0; k < table.at("set").size(); ++k) {
    const int set = static_cast<int>(table.at("set")[k]);
    const int curve = static_cast<int>(table.at("curve")[k]);
    const double x = table.at("x")[k], expected = table.at("value")[k];
    // the force-velocity pairs are OpenSim's velocity for a force (Thelen's v(f)), inverted
    // here in closed form: agreement to the rounding of that velocity times the curve's slope
    const double tolerance = curve == 2 ? 1e-10 : 1e-12;
    EXPECT_NEAR(Curve(ReferenceSet(set), curve, x), expected, tolerance)
        << "set " << set << " curve " << curve << " at " << x;
    ++rows_per_curve[curve];
  }
  ASSERT_EQ(rows_per_curve.size(), 4u);
  for (const auto& [curve, rows] : rows_per_curve) EXPECT_GE(rows, 300) << curve;
}

TEST(Thelen2003Curves, ForceVelocityIsContinuousWhereItsLineBegins) {
  for (int set = 0; set < 2; ++set) {
    const ThelenCurves c = ReferenceSet(set);
    const double k = (2.0 + 2.0 / c.Af) / (c.Flen - 1.0);
    const double f_line = c.fv_linear_extrap_threshold * c.Flen;
    const double v_line = (f_line - 1.0) / (k * (c.Flen - f_line));
    EXPECT_NEAR(thelen2003::ForceVelocity(c, v_line * (1 - 1e-12)), f_line, 1e-9) << set;
    EXPECT_NEAR(thelen2003::ForceVelocity(c, v_line * (1 + 1e-12)), f_line, 1e-9) << set;
    EXPECT_EQ(thelen2003::ForceVelocity(c, 0.0), 1.0);
    EXPECT_EQ(thelen2003::ForceVelocity(c, -1.0), 0.0);
    EXPECT_NEAR(thelen2003::TendonForceLength(c, c.FmaxTendonStrain), 1.0, 1e-14);
    EXPECT_NEAR(thelen2003::PassiveForceLength(c, 1.0 + c.FmaxMuscleStrain), 1.0, 1e-14);
  }
}

TEST(Thelen2003Curves, RefuseWhatCannotMakeTheCurvesNamingTheProperty) {
  const auto refusal = [](ThelenCurves c) -> std::string {
    try {
      Validate(c);
    } catch (const ParameterError& e) {
      return e.path() + " = " + e.value() + ": " + e.rule();
    }
    return "accepted";
  };
  ThelenCurves c;
  c.Flen = 1.0;
  EXPECT_THAT(refusal(c), HasSubstr("Flen = 1: must be above 1"));
  c = {};
  c.fv_linear_extrap_threshold = 0.5;  // below 1 / Flen: the line would start shortening
  EXPECT_THAT(refusal(c), HasSubstr("fv_linear_extrap_threshold = 0.5: must be below 1"));
  c = {};
  c.KshapeActive = 0.0;
  EXPECT_THAT(refusal(c), HasSubstr("KshapeActive = 0: must be > 0"));
  c = {};
  c.FmaxTendonStrain = -0.01;
  EXPECT_THAT(refusal(c), HasSubstr("FmaxTendonStrain = -0.01: must be > 0"));
  EXPECT_EQ(refusal(ThelenCurves{}), "accepted");
}

TEST(ThelenToDeGroote, KeepsTheStrainsAndFitsTheActiveWidth) {
  const ThelenCurves c;
  const DeGrooteConversion out = NearestDeGroote(c);
  EXPECT_EQ(out.passive_fiber_strain_at_one_norm_force, 0.6);
  EXPECT_EQ(out.tendon_strain_at_one_norm_force, 0.04);
  // over the same interval, the chosen width beats its neighbours
  const double low = out.active.from, high = out.active.to;
  EXPECT_NEAR(high, 1.0 + std::sqrt(0.45 * std::log(100.0)), 1e-12);
  const auto rms = [&](double width) {
    double sum = 0.0;
    const int n = 4001;
    for (int i = 0; i < n; ++i) {
      const double l = low + (high - low) * i / (n - 1);
      const double d =
          degroote2016::ActiveForceLength(l, width).value - thelen2003::ActiveForceLength(c, l);
      sum += d * d;
    }
    return std::sqrt(sum / n);
  };
  const double w = out.active_force_width_scale;
  EXPECT_LT(rms(w), rms(w - 1e-3));
  EXPECT_LT(rms(w), rms(w + 1e-3));
  // at full lengthening, by hand from Thelen's eqs. 6-7 at OpenSim's defaults (Af 0.25,
  // Flen 1.4, the line from 0.95 Flen = 1.33): k = (2 + 2 / Af) / (Flen - 1) = 25,
  // b = k (Flen - 1.33) = 1.75, the line from v~ = 0.33 / b with dv~/df = 1 / b + k 0.33 / b^2
  const double b = 1.75, v_line = 0.33 / b, dv_df = 1.0 / b + 25.0 * 0.33 / (b * b);
  const double thelen_at_one = 1.33 + (1.0 - v_line) / dv_df;
  EXPECT_NEAR(thelen2003::ForceVelocity(c, 1.0), thelen_at_one, 1e-14);
  const double at_one = degroote2016::ForceVelocity(1.0).value - thelen_at_one;  // about 0.215
  // the grid holds v~ = 1: the largest is at least that, and near it (the curves part there)
  EXPECT_GE(out.lengthening.largest, at_one);
  EXPECT_LT(out.lengthening.largest, at_one + 1e-3);
  EXPECT_GT(out.lengthening.largest, 0.1);
}

}  // namespace
}  // namespace musclesim
