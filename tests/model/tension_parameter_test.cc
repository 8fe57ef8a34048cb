#include "musclesim/model/tension_parameter.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using Kind = TensionParameterKind;

// ---- models: lengths in m around 0.1 m, L_opt = [0.09, 0.11], spreads sqrt(sigma / b) of
// 2.5 to 7 mm, so that every curve bends over millimetres and every velocity over eps

// n = 1 (g linear, eps without effect), one Gaussian peaking inside L_opt.
ModelParams SymmetricLinear() {
  ModelParams p;
  p.f_iso = 40.0;
  p.passive = {1.5, 40.0, 0.1};
  p.active_length = {0.09, 0.11, 1.0, {{0.02, 4e4, 0.101}}};
  p.velocity = {0.4, 1, 0.02};
  return p;
}

// n = 4, sigma != 1, three Gaussians (one negative) whose sum peaks inside L_opt.
ModelParams SymmetricQuartic() {
  ModelParams p;
  p.f_iso = 25.0;
  p.passive = {0.8, 60.0, 0.104};
  p.active_length = {
      0.09, 0.11, 0.6, {{0.02, 3e4, 0.097}, {0.012, 5e4, 0.106}, {-0.003, 2e4, 0.1}}};
  p.velocity = {0.5, 4, 0.01};
  return p;
}

// Three Gaussians centred at and beyond l2: f still rises at l2, where its maximum over L_opt
// is (checked in the test).
ModelParams PeakAtUpperEnd() {
  ModelParams p;
  p.f_iso = 60.0;
  p.passive = {2.0, 35.0, 0.098};
  p.active_length = {
      0.09, 0.11, 1.0, {{0.02, 2e4, 0.115}, {0.01, 3e4, 0.125}, {0.005, 4e4, 0.092}}};
  p.velocity = {0.6, 3, 0.02};
  return p;
}

// The mirror image: the maximum at l1, f falling there.
ModelParams PeakAtLowerEnd() {
  ModelParams p;
  p.f_iso = 30.0;
  p.passive = {1.0, 50.0, 0.102};
  p.active_length = {
      0.09, 0.11, 1.3, {{0.02, 2e4, 0.085}, {0.01, 3e4, 0.075}, {0.005, 4e4, 0.108}}};
  p.velocity = {0.3, 2, 0.01};
  return p;
}

// Asymmetric: its own eccentric v_max, n and a limit.
ModelParams AsymmetricWithEccentricMax() {
  ModelParams p = SymmetricQuartic();
  p.velocity = {0.6, 3, 0.02};
  p.velocity.eccentric = {0.3, 2, 1.6};
  return p;
}

// Asymmetric through n_e and a limit only: the lengthening branch takes the concentric
// v_max, so velocity.v_max acts on both branches.
ModelParams AsymmetricSharedMax() {
  ModelParams p = PeakAtUpperEnd();
  p.velocity = {0.5, 4, 0.02};
  p.velocity.eccentric = {std::nullopt, 2, 1.8};
  return p;
}

// A limit alone (n_e = n, v_max_e = v_max).
ModelParams LimitOnly() {
  ModelParams p = SymmetricLinear();
  p.velocity = {0.4, 3, 0.02};
  p.velocity.eccentric = {std::nullopt, std::nullopt, 1.5};
  return p;
}

// eccentric.v_max given equal to v_max: the curve is symmetric, but the lengthening branch's
// v_max is its own parameter, and velocity.v_max no longer acts on it.
ModelParams EccentricMaxEqualToConcentric() {
  ModelParams p = PeakAtLowerEnd();
  p.velocity = {0.5, 2, 0.02};
  p.velocity.eccentric = {0.5, std::nullopt, std::nullopt};
  return p;
}

// ---- the parameters, reached through fields written out here (not through ParameterValue),
// so that the parser's mapping from path to field is checked too

struct Case {
  std::string path;
  std::function<double&(ModelParams&)> field;
  double step;  // h of the differences [unit of p]
};

std::vector<Case> CasesFor(const ModelParams& p) {
  const ActiveLengthParams& a = p.active_length;
  // lengths move by 1e-3 of the narrowest spread: a Richardson error (h / scale)^4 ~ 1e-12
  double spread = a.optimal_max - a.optimal_min;
  for (const Gaussian& g : a.gaussians) spread = std::min(spread, std::sqrt(a.sigma / g.precision));
  const double dl = 1e-3 * spread;
  // positive scales move by 1e-3 of their value, for the same reason
  std::vector<Case> cases = {
      {"f_iso", [](ModelParams& m) -> double& { return m.f_iso; }, 1e-3 * p.f_iso},
      {"passive.k_p", [](ModelParams& m) -> double& { return m.passive.k_p; },
       1e-3 * p.passive.k_p},
      {"passive.alpha", [](ModelParams& m) -> double& { return m.passive.alpha; },
       1e-3 * p.passive.alpha},
      {"passive.slack_length", [](ModelParams& m) -> double& { return m.passive.slack_length; },
       dl},
      {"active_length.optimal_range[0]",
       [](ModelParams& m) -> double& { return m.active_length.optimal_min; }, dl},
      {"active_length.optimal_range[1]",
       [](ModelParams& m) -> double& { return m.active_length.optimal_max; }, dl},
      {"active_length.sigma", [](ModelParams& m) -> double& { return m.active_length.sigma; },
       1e-3 * a.sigma},
      {"velocity.v_max", [](ModelParams& m) -> double& { return m.velocity.v_max; },
       1e-3 * p.velocity.v_max},
      {"velocity.epsilon", [](ModelParams& m) -> double& { return m.velocity.epsilon; },
       1e-3 * p.velocity.epsilon},
  };
  for (std::size_t k = 0; k < a.gaussians.size(); ++k) {
    const std::string at = "active_length.gaussians[" + std::to_string(k) + "].";
    const Gaussian& g = a.gaussians[k];
    const auto component = [k](ModelParams& m) -> Gaussian& {
      return m.active_length.gaussians[k];
    };
    cases.push_back({at + "amplitude",
                     [component](ModelParams& m) -> double& { return component(m).amplitude; },
                     1e-3 * std::abs(g.amplitude)});
    cases.push_back({at + "width",
                     [component](ModelParams& m) -> double& { return component(m).precision; },
                     1e-3 * g.precision});
    cases.push_back({at + "center",
                     [component](ModelParams& m) -> double& { return component(m).center; }, dl});
  }
  if (p.velocity.eccentric.v_max) {
    cases.push_back({"velocity.eccentric.v_max",
                     [](ModelParams& m) -> double& { return *m.velocity.eccentric.v_max; },
                     1e-3 * *p.velocity.eccentric.v_max});
  }
  if (p.velocity.eccentric.limit) {
    // L - 1 is the scale the tanh bends over
    cases.push_back({"velocity.eccentric.limit",
                     [](ModelParams& m) -> double& { return *m.velocity.eccentric.limit; },
                     1e-3 * (*p.velocity.eccentric.limit - 1.0)});
  }
  return cases;
}

struct State {
  double x, v, u;
};

// Lengths on both sides of the slack length (at least 1.5 mm from it, far more than any
// step dl, so no difference straddles the kink) and of L_opt; velocities on both sides of 0,
// at the scale of eps and of v_max, and beyond v_max; two activations.
std::vector<State> StatesFor(const ModelParams& p) {
  const double slack = p.passive.slack_length;
  const double eps = p.velocity.epsilon, v_max = p.velocity.v_max;
  std::vector<State> states;
  for (double dx : {-0.015, -0.006, -0.0015, 0.0015, 0.004, 0.009, 0.016}) {
    for (double v :
         {-3.0 * v_max, -v_max, -0.25 * v_max, -0.05 * v_max, -3.0 * eps, -eps, -0.3 * eps, 0.0,
          0.3 * eps, eps, 3.0 * eps, 0.05 * v_max, 0.25 * v_max, 0.9 * v_max, 1.4 * v_max}) {
      for (double u : {0.35, 1.0}) states.push_back({slack + dx, v, u});
    }
  }
  return states;
}

// The three parts of T, for differencing.
struct Parts {
  double passive, active, total;
};
Parts PartsAt(const TensionModel& model, const State& s) {
  const TensionSample t = model.Evaluate(s.x, s.v, s.u);
  return {t.passive, t.active, t.total};
}

// The size of T's parts before any cancellation, which bounds T's rounding: k_p exp(..),
// sum |psi_k| / f_peak and 1 + |phi / v_max^alpha| (>= |g|, and >= 1 - g's cancellation).
double RoundingScale(const TensionModel& model, const State& s) {
  const ModelParams& p = model.params();
  const double stretch = std::max(0.0, s.x - p.passive.slack_length);
  const double passive = p.passive.k_p * std::exp(p.passive.alpha * stretch);
  const double sigma = p.active_length.sigma;
  double components = 0.0;
  for (const Gaussian& g : p.active_length.gaussians) {
    components += std::abs(g.amplitude) / std::sqrt(2.0 * std::numbers::pi * sigma) *
                  std::exp(-g.precision * (s.x - g.center) * (s.x - g.center) / (2.0 * sigma));
  }
  const double velocity = 1.0 + std::abs(model.velocity().Evaluate(s.v).value);
  return passive + s.u * p.f_iso * components / model.active_length().peak_value() * velocity;
}

// Parameters that do not act on T at all in `model`: eps when n = 1 (phi_eps(v) = v), an end
// of L_opt where f does not peak, the amplitude of a lone Gaussian (f_L = f / f_peak is then
// free of it).
bool ZeroByConstruction(const TensionModel& model, const std::string& path) {
  const ModelParams& p = model.params();
  const double peak = model.active_length().optimal_length();
  if (path == "velocity.epsilon") return p.velocity.n == 1;
  if (path == "active_length.optimal_range[0]") return peak != p.active_length.optimal_min;
  if (path == "active_length.optimal_range[1]") return peak != p.active_length.optimal_max;
  if (path == "active_length.gaussians[0].amplitude") return p.active_length.gaussians.size() == 1;
  return false;
}

// Checks every parameter of `params` at every state against Richardson-extrapolated central
// differences of TensionModel rebuilt at p +- h and p +- h/2.
void ExpectMatchesDifferences(const ModelParams& params) {
  const TensionModel model(params);
  const std::vector<State> states = StatesFor(params);
  for (const Case& c : CasesFor(params)) {
    SCOPED_TRACE(c.path);
    const std::optional<TensionParameter> parameter = ParseTensionParameter(c.path);
    ASSERT_TRUE(parameter.has_value());
    const TensionParameterDerivative derivative(model, *parameter);

    // the model at p +- h and p +- h / 2; differences divided by the steps as rounded
    const auto built = [&](double delta) {
      ModelParams moved = params;
      c.field(moved) += delta;
      return TensionModel(moved);
    };
    ModelParams unmoved = params;
    const double p0 = c.field(unmoved);
    const double h = c.step;
    const TensionModel plus(built(h)), minus(built(-h)), half_plus(built(h / 2)),
        half_minus(built(-h / 2));
    const double wide = (p0 + h) - (p0 - h), narrow = (p0 + h / 2) - (p0 - h / 2);

    int resolved = 0;
    for (const State& s : states) {
      const Parts a = PartsAt(plus, s), b = PartsAt(minus, s), c2 = PartsAt(half_plus, s),
                  d = PartsAt(half_minus, s);
      // Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central difference
      const auto reference = [&](double Parts::*part) {
        const double coarse = (a.*part - b.*part) / wide;
        const double fine = (c2.*part - d.*part) / narrow;
        return (4.0 * fine - coarse) / 3.0;
      };
      // rounding: each T carries at most ~30 ulps of its parts' size (exp, pow, a sum of
      // Gaussians that may cancel, 1 - phi; a generous count), which the combination above
      // turns into (4 * 2 / h + 2 / (2h)) / 3 = 3 / h times that: 100 ulps / h
      const double noise =
          100.0 * std::numeric_limits<double>::epsilon() * RoundingScale(model, s) / h;
      const TensionPartials got = derivative(s.x, s.v, s.u);
      const double parts[3][2] = {{got.passive, reference(&Parts::passive)},
                                  {got.active, reference(&Parts::active)},
                                  {got.total, reference(&Parts::total)}};
      for (const auto& [analytic, fd] : parts) {
        // 1e-8 relative: Richardson's truncation is (h / scale)^4 ~ 1e-12 of the derivative
        // with h 1e-3 of each scale, times the larger higher derivatives far out in a
        // Gaussian's tail; the worst seen is 1e-10, so 1e-8 leaves a factor 100
        EXPECT_NEAR(analytic, fd, 1e-8 * std::abs(fd) + noise)
            << "x = " << s.x << ", v = " << s.v << ", u = " << s.u;
        if (noise < 1e-8 * std::abs(fd)) ++resolved;  // the relative bound binds
      }
    }
    // the derivative is measured, not just bounded by the rounding floor: where it is not
    // zero by construction, at some states the floor lies below the relative bound
    if (!ZeroByConstruction(model, c.path)) {
      EXPECT_GT(resolved, 0);
    }
  }
}

TEST(TensionParameter, SymmetricLinearMatchesDifferences) {
  ExpectMatchesDifferences(SymmetricLinear());
}

TEST(TensionParameter, SymmetricQuarticMatchesDifferences) {
  const TensionModel model(SymmetricQuartic());
  // precondition: the maximum of f over L_opt is interior
  ASSERT_GT(model.active_length().optimal_length(), 0.09);
  ASSERT_LT(model.active_length().optimal_length(), 0.11);
  ExpectMatchesDifferences(SymmetricQuartic());
}

TEST(TensionParameter, PeakAtUpperEndMatchesDifferences) {
  const TensionModel model(PeakAtUpperEnd());
  // precondition: the maximum sits at l2 and f still rises there
  ASSERT_EQ(model.active_length().optimal_length(), 0.11);
  ASSERT_GT(model.active_length().sum().ValueAndSlope(0.11).slope, 0.0);
  ExpectMatchesDifferences(PeakAtUpperEnd());
}

TEST(TensionParameter, PeakAtLowerEndMatchesDifferences) {
  const TensionModel model(PeakAtLowerEnd());
  ASSERT_EQ(model.active_length().optimal_length(), 0.09);
  ASSERT_LT(model.active_length().sum().ValueAndSlope(0.09).slope, 0.0);
  ExpectMatchesDifferences(PeakAtLowerEnd());
}

TEST(TensionParameter, AsymmetricWithEccentricMaxMatchesDifferences) {
  ExpectMatchesDifferences(AsymmetricWithEccentricMax());
}

TEST(TensionParameter, AsymmetricSharedMaxMatchesDifferences) {
  ExpectMatchesDifferences(AsymmetricSharedMax());
}

TEST(TensionParameter, LimitOnlyMatchesDifferences) { ExpectMatchesDifferences(LimitOnly()); }

TEST(TensionParameter, EccentricMaxEqualToConcentricMatchesDifferences) {
  ExpectMatchesDifferences(EccentricMaxEqualToConcentric());
}

TEST(TensionParameter, EveryKindIsExercised) {
  std::set<Kind> kinds;
  for (const ModelParams& p :
       {SymmetricLinear(), SymmetricQuartic(), PeakAtUpperEnd(), PeakAtLowerEnd(),
        AsymmetricWithEccentricMax(), AsymmetricSharedMax(), LimitOnly(),
        EccentricMaxEqualToConcentric()}) {
    for (const Case& c : CasesFor(p)) kinds.insert(ParseTensionParameter(c.path)->kind);
  }
  EXPECT_EQ(kinds.size(), 14u);
}

// ---- the end of the active-length normalisation and the passive kink

TEST(TensionParameter, OptimalRangeEndsMatterOnlyWhereThePeakIs) {
  // at an interior peak neither end moves f_peak; at a peak on l2, only l2 does, at the rate
  // f'(l2): then T_a scales by -f'(l2) / f_peak per metre, written out here
  const TensionModel interior(SymmetricQuartic());
  const TensionModel upper(PeakAtUpperEnd());
  const State s{0.1, 0.1, 0.7};
  for (Kind k : {Kind::kOptimalMin, Kind::kOptimalMax}) {
    EXPECT_EQ(TensionPartialsAt(interior, {k, 0}, s.x, s.v, s.u).total, 0.0);
  }
  EXPECT_EQ(TensionPartialsAt(upper, {Kind::kOptimalMin, 0}, s.x, s.v, s.u).total, 0.0);
  const double active = upper.Evaluate(s.x, s.v, s.u).active;
  const CurvePoint end = upper.active_length().sum().ValueAndSlope(0.11);
  // a few ulps of T_a's size: the quotient is one rounding from each product
  EXPECT_NEAR(TensionPartialsAt(upper, {Kind::kOptimalMax, 0}, s.x, s.v, s.u).total,
              -active * end.slope / end.value, 1e-13 * std::abs(active * end.slope / end.value));
}

TEST(TensionParameter, AtTheSlackLengthTakesTheZeroBranch) {
  // at x == slack_length, PassiveTension returns the left branch: raising the slack length
  // keeps x on it (a one-sided difference of exactly 0), and k_p and alpha do not act
  const ModelParams params = SymmetricQuartic();
  const TensionModel model(params);
  const double x = params.passive.slack_length;
  for (Kind k : {Kind::kPassiveScale, Kind::kPassiveRate, Kind::kSlackLength}) {
    const TensionPartials d = TensionPartialsAt(model, {k, 0}, x, 0.1, 1.0);
    EXPECT_EQ(d.passive, 0.0);
    EXPECT_EQ(d.active, 0.0);
  }
  ModelParams raised = params;
  raised.passive.slack_length += 1e-6;
  EXPECT_EQ(TensionModel(raised).Evaluate(x, 0.1, 1.0).passive,
            model.Evaluate(x, 0.1, 1.0).passive);
  // just above it the right branch: dT_p/dx0 = -k_p alpha exp(alpha (x - x0)) -> -k_p alpha
  const double above = std::nextafter(x, 1.0);
  EXPECT_NEAR(TensionPartialsAt(model, {Kind::kSlackLength, 0}, above, 0.1, 1.0).passive,
              -params.passive.k_p * params.passive.alpha,
              1e-14 * params.passive.k_p * params.passive.alpha);  // exp of ~1e-16: 1 ulp
}

TEST(TensionParameter, VelocityDerivativesVanishAtZeroVelocity) {
  // phi_eps(0) = 0 on both branches, so g(0) = 1 whatever v_max, eps and L are
  const ModelParams params = AsymmetricWithEccentricMax();
  const TensionModel model(params);
  for (Kind k :
       {Kind::kMaxVelocity, Kind::kEpsilon, Kind::kEccentricMaxVelocity, Kind::kEccentricLimit}) {
    EXPECT_EQ(TensionPartialsAt(model, {k, 0}, 0.1, 0.0, 1.0).total, 0.0);
    EXPECT_EQ(TensionPartialsAt(model, {k, 0}, 0.1, -0.0, 1.0).total, 0.0);
  }
}

TEST(TensionParameter, LimitDerivativeKeepsItsPrecisionForSmallPsi) {
  // d/dL [1 + (L - 1) tanh(psi / (L - 1))] = tanh z - z sech^2 z = 2 z^3 / 3 - 8 z^5 / 15 +
  // ..., z = psi / (L - 1): far below eps, psi ~ v eps^(alpha-1) / v_max^alpha and z tiny,
  // where the difference form would lose all digits
  ModelParams params = LimitOnly();  // n = 3, L = 1.5
  const TensionModel model(params);
  const double v = -1e-9;
  const double eps = params.velocity.epsilon, v_max = params.velocity.v_max;
  const double alpha = 1.0 / 3.0;
  const double psi = -v * std::pow(v * v + eps * eps, (alpha - 1.0) / 2.0) / std::pow(v_max, alpha);
  const double z = psi / 0.5;
  const double series = 2.0 * z * z * z / 3.0 - 8.0 * std::pow(z, 5) / 15.0;
  const double active_scale =
      model.Evaluate(0.1, v, 1.0).active / model.velocity().Evaluate(v).value;  // u f_iso f_L
  // the series' next term is ~z^7, z ~ 1e-7 here: 1e-12 relative is rounding only
  EXPECT_NEAR(TensionPartialsAt(model, {Kind::kEccentricLimit, 0}, 0.1, v, 1.0).active,
              active_scale * series, 1e-12 * std::abs(active_scale * series));
}

// ---- the parser, the names and the parameters a model lacks

TEST(TensionParameterParse, ReadsEveryContinuousParameter) {
  const std::vector<std::pair<std::string, TensionParameter>> good = {
      {"f_iso", {Kind::kIsometricTension, 0}},
      {"passive.k_p", {Kind::kPassiveScale, 0}},
      {"passive.alpha", {Kind::kPassiveRate, 0}},
      {"passive.slack_length", {Kind::kSlackLength, 0}},
      {"active_length.optimal_range[0]", {Kind::kOptimalMin, 0}},
      {"active_length.optimal_range[1]", {Kind::kOptimalMax, 0}},
      {"active_length.sigma", {Kind::kSigma, 0}},
      {"active_length.gaussians[1].amplitude", {Kind::kAmplitude, 1}},
      {"active_length.gaussians[0].width", {Kind::kWidth, 0}},
      {"active_length.gaussians[12].center", {Kind::kCenter, 12}},
      {"velocity.v_max", {Kind::kMaxVelocity, 0}},
      {"velocity.epsilon", {Kind::kEpsilon, 0}},
      {"velocity.eccentric.v_max", {Kind::kEccentricMaxVelocity, 0}},
      {"velocity.eccentric.limit", {Kind::kEccentricLimit, 0}},
  };
  for (const auto& [path, expected] : good) {
    const std::optional<TensionParameter> got = ParseTensionParameter(path);
    ASSERT_TRUE(got.has_value()) << path;
    EXPECT_EQ(*got, expected) << path;
    EXPECT_EQ(ToString(*got), path);  // the canonical form reads back as written
  }
}

TEST(TensionParameterParse, AcceptsTheSpellingsThatSetAccepts) {
  // `--set` takes a dot on either side of an index as optional and ignores one trailing dot
  const TensionParameter width{Kind::kWidth, 2};
  EXPECT_EQ(ParseTensionParameter("active_length.gaussians.[2].width"), width);
  EXPECT_EQ(ParseTensionParameter("active_length.gaussians[2]width"), width);
  EXPECT_EQ(ParseTensionParameter("active_length.gaussians[02].width"), width);
  EXPECT_EQ(ParseTensionParameter("velocity.epsilon."), (TensionParameter{Kind::kEpsilon, 0}));
}

TEST(TensionParameterParse, RejectsWhatIsNoContinuousParameter) {
  for (const char* bad : {"",
                          ".",
                          "model.f_iso",
                          "f_iso.x",
                          "F_ISO",
                          "passive",
                          "passive.k_p.x",
                          "passive.kp",
                          "velocity.n",
                          "velocity.eccentric.n",
                          "velocity.eccentric",
                          "velocity.v_max[0]",
                          "active_length",
                          "active_length.optimal_range",
                          "active_length.optimal_range[2]",
                          "active_length.optimal_range.min",
                          "active_length.gaussians",
                          "active_length.gaussians[1]",
                          "active_length.gaussians[1].precision",
                          "active_length.gaussians[].width",
                          "active_length.gaussians[x].width",
                          "active_length.gaussians[-1].width",
                          "active_length.gaussians[1.width",
                          "active_length.gaussians.1.width",
                          "active_length.fit.widths[0]",
                          "active_length..sigma",
                          "f_iso..",
                          "velocity.epsilon[0]",
                          "active_length.gaussians[99999999999999999999999].width"}) {
    EXPECT_FALSE(ParseTensionParameter(bad).has_value()) << bad;
  }
}

TEST(TensionParameterPresence, ValuesAreTheFieldsNamed) {
  const ModelParams p = AsymmetricWithEccentricMax();
  for (const Case& c : CasesFor(p)) {
    ModelParams copy = p;
    EXPECT_EQ(ParameterValue(p, *ParseTensionParameter(c.path)), c.field(copy)) << c.path;
  }
}

TEST(TensionParameterPresence, RejectsAComponentPastTheLast) {
  const ModelParams params = SymmetricQuartic();  // three Gaussians
  const TensionModel model(params);
  const TensionParameter fourth{Kind::kCenter, 3};
  try {
    TensionParameterDerivative(model, fourth);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "active_length.gaussians[3].center");
    EXPECT_THAT(e.what(), HasSubstr("3 Gaussian(s), gaussians[0] to gaussians[2]"));
  }
  EXPECT_THROW(ParameterValue(params, fourth), ParameterError);
  EXPECT_NO_THROW(ParameterValue(params, {Kind::kCenter, 2}));
}

TEST(TensionParameterPresence, RejectsEccentricParametersNotGiven) {
  const ModelParams params = AsymmetricSharedMax();  // a limit, no eccentric v_max
  const TensionModel model(params);
  try {
    TensionParameterDerivative(model, {Kind::kEccentricMaxVelocity, 0});
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "velocity.eccentric.v_max");
    EXPECT_THAT(e.what(), HasSubstr("covers both branches"));
  }
  EXPECT_NO_THROW(TensionParameterDerivative(model, {Kind::kEccentricLimit, 0}));

  const TensionModel symmetric(SymmetricQuartic());
  try {
    TensionParameterDerivative(symmetric, {Kind::kEccentricLimit, 0});
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "velocity.eccentric.limit");
    EXPECT_THAT(e.what(), HasSubstr("unbounded"));
  }
}

}  // namespace
}  // namespace musclesim
