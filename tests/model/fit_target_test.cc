#include "musclesim/model/fit_target.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "musclesim/core/errors.h"
#include "support/numeric.h"

namespace musclesim {
namespace {

struct Case {
  Eigen::VectorXd a;
  GaussianShapes shapes;
  double sigma;
};

double Psi(const Case& c, double x) {
  double f = 0.0;
  for (Eigen::Index k = 0; k < c.a.size(); ++k) {
    const double dx = x - c.shapes.centers(k);
    f += c.a(k) / std::sqrt(2.0 * std::numbers::pi * c.sigma) *
         std::exp(-c.shapes.precisions(k) * dx * dx / (2.0 * c.sigma));
  }
  return f;
}

// Piecewise-linear target evaluated directly: zero outside the vertices.
double Polygon(const std::vector<TargetPoint>& v, double x) {
  if (x < v.front().x || x > v.back().x) return 0.0;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    if (x <= v[i + 1].x) {
      return v[i].y + (v[i + 1].y - v[i].y) * (x - v[i].x) / (v[i + 1].x - v[i].x);
    }
  }
  return 0.0;
}

// Random shapes around [0.09, 0.11]; sigma varies so that only b / sigma matters.
Case RandomCase(std::mt19937& rng) {
  std::uniform_real_distribution<double> amplitude(-1.0, 2.5), center(0.085, 0.115),
      log_spread(std::log(1e-3), std::log(2e-2)), log_sigma(std::log(0.1), std::log(10.0));
  const int m = 1 + static_cast<int>(rng() % 4);
  Case c{Eigen::VectorXd(m), {Eigen::VectorXd(m), Eigen::VectorXd(m)}, std::exp(log_sigma(rng))};
  for (int k = 0; k < m; ++k) {
    const double spread = std::exp(log_spread(rng));
    c.a(k) = amplitude(rng) * 0.01;
    c.shapes.precisions(k) = c.sigma / (spread * spread);
    c.shapes.centers(k) = center(rng);
  }
  return c;
}

std::vector<TargetPoint> RandomPolygon(std::mt19937& rng) {
  std::uniform_real_distribution<double> gap(0.002, 0.008), height(0.0, 1.2);
  std::vector<TargetPoint> v;
  double x = 0.088;
  const int n = 2 + static_cast<int>(rng() % 5);
  for (int i = 0; i < n; ++i) {
    v.push_back({x, height(rng)});
    x += gap(rng);
  }
  return v;
}

// integral of (f - target)^2 over the real line by adaptive quadrature: outside
// [lo, hi] every Gaussian is below exp(-40^2 / 2) of its peak
double QuadratureCost(const Case& c, const std::vector<TargetPoint>& polygon) {
  double spread = 0.0;
  std::vector<double> breaks;
  for (Eigen::Index k = 0; k < c.a.size(); ++k) {
    spread = std::max(spread, std::sqrt(c.sigma / c.shapes.precisions(k)));
    breaks.push_back(c.shapes.centers(k));
  }
  for (const TargetPoint& p : polygon) breaks.push_back(p.x);
  const double lo = *std::min_element(breaks.begin(), breaks.end()) - 40 * spread;
  const double hi = *std::max_element(breaks.begin(), breaks.end()) + 40 * spread;
  return testing::Integrate(
      [&](double x) {
        const double r = Psi(c, x) - Polygon(polygon, x);
        return r * r;
      },
      lo, hi, breaks, 1e-17);
}

// The closed-form cost against quadrature for 40 random cases, each with the vertices
// `make_vertices` draws.
template <typename MakeVertices>
void ExpectCostEqualsQuadrature(unsigned seed, MakeVertices make_vertices) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 40; ++trial) {
    const Case c = RandomCase(rng);
    const std::vector<TargetPoint> vertices = make_vertices(rng);
    const auto target = MakePiecewiseLinearTarget(vertices, c.sigma);
    const double quadrature = QuadratureCost(c, vertices);
    // 1e-10 relative: the bar; quadrature is converged far below it
    EXPECT_NEAR(target->Cost(c.a, c.shapes, nullptr), quadrature, 1e-10 * quadrature)
        << "trial " << trial;
  }
}

TEST(FitTarget, IndicatorCostEqualsQuadrature) {
  ExpectCostEqualsQuadrature(1, [](std::mt19937&) {
    return std::vector<TargetPoint>{{0.095, 1.0}, {0.105, 1.0}};
  });
}

TEST(FitTarget, PolygonCostEqualsQuadrature) { ExpectCostEqualsQuadrature(2, RandomPolygon); }

TEST(FitTarget, KindNamesReadBackAndUnknownNamesListThemAll) {
  for (const char* name : {"indicator", "polygon", "samples", "preset"}) {
    EXPECT_EQ(ToString(ParseFitTargetKind(name)), name);
  }
  try {
    ParseFitTargetKind("circle");
    ADD_FAILURE() << "circle accepted";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "target = circle: must be one of indicator, polygon, samples, preset");
  }
}

TEST(FitTarget, SampleCostEqualsDirectSum) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(0.08, 0.12), y(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const Case c = RandomCase(rng);
    std::vector<TargetPoint> samples(5 + rng() % 20);
    for (TargetPoint& s : samples) s = {x(rng), y(rng)};
    double direct = 0.0;
    for (const TargetPoint& s : samples) direct += (Psi(c, s.x) - s.y) * (Psi(c, s.x) - s.y);
    const auto target = MakeSampleTarget(samples, c.sigma);
    EXPECT_NEAR(target->Cost(c.a, c.shapes, nullptr), direct, 1e-12 * direct);
  }
}

TEST(FitTarget, NormSquaredIsTheTargetIntegral) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<TargetPoint> polygon = RandomPolygon(rng);
    const double quadrature =
        testing::Integrate([&](double x) { return Polygon(polygon, x) * Polygon(polygon, x); },
                           polygon.front().x, polygon.back().x, {}, 1e-18);
    EXPECT_NEAR(MakePiecewiseLinearTarget(polygon, 1.0)->NormSquared(), quadrature,
                1e-12 * quadrature);
  }
}

// Every component of the closed-form gradient against a central difference of the cost.
void ExpectGradientMatches(const FitTarget& target, Case c) {
  CostGradient g;
  target.Cost(c.a, c.shapes, &g);
  const auto check = [&](Eigen::VectorXd& param, const Eigen::VectorXd& analytic,
                         const char* name) {
    for (Eigen::Index k = 0; k < param.size(); ++k) {
      const double saved = param(k);
      const double h = 1e-6 * std::max(std::abs(saved), 1e-3);
      param(k) = saved + h;
      const double up = target.Cost(c.a, c.shapes, nullptr);
      param(k) = saved - h;
      const double down = target.Cost(c.a, c.shapes, nullptr);
      param(k) = saved;
      const double numeric = (up - down) / (2 * h);
      // truncation O(h^2) and rounding O(eps * N / h): 1e-5 of the gradient's scale
      const double scale = std::max({std::abs(numeric), std::abs(analytic(k)),
                                     target.Cost(c.a, c.shapes, nullptr) / std::abs(saved)});
      EXPECT_NEAR(analytic(k), numeric, 1e-5 * scale) << name << "[" << k << "]";
    }
  };
  check(c.a, g.amplitudes, "amplitude");
  check(c.shapes.precisions, g.precisions, "precision");
  check(c.shapes.centers, g.centers, "center");
}

TEST(FitTarget, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.08, 0.12), y(0.0, 1.0);
  for (int trial = 0; trial < 15; ++trial) {
    const Case c = RandomCase(rng);
    ExpectGradientMatches(*MakePiecewiseLinearTarget({{0.095, 1.0}, {0.105, 1.0}}, c.sigma), c);
    ExpectGradientMatches(*MakePiecewiseLinearTarget(RandomPolygon(rng), c.sigma), c);
    std::vector<TargetPoint> samples(12);
    for (TargetPoint& s : samples) s = {x(rng), y(rng)};
    ExpectGradientMatches(*MakeSampleTarget(samples, c.sigma), c);
  }
}

// --- preset targets ----------------------------------------------------------------------

// A random sum of Gaussians around a preset scaled to l_opt, widths from a fiftieth to twice
// l_opt (narrower than any panel of the target's quadrature, and wider than its support).
Case RandomPresetCase(std::mt19937& rng, double l_opt) {
  std::uniform_real_distribution<double> amplitude(-0.5, 1.5), center(0.3, 1.9),
      log_spread(std::log(0.02), std::log(2.0)), log_sigma(std::log(0.1), std::log(10.0));
  const int m = 1 + static_cast<int>(rng() % 4);
  Case c{Eigen::VectorXd(m), {Eigen::VectorXd(m), Eigen::VectorXd(m)}, std::exp(log_sigma(rng))};
  for (int k = 0; k < m; ++k) {
    const double spread = std::exp(log_spread(rng)) * l_opt;
    c.a(k) = amplitude(rng) * l_opt;
    c.shapes.precisions(k) = c.sigma / (spread * spread);
    c.shapes.centers(k) = center(rng) * l_opt;
  }
  return c;
}

// integral of (f - preset(x / l_opt))^2 by adaptive Simpson, split at the preset's breaks and
// the centres, over the support widened by 12 spreads of the widest Gaussian (beyond, each
// Gaussian is below e^-72 of its peak); to 1e-13 l_opt, where the cost is of order l_opt
double PresetQuadratureCost(const Case& c, ForceLengthPreset preset, double l_opt) {
  std::vector<double> breaks;
  double spread = 0.0;
  for (double s : PiecesOf(preset).breaks) breaks.push_back(s * l_opt);
  for (Eigen::Index k = 0; k < c.a.size(); ++k) {
    spread = std::max(spread, std::sqrt(c.sigma / c.shapes.precisions(k)));
    breaks.push_back(c.shapes.centers(k));
  }
  const double lo = *std::min_element(breaks.begin(), breaks.end()) - 12 * spread;
  const double hi = *std::max_element(breaks.begin(), breaks.end()) + 12 * spread;
  return testing::Integrate(
      [&](double x) {
        const double r = Psi(c, x) - EvaluatePreset(preset, x / l_opt);
        return r * r;
      },
      lo, hi, breaks, 1e-13 * l_opt, 64);
}

TEST(FitTarget, PresetCostEqualsQuadrature) {
  std::mt19937 rng(6);
  for (const ForceLengthPreset preset : AllForceLengthPresets()) {
    for (const double l_opt : {1.0, 0.062}) {
      for (int trial = 0; trial < 8; ++trial) {
        const Case c = RandomPresetCase(rng, l_opt);
        const auto target = MakePresetTarget(preset, l_opt, c.sigma);
        const double quadrature = PresetQuadratureCost(c, preset, l_opt);
        // 1e-10 relative, as for the polygon: Gauss-Legendre and Simpson are both converged
        // far below it
        EXPECT_NEAR(target->Cost(c.a, c.shapes, nullptr), quadrature, 1e-10 * quadrature)
            << ToString(preset) << " l_opt " << l_opt << " trial " << trial;
      }
    }
  }
}

TEST(FitTarget, PresetNormSquaredScalesWithTheOptimalLength) {
  for (const ForceLengthPreset preset : AllForceLengthPresets()) {
    const PresetPieces pieces = PiecesOf(preset);
    const double normalised =
        testing::Integrate([&](double s) { return std::pow(EvaluatePreset(preset, s), 2); },
                           pieces.breaks.front(), pieces.breaks.back(), pieces.breaks, 1e-14, 64);
    for (const double l_opt : {1.0, 0.062, 7.0}) {
      // integral of C(x / l_opt)^2 dx = l_opt * integral of C(s)^2 ds; 1e-12: quadrature
      EXPECT_NEAR(MakePresetTarget(preset, l_opt, 1.0)->NormSquared(), l_opt * normalised,
                  1e-12 * l_opt * normalised)
          << ToString(preset);
      EXPECT_DOUBLE_EQ(MakePresetTarget(preset, l_opt, 1.0)->SupportMin(),
                       pieces.breaks.front() * l_opt);
      EXPECT_DOUBLE_EQ(MakePresetTarget(preset, l_opt, 1.0)->SupportMax(),
                       pieces.breaks.back() * l_opt);
    }
  }
}

TEST(FitTarget, PresetGradientMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  for (const ForceLengthPreset preset : AllForceLengthPresets()) {
    for (int trial = 0; trial < 4; ++trial) {
      const Case c = RandomPresetCase(rng, 0.1);
      ExpectGradientMatches(*MakePresetTarget(preset, 0.1, c.sigma), c);
    }
  }
}

}  // namespace
}  // namespace musclesim
