#include "musclesim/model/force_length_presets.h"

#include <array>
#include <cmath>

#include "musclesim/core/enum_names.h"

namespace musclesim {

constexpr std::array<ForceLengthPreset, 4> kAllPresets = {
    ForceLengthPreset::kDeGroote2016, ForceLengthPreset::kThelen2003,
    ForceLengthPreset::kGordon1966, ForceLengthPreset::kMuJoCo};

std::string_view ToString(ForceLengthPreset preset) {
  return ToString(kForceLengthPresetNames, preset);
}

ForceLengthPreset ParseForceLengthPreset(std::string_view text) {
  return Parse(kForceLengthPresetNames, "name", text);
}

std::span<const ForceLengthPreset> AllForceLengthPresets() { return kAllPresets; }

namespace {

// --- degroote2016 --------------------------------------------------------------------------
// F. De Groote, A. L. Kinney, A. V. Rao, B. J. Fregly, "Evaluation of direct collocation
// optimal control problem formulations for solving the muscle redundancy problem", Ann. Biomed.
// Eng. 44:2922-2936 (2016), supplement eq. S2: the sum of three Gaussian-like terms
//   f(l) = sum_i b1i exp(-0.5 (l - b2i)^2 / (b3i + b4i l)^2)
// with the paper's constants below. The denominator is squared as in OpenSim's reference
// implementation (opensim-core, OpenSim/Actuators/DeGrooteFregly2016Muscle.h,
// calcGaussianLikeCurve, which notes that the supplement omits the square). OpenSim uses
// longer constants from the authors' code, with b11 changed so that f(1) = 1.
//
// With the paper's constants the curve does not peak at 1 at l = 1: f(1) = 0.99933, and its
// maximum is 1.00047 at l = 1.0136. The preset rescales both axes so that its peak is (1, 1):
//   preset(s) = f(s * l_peak) / f(l_peak)
// i.e. the optimal length is taken where the published curve peaks. The formula means nothing
// at negative lengths (the second term's width b32 + b42 l changes sign at l = 0.15) and never
// reaches 0 (it levels off at 0.433 exp(-12.5) = 1.6e-6 both ways, so it has no finite L2
// norm): the preset is cut to 0 <= s <= 3, where it is 0.0018 and 1.4e-4.
struct GaussianLike {
  double b1, b2, b3, b4;
};
constexpr GaussianLike kDeGrooteTerms[] = {
    {0.815, 1.055, 0.162, 0.063},
    {0.433, 0.717, -0.030, 0.200},
    {0.100, 1.000, 0.354, 0.000},
};

double DeGrootePublished(double l) {
  double f = 0.0;
  for (const GaussianLike& t : kDeGrooteTerms) {
    const double width = t.b3 + t.b4 * l;
    const double gap = l - t.b2;
    // at width 0 (l = 0.15 for the second term) the term's limit is 0; IEEE gives exp(-inf)
    f += t.b1 * std::exp(-0.5 * gap * gap / (width * width));
  }
  return f;
}

// df/dl: the term's derivative b1 e (b2 - l)(b3 + b2 b4) / (b3 + b4 l)^3 (OpenSim's
// calcGaussianLikeCurveDerivative)
double DeGrootePublishedSlope(double l) {
  double slope = 0.0;
  for (const GaussianLike& t : kDeGrooteTerms) {
    const double width = t.b3 + t.b4 * l;
    const double gap = l - t.b2;
    const double term = t.b1 * std::exp(-0.5 * gap * gap / (width * width));
    slope += term * (-gap) * (t.b3 + t.b2 * t.b4) / (width * width * width);
  }
  return slope;
}

struct Peak {
  double at, value;
};

// The published curve's maximum: its slope is positive at 1 and negative at 1.05, with a
// single sign change between (the curve is concave there); bisected to the last bit.
Peak DeGrootePeak() {
  double lo = 1.0, hi = 1.05;
  while (true) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (DeGrootePublishedSlope(mid) > 0.0 ? lo : hi) = mid;
  }
  return {lo, DeGrootePublished(lo)};
}

constexpr double kDeGrooteMin = 0.0, kDeGrooteMax = 3.0;

double DeGroote(double s) {
  static const Peak peak = DeGrootePeak();
  if (s < kDeGrooteMin || s > kDeGrooteMax) return 0.0;
  return DeGrootePublished(s * peak.at) / peak.value;
}

// --- thelen2003 ----------------------------------------------------------------------------
// D. G. Thelen, "Adjustment of muscle mechanics model parameters to simulate dynamic
// contractions in older adults", J. Biomech. Eng. 125:70-77 (2003), eq. 3:
//   f(s) = exp(-(s - 1)^2 / gamma),  gamma = 0.45
// gamma divides the square directly (it is not a variance): OpenSim's Thelen2003Muscle::calcfal
// computes exp(-(lceN - 1)^2 / KshapeActive) with KshapeActive = 0.45 by default. The peak is 1
// at s = 1 as published. This is one Gaussian of standard deviation sqrt(gamma / 2) = 0.474,
// nonzero at every length (0.108 at s = 0): the preset keeps it whole down to 6 standard
// deviations (1 - 2.85 <= s <= 1 + 2.85), where it is 1.5e-8, so that one Gaussian can
// reproduce it to roundoff.
constexpr double kThelenGamma = 0.45;
constexpr double kThelenHalfWidth = 2.846049894151541;  // 6 sqrt(kThelenGamma / 2)

double Thelen(double s) {
  if (std::abs(s - 1.0) > kThelenHalfWidth) return 0.0;
  return std::exp(-(s - 1.0) * (s - 1.0) / kThelenGamma);
}

// --- gordon1966 ----------------------------------------------------------------------------
// A. M. Gordon, A. F. Huxley, F. J. Julian, "The variation in isometric tension with sarcomere
// length in vertebrate muscle fibres", J. Physiol. 184:170-192 (1966): the piecewise-linear
// relation of its Fig. 12, the breakpoints of data/ghj1966_breakpoints.csv (sarcomere lengths
// 1.27, 1.67, 2.0, 2.25 and 3.65 um, tensions 0, 0.84, 1, 1, 0). The optimal length is taken
// as the middle of the plateau, 2.125 um, so the plateau is 0.941 <= s <= 1.059.
constexpr double kGordonOptimum = 2.125;  // um
struct Vertex {
  double s, f;
};
constexpr Vertex kGordonVertices[] = {
    {1.27 / kGordonOptimum, 0.0}, {1.67 / kGordonOptimum, 0.84}, {2.0 / kGordonOptimum, 1.0},
    {2.25 / kGordonOptimum, 1.0}, {3.65 / kGordonOptimum, 0.0},
};

double Gordon(double s) {
  const auto& v = kGordonVertices;
  if (s < v[0].s || s > v[4].s) return 0.0;
  for (int i = 0; i < 4; ++i) {
    if (s <= v[i + 1].s) {
      return v[i].f + (v[i + 1].f - v[i].f) * (s - v[i].s) / (v[i + 1].s - v[i].s);
    }
  }
  return 0.0;
}

// --- mujoco --------------------------------------------------------------------------------
// MuJoCo's default muscle active force-length curve, mju_muscleGainLength in
// src/engine/engine_util_misc.c, with its default lmin = 0.5 and lmax = 1.6: four quadratic
// pieces joined with matching slopes at a = (lmin + 1) / 2 = 0.75, 1 and b = (1 + lmax) / 2 =
// 1.3, zero outside [lmin, lmax]:
//   0.5 x^2      x = (s - lmin) / (a - lmin)   on [lmin, a]
//   1 - 0.5 x^2  x = (1 - s) / (1 - a)         on [a, 1]
//   1 - 0.5 x^2  x = (s - 1) / (b - 1)         on [1, b]
//   0.5 x^2      x = (lmax - s) / (lmax - b)   on [b, lmax]
// Its peak is 1 at s = 1 as published.
constexpr double kMuJoCoMin = 0.5, kMuJoCoMax = 1.6;
constexpr double kMuJoCoA = 0.5 * (kMuJoCoMin + 1.0), kMuJoCoB = 0.5 * (1.0 + kMuJoCoMax);

double MuJoCo(double s) {
  if (s < kMuJoCoMin || s > kMuJoCoMax) return 0.0;
  if (s <= kMuJoCoA) {
    const double x = (s - kMuJoCoMin) / (kMuJoCoA - kMuJoCoMin);
    return 0.5 * x * x;
  }
  if (s <= 1.0) {
    const double x = (1.0 - s) / (1.0 - kMuJoCoA);
    return 1.0 - 0.5 * x * x;
  }
  if (s <= kMuJoCoB) {
    const double x = (s - 1.0) / (kMuJoCoB - 1.0);
    return 1.0 - 0.5 * x * x;
  }
  const double x = (kMuJoCoMax - s) / (kMuJoCoMax - kMuJoCoB);
  return 0.5 * x * x;
}

}  // namespace

double EvaluatePreset(ForceLengthPreset preset, double s) {
  switch (preset) {
    case ForceLengthPreset::kDeGroote2016: return DeGroote(s);
    case ForceLengthPreset::kThelen2003: return Thelen(s);
    case ForceLengthPreset::kGordon1966: return Gordon(s);
    case ForceLengthPreset::kMuJoCo: return MuJoCo(s);
  }
  return 0.0;
}

PresetPieces PiecesOf(ForceLengthPreset preset) {
  // panels: DeGroote's narrowest term, the second, is 0.064 wide (b32 + b42 l) at l = 0.47,
  // below which it is under 1e-4; panels of 0.04 resolve it (an eighth of that changes a fit's
  // residual by 1e-11 relative). Thelen's Gaussian is 0.47 wide. The polygon and the quadratics
  // are polynomials between their breaks, resolved by any panel.
  switch (preset) {
    case ForceLengthPreset::kDeGroote2016: return {{kDeGrooteMin, kDeGrooteMax}, 0.04};
    case ForceLengthPreset::kThelen2003:
      return {{1.0 - kThelenHalfWidth, 1.0 + kThelenHalfWidth}, 0.1};
    case ForceLengthPreset::kGordon1966: {
      PresetPieces pieces{{}, 0.1};
      for (const Vertex& v : kGordonVertices) pieces.breaks.push_back(v.s);
      return pieces;
    }
    case ForceLengthPreset::kMuJoCo:
      return {{kMuJoCoMin, kMuJoCoA, 1.0, kMuJoCoB, kMuJoCoMax}, 0.1};
  }
  return {};
}

}  // namespace musclesim
