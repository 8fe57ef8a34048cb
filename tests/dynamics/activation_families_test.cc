// The activation dynamics' families (docs/model.md 8.1) against their tools: MuJoCo's
// mju_muscleDynamics tabulated by MuJoCo 4.0 itself (bench/peers/reference/
// mujoco_activation.csv, written by bench/peers/reference_curves.py), with and without
// tausmooth; MuJoCo's step the same law as thelen2003's, each written from its own source;
// every slope against central differences. OpenSim's (degroote2016) is checked through a whole
// trajectory in tests/scenario/opensim_reference_test.cc.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/scenario.h"
#include "support/numeric.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using testing::CentralDifference;
using ::testing::HasSubstr;

ActivationDynamics Mujoco(double tausmooth) {
  ActivationDynamics d;
  d.family = ActivationFamily::kMujoco;
  d.tau_activation = 0.01;  // MuJoCo's default timeconst, the table's
  d.tau_deactivation = 0.04;
  d.tausmooth = tausmooth;
  return d;
}

ActivationDynamics DeGroote(double smoothing) {
  ActivationDynamics d;
  d.family = ActivationFamily::kDeGroote2016;
  d.tau_activation = 0.015;  // OpenSim's defaults
  d.tau_deactivation = 0.06;
  d.smoothing = smoothing;
  return d;
}

TEST(ActivationFamilies, MujocoIsMujocosMuscleDynamicsWithAndWithoutTausmooth) {
  const testing::PeerTable table = testing::ReadPeerTable("mujoco_activation.csv");
  const std::size_t rows = table.at("act_dot").size();
  ASSERT_GT(rows, 200u);
  int smoothed = 0;
  for (std::size_t k = 0; k < rows; ++k) {
    const double w = table.at("tausmooth")[k], e = table.at("ctrl")[k], u = table.at("act")[k];
    const double expected = table.at("act_dot")[k];
    if (w > 0.0) ++smoothed;
    // the same closed form in double precision: a few ulps of the rate's scale (1/tau)
    EXPECT_NEAR(EvaluateActivationRate(Mujoco(w), e, u).value, expected,
                1e-13 * std::max(1.0, std::abs(expected)))
        << "tausmooth " << w << ", e " << e << ", u " << u;
  }
  EXPECT_GT(smoothed, 100);
}

TEST(ActivationFamilies, MujocosStepIsThelensLaw) {
  ActivationDynamics thelen = Mujoco(0.0);
  thelen.family = ActivationFamily::kThelen2003;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      const double e = i / 20.0, u = j / 20.0;
      const ActivationRate a = EvaluateActivationRate(Mujoco(0.0), e, u);
      const ActivationRate b = EvaluateActivationRate(thelen, e, u);
      const double scale = 1.0 / 0.01;
      EXPECT_NEAR(a.value, b.value, 1e-13 * scale) << e << " " << u;
      EXPECT_NEAR(a.by_activation, b.by_activation, 1e-12 * scale) << e << " " << u;
      EXPECT_NEAR(a.by_excitation, b.by_excitation, 1e-12 * scale) << e << " " << u;
    }
  }
  EXPECT_TRUE(HasExcitationKink(thelen));
  EXPECT_TRUE(HasExcitationKink(Mujoco(0.0)));
  EXPECT_FALSE(HasExcitationKink(Mujoco(0.2)));
  EXPECT_FALSE(HasExcitationKink(DeGroote(0.1)));
}

TEST(ActivationFamilies, SlopesAreCentralDifferences) {
  for (const ActivationDynamics& d : {DeGroote(0.1), DeGroote(10.0), Mujoco(0.2), Mujoco(1.5)}) {
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; j <= 10; ++j) {
        // off the grid of the smoothstep's ends, where its third derivative jumps
        const double e = 0.013 + 0.097 * i, u = 0.007 + 0.098 * j;
        const ActivationRate rate = EvaluateActivationRate(d, e, u);
        const double by_u =
            CentralDifference([&](double x) { return EvaluateActivationRate(d, e, x).value; }, u);
        const double by_e =
            CentralDifference([&](double x) { return EvaluateActivationRate(d, x, u).value; }, e);
        const std::string where = std::string(ActivationFamilyName(d.family)) + " e " +
                                  std::to_string(e) + " u " + std::to_string(u);
        EXPECT_NEAR(rate.by_activation, by_u, 1e-6 * std::max(1.0, std::abs(by_u))) << where;
        EXPECT_NEAR(rate.by_excitation, by_e, 1e-6 * std::max(1.0, std::abs(by_e))) << where;
      }
    }
  }
}

TEST(ActivationFamilies, EveryFamilyRestsAtTheExcitationAndMovesTowardsIt) {
  for (const ActivationDynamics& d : {DeGroote(0.1), DeGroote(10.0), Mujoco(0.0), Mujoco(0.2)}) {
    for (const double e : {0.0, 0.3, 0.7, 1.0}) {
      EXPECT_EQ(EvaluateActivationRate(d, e, e).value, 0.0);
      if (e > 0.0) {
        EXPECT_GT(EvaluateActivationRate(d, e, e - 0.1).value, 0.0) << e;
      }
      if (e < 1.0) {
        EXPECT_LT(EvaluateActivationRate(d, e, e + 0.1).value, 0.0) << e;
      }
    }
  }
}

// The YAML block of a single-actuator scenario with `dynamics` as its activation_dynamics.
Scenario Read(const std::string& dynamics) {
  const std::string yaml =
      "model: {family: mujoco, f_iso: 100, lengthrange: [0.05, 0.15]}\n"
      "actuator: {mass: 1}\ninitial: {length: 0.1}\n"
      "excitation: {type: constant, value: 0.5}\n"
      "activation_dynamics: " +
      dynamics +
      "\n"
      "time: {start: 0, end: 0.1}\n";
  return ReadScenario(ParseDocument("families.yaml", yaml), "families.yaml");
}

std::string Refusal(const std::string& dynamics) {
  try {
    Read(dynamics);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ActivationFamilies, YamlReadsEachFamilyAndItsSmoothing) {
  const auto dynamics = [](const Scenario& s) { return s.elements[0].excitation->dynamics; };
  const ActivationDynamics plain = dynamics(Read("{tau_activation: 0.01, tau_deactivation: 0.04}"));
  EXPECT_EQ(plain.family, ActivationFamily::kThelen2003);
  const ActivationDynamics opensim = dynamics(
      Read("{family: degroote2016, tau_activation: 0.015, tau_deactivation: 0.06, smoothing: 5}"));
  EXPECT_EQ(opensim.family, ActivationFamily::kDeGroote2016);
  EXPECT_EQ(opensim.smoothing, 5.0);
  const ActivationDynamics mujoco = dynamics(
      Read("{family: mujoco, tau_activation: 0.01, tau_deactivation: 0.04, tausmooth: 0.2}"));
  EXPECT_EQ(mujoco.family, ActivationFamily::kMujoco);
  EXPECT_EQ(mujoco.tausmooth, 0.2);
  // the defaults are the tools' own
  EXPECT_EQ(dynamics(Read("{family: degroote2016, tau_activation: 0.015, "
                          "tau_deactivation: 0.06}"))
                .smoothing,
            0.1);
  EXPECT_EQ(
      dynamics(Read("{family: mujoco, tau_activation: 0.01, tau_deactivation: 0.04}")).tausmooth,
      0.0);
}

TEST(ActivationFamilies, YamlRefusesAnotherFamilysKeyAndValuesOutOfRange) {
  EXPECT_THAT(Refusal("{family: hill, tau_activation: 0.01, tau_deactivation: 0.04}"),
              HasSubstr("must be thelen2003, degroote2016 or mujoco"));
  EXPECT_THAT(Refusal("{tau_activation: 0.01, tau_deactivation: 0.04, tausmooth: 0.2}"),
              HasSubstr("tausmooth"));
  EXPECT_THAT(
      Refusal("{family: mujoco, tau_activation: 0.01, tau_deactivation: 0.04, smoothing: 1}"),
      HasSubstr("smoothing"));
  EXPECT_THAT(
      Refusal("{family: mujoco, tau_activation: 0.01, tau_deactivation: 0.04, tausmooth: -1}"),
      HasSubstr("activation_dynamics.tausmooth"));
  EXPECT_THAT(Refusal("{family: degroote2016, tau_activation: 0.01, tau_deactivation: 0.04, "
                      "smoothing: 0}"),
              HasSubstr("activation_dynamics.smoothing"));
}

}  // namespace
}  // namespace musclesim
