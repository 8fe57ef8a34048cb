#include "musclesim/model/tension.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "musclesim/core/errors.h"
#include "support/canonical_actuator.h"
#include "support/numeric.h"

namespace musclesim {
namespace {

ModelParams Example() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {2.0, 30.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{0.05, 90.0, 0.097}, {0.03, 400.0, 0.104}}};
  p.velocity = {1.0, 3, 1e-3};
  return p;
}

// The canonical actuator of scenarios/*.yaml: three narrow Gaussians, the maximum of f
// inside L_opt, n = 3.
ModelParams Canonical() { return testing::CanonicalModel(); }

// T written out again from docs/model.md with plain std::exp and std::pow, sharing no code
// with the library: eq. 1 (section 2), eqs. 3-4 and 13 (section 3), eq. 12 regularised
// (section 4), eqs. 16-17 (section 5). The maximum of f over L_opt is found by brute force.
class ReferenceTension {
 public:
  explicit ReferenceTension(const ModelParams& p) : p_(p) {
    // a grid of 1e6 + 1 points over L_opt (h = 1e-8 m): where the maximum is interior the
    // grid misses it by h / 2 at most, and f by |f''| h^2 / 8 ~ (b / sigma) f h^2 / 8,
    // 3e-13 f for the largest b here (2.1e4); at an end of L_opt the grid hits it exactly
    const int cells = 1000000;
    const double l1 = p.active_length.optimal_min, l2 = p.active_length.optimal_max;
    for (int i = 0; i <= cells; ++i) {
      const double x = l1 + (l2 - l1) * i / cells;
      if (F(x) > peak_) {
        peak_ = F(x);
        argmax_ = x;
      }
    }
  }

  // psi_k(x) = a_k / sqrt(2 pi sigma) exp(-b_k (x - d_k)^2 / (2 sigma)), summed (eqs. 3-4)
  double F(double x) const {
    const double sigma = p_.active_length.sigma;
    double f = 0.0;
    for (const Gaussian& g : p_.active_length.gaussians) {
      f += g.amplitude / std::sqrt(2.0 * std::numbers::pi * sigma) *
           std::exp(-g.precision * (x - g.center) * (x - g.center) / (2.0 * sigma));
    }
    return f;
  }
  double LengthFactor(double x) const { return F(x) / peak_; }  // eq. 13
  // T_p (eq. 1)
  double Passive(double x) const {
    const PassiveParams& q = p_.passive;
    return x <= q.slack_length ? 0.0 : q.k_p * (std::exp(q.alpha * (x - q.slack_length)) - 1.0);
  }
  // g_eps (eq. 12 with phi_eps(v) = v (v^2 + eps^2)^((alpha - 1) / 2), alpha = 1 / n)
  double VelocityFactor(double v) const {
    const VelocityParams& q = p_.velocity;
    const double alpha = 1.0 / q.n;
    const double phi = v * std::pow(v * v + q.epsilon * q.epsilon, (alpha - 1.0) / 2.0);
    return 1.0 - phi / std::pow(q.v_max, alpha);
  }
  double Active(double x, double v, double u) const {  // eq. 16
    return u * p_.f_iso * LengthFactor(x) * VelocityFactor(v);
  }
  double Total(double x, double v, double u) const {  // eq. 17
    return Passive(x) + Active(x, v, u);
  }
  double argmax() const { return argmax_; }

 private:
  ModelParams p_;
  double peak_ = -INFINITY;
  double argmax_ = 0.0;
};

TEST(Tension, EqualsTheModelWrittenOutFromDocsModelMd) {
  ModelParams linear = Example();
  linear.velocity = {0.8, 1, 0.3};  // n = 1: eps changes nothing (section 4)
  ModelParams scaled = Canonical();
  scaled.active_length.sigma = 2.0;  // b_k / sigma halved: wider components
  for (const ModelParams& params : {Example(), Canonical(), linear, scaled}) {
    const TensionModel model(params);
    const ReferenceTension reference(params);
    for (double x : {0.06, 0.08, 0.095, 0.1, 0.105, 0.11, 0.13}) {  // below, on, above L_opt and x0
      for (double v : {-0.5, -1e-3, 0.0, 2e-4, 0.3, 1.2}) {
        for (double u : {0.0, 0.6, 1.0}) {
          const TensionSample s = model.Evaluate(x, v, u);
          const double scale = params.f_iso + std::abs(reference.Passive(x));
          // the two differ by rounding in a handful of exp and pow (~1e-15 relative) and by
          // the brute-force peak (3e-13 relative, see ReferenceTension): 1e-11 of the scale
          EXPECT_NEAR(s.passive, reference.Passive(x), 1e-11 * scale) << x;
          EXPECT_NEAR(s.active, reference.Active(x, v, u), 1e-11 * scale)
              << x << " " << v << " " << u;
          EXPECT_NEAR(s.total, reference.Total(x, v, u), 1e-11 * scale)
              << x << " " << v << " " << u;
          // dT/du = f_iso f_L g (section 5)
          EXPECT_NEAR(s.d_activation, reference.Active(x, v, 1.0), 1e-11 * scale);
        }
      }
    }
  }
}

TEST(Tension, IsometricAtOptimalLengthGivesActivationTimesFiso) {
  // at the brute-force maximum of f over L_opt, f_L = 1 to within the grid's 3e-13; the
  // library's exact maximum lies within half a grid cell of it, or, when rounding in f
  // (1e-16 relative) picks a neighbouring point, 1.5 cells (1.5e-8 m)
  for (const ModelParams& params : {Example(), Canonical()}) {
    const TensionModel model(params);
    const ReferenceTension reference(params);
    EXPECT_NEAR(model.active_length().optimal_length(), reference.argmax(), 1.5e-8);
    for (double u : {0.0, 0.25, 1.0}) {
      EXPECT_NEAR(model.Evaluate(reference.argmax(), 0.0, u).active, u * params.f_iso,
                  1e-11 * params.f_iso);
    }
  }
}

TEST(Tension, DerivativesMatchFiniteDifferences) {
  const TensionModel model(Example());
  for (double x : {0.09, 0.1, 0.11}) {  // away from the slack kink at 0.105
    for (double v : {-0.4, -0.002, 0.0, 0.001, 0.5}) {
      const double u = 0.7;
      const TensionSample s = model.Evaluate(x, v, u);
      const double by_x = testing::CentralDifference(
          [&](double y) { return model.Evaluate(y, v, u).total; }, x, 1e-7);
      const double by_v = testing::CentralDifference(
          [&](double w) { return model.Evaluate(x, w, u).total; }, v, 1e-8);
      const double by_u = testing::CentralDifference(
          [&](double a) { return model.Evaluate(x, v, a).total; }, u, 1e-6);
      // central differences err by truncation h^2 d3T / 6 and rounding eps_mach T / h.
      // In x (h = 1e-7 m): d3T ~ f_iso (b / sigma)^(3/2) <= 1e6 N/m^3 gives 2e-9 N/m,
      // rounding 1e-16 x 100 N / 1e-7 m = 1e-7 N/m, against |dT/dx| of 6 to 300 N/m.
      // In v (h = 1e-8 m/s): near v = 0, d3T ~ u f_iso eps^(1/n - 3) = 7e9 gives 1e-7,
      // rounding 1e-6, against |dT/dv| of 36 to 7000 N s/m. In u (h = 1e-6) T is linear:
      // rounding alone, 1e-16 x 100 N / 1e-6 = 1e-8 N. 1e-5 and 1e-7 relative (or absolute
      // below 1) cover these with a margin of ten or more.
      EXPECT_NEAR(s.d_length, by_x, 1e-5 * std::max(1.0, std::abs(by_x))) << x << " " << v;
      EXPECT_NEAR(s.d_velocity, by_v, 1e-5 * std::max(1.0, std::abs(by_v))) << x << " " << v;
      EXPECT_NEAR(s.d_activation, by_u, 1e-7 * std::max(1.0, std::abs(by_u)));
    }
  }
}

TEST(Tension, ValidationNamesTheBlock) {
  ModelParams p = Example();
  p.velocity.n = 0;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("velocity.n = 0")));
  p = Example();
  p.f_iso = -1;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(::testing::HasSubstr("f_iso = -1")));
  p = Example();
  p.active_length.gaussians[0].precision = 0;
  EXPECT_THAT([&] { TensionModel m(p); },
              ::testing::ThrowsMessage<ParameterError>(
                  ::testing::HasSubstr("active_length.gaussians[0].width = 0")));
}

}  // namespace
}  // namespace musclesim
