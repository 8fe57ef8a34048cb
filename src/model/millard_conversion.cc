#include "musclesim/model/millard_conversion.h"

#include <cmath>

#include "musclesim/core/brent_minimum.h"
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
    if (d > out.largest) out = {d, x, 0.0};
  }
  out.rms = std::sqrt(sum / kSamples);
  return out;
}

// De Groote's tendon, f_T = 0.2 (exp(ln 6 strain / strain_at_one) - 1)
double DeGrooteTendon(double strain, double strain_at_one) {
  return 0.2 * std::expm1(std::log(6.0) * strain / strain_at_one);
}

}  // namespace

DeGrooteConversion NearestDeGroote(const MillardCurves& curves) {
  const SegmentedBezierCurve active = MillardCurve(curves.active);
  const SegmentedBezierCurve velocity = MillardCurve(curves.velocity);
  const SegmentedBezierCurve passive = MillardCurve(curves.passive);
  const SegmentedBezierCurve tendon = MillardCurve(curves.tendon);
  DeGrooteConversion out;
  out.passive_fiber_strain_at_one_norm_force = curves.passive.strain_at_one_norm_force;
  out.tendon_strain_at_one_norm_force = curves.tendon.strain_at_one_norm_force;

  const double low = curves.active.min_norm_active_fiber_length;
  const double high = curves.active.max_norm_active_fiber_length;
  const auto millard_active = [&](double l) { return active.Evaluate(l).value; };
  const auto active_at = [](double width) {
    return [width](double l) { return degroote2016::ActiveForceLength(l, width).value; };
  };
  out.active_force_width_scale =
      BrentMinimum(
          [&](double width) { return Departure(low, high, active_at(width), millard_active).rms; },
          1.0, 10.0, 1e-6)
          .first;
  out.active = Departure(low, high, active_at(out.active_force_width_scale), millard_active);

  const double strain_zero = curves.passive.strain_at_zero_force;
  const double strain_one = curves.passive.strain_at_one_norm_force;
  out.passive = Departure(
      std::min(1.0, 1.0 + strain_zero), 1.0 + strain_one,
      [&](double l) { return degroote2016::PassiveForceLength(l, strain_one).value; },
      [&](double l) { return passive.Evaluate(l).value; });
  out.velocity = Departure(
      -1.0, 1.0, [](double v) { return degroote2016::ForceVelocity(v).value; },
      [&](double v) { return velocity.Evaluate(v).value; });
  const double tendon_strain = curves.tendon.strain_at_one_norm_force;
  out.tendon = Departure(
      0.0, tendon_strain, [&](double e) { return DeGrooteTendon(e, tendon_strain); },
      [&](double e) { return tendon.Evaluate(1.0 + e).value; });
  return out;
}

}  // namespace musclesim
