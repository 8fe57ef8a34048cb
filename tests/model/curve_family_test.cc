// The curve families against the tools that define them: OpenSim's DeGrooteFregly2016Muscle
// and MuJoCo's mju_muscleGain / mju_muscleBias, tabulated by those tools themselves
// (bench/peers/reference/*.csv, written by bench/peers/reference_curves.py); every
// derivative against central differences, pennation included.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/model/tension.h"
#include "support/numeric.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using testing::CentralDifference;
using ::testing::HasSubstr;

// A peer's table, one row at a time as a map from column to value.
std::vector<std::map<std::string, double>> Rows(const std::string& name) {
  const testing::PeerTable table = testing::ReadPeerTable(name);
  std::vector<std::map<std::string, double>> rows(table.begin()->second.size());
  for (const auto& [column, values] : table) {
    for (std::size_t k = 0; k < values.size(); ++k) rows[k][column] = values[k];
  }
  EXPECT_GT(rows.size(), 10u) << name;
  return rows;
}

ModelParams DeGroote() {
  ModelParams p;
  p.family = CurveFamily::kDeGroote2016;
  p.f_iso = 1.0;
  p.degroote2016.optimal_fiber_length = 0.1;
  p.degroote2016.max_contraction_velocity = 10.0;
  return p;
}

// OpenSim's values are double-precision evaluations of the same closed forms: agreement to
// a few ulps of the curve's scale
constexpr double kOpenSimTolerance = 1e-12;

TEST(DeGroote2016Curves, ActiveAndPassiveForceLengthAreOpenSimsWithTheirSlopes) {
  const TensionModel model(DeGroote());
  const double l_opt = 0.1;
  for (const auto& row : Rows("degroote2016_fiber_length.csv")) {
    const double l = row.at("normalized_fiber_length") * l_opt;
    const TensionSample active = model.Evaluate(l, 0.0, 1.0), passive = model.Passive(l, 0.0);
    const double f_v0 = degroote2016::ForceVelocity(0.0).value;  // OpenSim's f_v(0), not 1
    EXPECT_NEAR(active.d_activation / f_v0, row.at("active"), kOpenSimTolerance) << l;
    EXPECT_NEAR((active.d_length - passive.d_length) * l_opt / f_v0, row.at("active_slope"), 1e-10)
        << l;
    EXPECT_NEAR(passive.total, row.at("passive"), kOpenSimTolerance) << l;
    EXPECT_NEAR(passive.d_length * l_opt, row.at("passive_slope"), 1e-10) << l;
  }
}

TEST(DeGroote2016Curves, ForceVelocityIsOpenSimsWithLengtheningPositive) {
  ModelParams p = DeGroote();
  const TensionModel model(p);
  const double l_opt = 0.1, v_max = 10.0;
  const double isometric = model.Evaluate(l_opt, 0.0, 1.0).d_activation;
  for (const auto& row : Rows("degroote2016_fiber_velocity.csv")) {
    // OpenSim's lengthening velocity in optimal lengths per v_max; musclesim's v shortens
    const double v = -row.at("normalized_fiber_velocity") * v_max * l_opt;
    const double f_v = model.Evaluate(l_opt, v, 1.0).d_activation / isometric *
                       degroote2016::ForceVelocity(0.0).value;
    EXPECT_NEAR(f_v, row.at("force_velocity"), kOpenSimTolerance) << v;
  }
}

MujocoMuscleParams MujocoSet(int set) {
  // bench/peers/reference_curves.py: gainprm sets "default" and "other", lengthrange
  // [0.05, 0.25] m, force >= 0 so F0 = force
  MujocoMuscleParams m;
  if (set == 1) {
    m.range[0] = 0.6;
    m.range[1] = 1.2;
    m.lmin = 0.4;
    m.lmax = 1.8;
    m.vmax = 2.0;
    m.fpmax = 1.1;
    m.fvmax = 1.5;
  }
  m.lengthrange[0] = 0.05;
  m.lengthrange[1] = 0.25;
  return m;
}

TEST(MujocoCurves, GainAndBiasAreMujocosWithItsSigns) {
  for (const auto& row : Rows("mujoco_muscle.csv")) {
    const int set = static_cast<int>(row.at("set"));
    ModelParams p;
    p.family = CurveFamily::kMujoco;
    p.f_iso = set == 0 ? 100.0 : 250.0;
    p.mujoco = MujocoSet(set);
    const TensionModel model(p);
    // MuJoCo's actuator velocity lengthens; its force = gain u + bias pushes
    const double x = row.at("length"), v = -row.at("velocity");
    const TensionSample s = model.Evaluate(x, v, 0.7);
    const double scale = 1e-13 * p.f_iso;
    EXPECT_NEAR(-s.d_activation, row.at("gain"), scale) << x << " " << v;
    EXPECT_NEAR(-s.passive, row.at("bias"), scale) << x << " " << v;
    EXPECT_NEAR(s.total, -(0.7 * row.at("gain") + row.at("bias")), scale);
  }
}

// Every derivative of Evaluate against a central difference of its own value, at a spread
// of states that avoids the curves' kinks (MuJoCo's are C1, so at a kink the derivative is
// still continuous: the difference is checked there too, to a looser tolerance).
void ExpectDerivativesMatchDifferences(const TensionModel& model,
                                       const std::vector<double>& lengths,
                                       const std::vector<double>& velocities, double tolerance) {
  for (double x : lengths) {
    for (double v : velocities) {
      for (double u : {0.0, 0.35, 1.0}) {
        const TensionSample s = model.Evaluate(x, v, u);
        // a derivative's own size, or the tension's over a length or speed of order 0.1
        const double scale = std::max({1.0, 10.0 * std::abs(s.total)});
        const double d_length =
            CentralDifference([&](double y) { return model.Evaluate(y, v, u).total; }, x, 1e-7);
        const double d_velocity =
            CentralDifference([&](double y) { return model.Evaluate(x, y, u).total; }, v, 1e-7);
        const double d_activation =
            CentralDifference([&](double y) { return model.Evaluate(x, v, y).total; }, u, 1e-7);
        const auto bound = [&](double d) { return tolerance * std::max(scale, std::abs(d)); };
        EXPECT_NEAR(s.d_length, d_length, bound(d_length)) << x << " " << v << " " << u;
        EXPECT_NEAR(s.d_velocity, d_velocity, bound(d_velocity)) << x << " " << v << " " << u;
        EXPECT_NEAR(s.d_activation, d_activation, bound(d_activation)) << x << " " << v;
        EXPECT_NEAR(s.total, s.passive + s.active, 1e-12 * scale);
        const TensionSample passive = model.Passive(x, v);
        EXPECT_NEAR(s.passive, passive.total, 1e-12 * scale);
      }
    }
  }
}

TEST(DeGroote2016Curves, DerivativesMatchDifferencesWithDampingWidthAndPennation) {
  ModelParams p = DeGroote();
  p.f_iso = 500.0;
  p.degroote2016.fiber_damping = 0.05;
  p.degroote2016.active_force_width_scale = 1.4;
  p.degroote2016.passive_fiber_strain_at_one_norm_force = 0.5;
  for (double angle : {0.0, 0.3, 1.2}) {
    p.pennation_angle = angle;
    ExpectDerivativesMatchDifferences(TensionModel(p), {0.05, 0.08, 0.1, 0.12, 0.15},
                                      {-1.5, -0.2, 0.0, 0.3, 0.9}, 1e-6);
  }
}

TEST(MujocoCurves, DerivativesMatchDifferencesAwayFromAndAtTheJoints) {
  ModelParams p;
  p.family = CurveFamily::kMujoco;
  p.f_iso = 200.0;
  p.mujoco = MujocoSet(1);
  const TensionModel model(p);
  // L0 = 0.2 / 0.6; L = 0.6 + (x - 0.05) / L0; interior points of each piece
  std::vector<double> lengths;
  for (double L : {0.55, 0.85, 1.2, 1.5, 1.75, 1.95}) lengths.push_back(0.05 + (L - 0.6) / 3.0);
  ExpectDerivativesMatchDifferences(model, lengths, {-0.9, -0.3, 0.4, 0.7}, 1e-6);
  for (double angle : {0.4, 1.0}) {
    p.pennation_angle = angle;
    ExpectDerivativesMatchDifferences(TensionModel(p), {0.1, 0.15, 0.2}, {-0.3, 0.2}, 1e-6);
  }
}

TEST(Pennation, ConstantThicknessGeometryWrittenOutAgain) {
  // l_f sin(alpha) = l_opt sin(alpha_opt): at x along the line, l_f = sqrt(x^2 + w^2); the
  // line's tension is F(l_f, v_f) cos(alpha) with the fiber shortening at d l_f/dt
  ModelParams fiber = DeGroote();
  fiber.f_iso = 300.0;
  fiber.degroote2016.fiber_damping = 0.1;
  ModelParams pennate = fiber;
  pennate.pennation_angle = 0.5;
  const TensionModel along(fiber), through(pennate);
  const double w = 0.1 * std::sin(0.5);
  for (double x : {0.06, 0.087758, 0.11}) {
    for (double v : {-0.4, 0.0, 0.25}) {
      const double l_f = std::sqrt(x * x + w * w), cosine = x / l_f;
      const double v_f = x * v / l_f;  // d/dt sqrt(x^2 + w^2) with v = -dx/dt
      EXPECT_NEAR(through.Evaluate(x, v, 0.6).total, along.Evaluate(l_f, v_f, 0.6).total * cosine,
                  1e-12 * 300.0);
    }
  }
  // at the optimal fiber length the angle is the given one
  const double x_opt = 0.1 * std::cos(0.5);
  EXPECT_NEAR(through.Evaluate(x_opt, 0.0, 1.0).d_activation,
              along.Evaluate(0.1, 0.0, 1.0).d_activation * std::cos(0.5), 1e-12);
}

TEST(Pennation, ZeroAngleIsTheUnpennateModelExactly) {
  ModelParams p;  // the paper's family, defaults
  p.f_iso = 100.0;
  p.passive = {2.0, 30.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {{0.05, 90.0, 0.097}, {0.03, 400.0, 0.104}}};
  p.velocity = {1.0, 3, 1e-3};
  const TensionModel plain(p);
  p.pennation_angle = 0.0;
  const TensionModel zero(p);
  for (double x : {0.09, 0.1, 0.11}) {
    const TensionSample a = plain.Evaluate(x, 0.2, 0.5), b = zero.Evaluate(x, 0.2, 0.5);
    EXPECT_EQ(a.total, b.total);
    EXPECT_EQ(a.d_length, b.d_length);
    EXPECT_EQ(a.d_velocity, b.d_velocity);
  }
  // and with an angle the paper's curves are seen through the same geometry
  p.pennation_angle = 0.4;
  ExpectDerivativesMatchDifferences(TensionModel(p), {0.09, 0.1, 0.11}, {-0.2, 0.1}, 1e-6);
}

TEST(CurveFamilyValidation, EachFamilysBoundsAreNamedByKey) {
  ModelParams p = DeGroote();
  p.degroote2016.active_force_width_scale = 0.9;
  try {
    TensionModel model(p);
    FAIL() << "a width scale below 1 was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "active_force_width_scale");
    EXPECT_THAT(e.rule(), HasSubstr("must be from 1 to 1000"));
  }
  ModelParams m;
  m.family = CurveFamily::kMujoco;
  m.mujoco.lengthrange[0] = 0.2;
  m.mujoco.lengthrange[1] = 0.1;
  EXPECT_THROW(TensionModel{m}, ParameterError);
  m.mujoco.lengthrange[1] = 0.3;
  m.mujoco.fvmax = 1.0;
  try {
    TensionModel model(m);
    FAIL() << "fvmax 1 was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "fvmax");
  }
  m.mujoco.fvmax = 1.2;
  m.pennation_angle = std::numbers::pi / 2;
  try {
    TensionModel model(m);
    FAIL() << "a right pennation angle was accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "pennation_angle");
  }
}

TEST(CurveFamilyFactors, OptimalLengthAndFactorsOfEachFamily) {
  const TensionModel degroote(DeGroote());
  EXPECT_DOUBLE_EQ(degroote.OptimalFiberLength(), 0.1);
  EXPECT_NEAR(degroote.VelocityFactor(0.0).value, 1.0, 1e-15);
  EXPECT_FALSE(degroote.LengthKink().has_value());
  EXPECT_FALSE(degroote.HasVelocityKink());
  ModelParams p;
  p.family = CurveFamily::kMujoco;
  p.mujoco = MujocoSet(0);
  const TensionModel mujoco(p);
  // L = 1 where x = 0.05 + (1 - 0.75) L0, L0 = 0.2 / 0.3
  EXPECT_NEAR(mujoco.OptimalFiberLength(), 0.05 + 0.25 * 0.2 / 0.3, 1e-15);
  EXPECT_NEAR(mujoco.ActiveLengthFactor(mujoco.OptimalFiberLength()).value, 1.0, 1e-15);
  // shortening at vmax L0 stops the active force; lengthening fast saturates at fvmax
  const double vmax = 1.5 * 0.2 / 0.3;
  EXPECT_NEAR(mujoco.VelocityFactor(vmax).value, 0.0, 1e-15);
  EXPECT_NEAR(mujoco.VelocityFactor(-vmax).value, 1.2, 1e-15);
}

}  // namespace
}  // namespace musclesim
