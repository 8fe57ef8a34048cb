#include "musclesim/model/degroote_conversion.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "musclesim/core/brent_minimum.h"
#include "musclesim/core/errors.h"
#include "musclesim/model/degroote2016.h"

namespace musclesim {

namespace {

constexpr int kSamples = 1001;  // per compared interval, evenly spaced

// f(x) - g(x) over [a, b], its largest magnitude and its root mean square.
template <typename F, typename G>
CurveDeparture Departure(double a, double b, F f, G g) {
  CurveDeparture out;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double x = a + (b - a) * i / (kSamples - 1);
    const double d = std::abs(f(x) - g(x));
    sum += d * d;
    if (d > out.largest) {
      out.largest = d;
      out.at = x;
    }
  }
  out.rms = std::sqrt(sum / kSamples);
  out.from = a;
  out.to = b;
  return out;
}

// De Groote's tendon, f_T = 0.2 (exp(ln 6 strain / strain_at_one) - 1)
double DeGrooteTendon(double strain, double strain_at_one) {
  return 0.2 * std::expm1(std::log(6.0) * strain / strain_at_one);
}

}  // namespace

DeGrooteConversion NearestDeGroote(const ComparedCurves& c) {
  DeGrooteConversion out;
  out.passive_fiber_strain_at_one_norm_force = c.passive_strain_at_one_norm_force;
  out.tendon_strain_at_one_norm_force = c.tendon_strain_at_one_norm_force;
  const auto active_at = [](double width) {
    return [width](double l) { return degroote2016::ActiveForceLength(l, width).value; };
  };
  out.active_force_width_scale =
      BrentMinimum(
          [&](double width) {
            return Departure(c.active_low, c.active_high, active_at(width), c.active).rms;
          },
          1.0, 10.0, 1e-6)
          .first;
  out.active =
      Departure(c.active_low, c.active_high, active_at(out.active_force_width_scale), c.active);
  const double e0 = c.passive_strain_at_one_norm_force;
  out.passive = Departure(
      c.passive_low, c.passive_high,
      [e0](double l) { return degroote2016::PassiveForceLength(l, e0).value; }, c.passive);
  const auto degroote_velocity = [](double v) { return degroote2016::ForceVelocity(v).value; };
  out.shortening = Departure(-1.0, 0.0, degroote_velocity, c.velocity);
  out.lengthening = Departure(0.0, 1.0, degroote_velocity, c.velocity);
  const double e_t = c.tendon_strain_at_one_norm_force;
  out.tendon = Departure(
      0.0, e_t, [e_t](double e) { return DeGrooteTendon(e, e_t); }, c.tendon);
  return out;
}

DeGrooteConversion NearestDeGroote(const MillardCurves& m) {
  // the curves are built once and shared by the comparisons' closures
  const auto active = std::make_shared<SegmentedBezierCurve>(MillardCurve(m.active));
  const auto velocity = std::make_shared<SegmentedBezierCurve>(MillardCurve(m.velocity));
  const auto passive = std::make_shared<SegmentedBezierCurve>(MillardCurve(m.passive));
  const auto tendon = std::make_shared<SegmentedBezierCurve>(MillardCurve(m.tendon));
  ComparedCurves c;
  c.active = [active](double l) { return active->Evaluate(l).value; };
  c.passive = [passive](double l) { return passive->Evaluate(l).value; };
  c.velocity = [velocity](double v) { return velocity->Evaluate(v).value; };
  c.tendon = [tendon](double e) { return tendon->Evaluate(1.0 + e).value; };
  c.active_low = m.active.min_norm_active_fiber_length;
  c.active_high = m.active.max_norm_active_fiber_length;
  c.passive_low = std::min(c.active_low, 1.0 + m.passive.strain_at_zero_force);
  c.passive_high = 1.0 + m.passive.strain_at_one_norm_force;
  c.passive_strain_at_one_norm_force = m.passive.strain_at_one_norm_force;
  c.tendon_strain_at_one_norm_force = m.tendon.strain_at_one_norm_force;
  return NearestDeGroote(c);
}

DeGrooteConversion NearestDeGroote(const ThelenCurves& t) {
  Validate(t);
  ComparedCurves c;
  c.active = [t](double l) { return thelen2003::ActiveForceLength(t, l); };
  c.passive = [t](double l) { return thelen2003::PassiveForceLength(t, l); };
  c.velocity = [t](double v) { return thelen2003::ForceVelocity(t, v); };
  c.tendon = [t](double e) { return thelen2003::TendonForceLength(t, e); };
  // where exp(-(l - 1)^2 / k) >= 0.01
  const double half_width = std::sqrt(t.KshapeActive * std::log(100.0));
  c.active_low = std::max(0.2, 1.0 - half_width);
  c.active_high = 1.0 + half_width;
  c.passive_low = c.active_low;
  c.passive_high = 1.0 + t.FmaxMuscleStrain;
  c.passive_strain_at_one_norm_force = t.FmaxMuscleStrain;
  c.tendon_strain_at_one_norm_force = t.FmaxTendonStrain;
  return NearestDeGroote(c);
}

}  // namespace musclesim
