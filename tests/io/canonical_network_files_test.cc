// The canonical network scenario files describe the very systems that
// network_simulation_test checks against closed forms, root solves and energy balances
// (tests/support/canonical_networks.h builds them in code): the file read by the reader has
// the same nodes, elements, initial state, time span and right-hand side, bit for bit.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "musclesim/io/readers/scenario_yaml.h"
#include "support/canonical_networks.h"

namespace musclesim {
namespace {

struct Canonical {
  const char* file;
  testing::NetworkExperiment (*make)();
};

testing::NetworkExperiment Msd() { return testing::MassSpringDamper(); }
testing::NetworkExperiment Pair() { return testing::AntagonistPair(); }
testing::NetworkExperiment Mtu() { return testing::MusculotendonIsokinetic(); }
testing::NetworkExperiment Millard() { return testing::MillardBenchmark(); }
testing::NetworkExperiment Chain10() { return testing::Chain(10); }

class CanonicalNetworkFile : public ::testing::TestWithParam<Canonical> {};

// `from_file`, of the scenario `spec`, is `tested`'s system: its parts, span, initial state
// and right-hand side.
void ExpectTheTestedSystem(const Scenario& spec, const NetworkSystem& from_file,
                           const testing::NetworkExperiment& tested) {
  const NetworkSystem& in_code = tested.system;

  ASSERT_EQ(from_file.nodes().size(), in_code.nodes().size());
  for (std::size_t i = 0; i < in_code.nodes().size(); ++i) {
    EXPECT_EQ(from_file.nodes()[i].name, in_code.nodes()[i].name);
    EXPECT_EQ(from_file.nodes()[i].kind, in_code.nodes()[i].kind);
  }
  ASSERT_EQ(from_file.elements().size(), in_code.elements().size());
  for (std::size_t e = 0; e < in_code.elements().size(); ++e) {
    EXPECT_EQ(from_file.elements()[e].name, in_code.elements()[e].name);
    EXPECT_EQ(from_file.elements()[e].kind, in_code.elements()[e].kind);
  }
  EXPECT_EQ(spec.Request().t_start, tested.request.t_start);
  EXPECT_EQ(spec.Request().t_end, tested.request.t_end);

  const int n = in_code.state_size();
  ASSERT_EQ(from_file.state_size(), n);
  std::vector<double> y0(n), y0_file(n);
  in_code.InitialState(y0.data());
  from_file.InitialState(y0_file.data());
  EXPECT_EQ(y0_file, y0);

  // the same parameters give the same floating-point operations: equal to the last bit,
  // at states around the start (lengths stay positive: 1 mm and 1 m/s perturbations)
  std::mt19937 random(7);
  std::uniform_real_distribution<double> nudge(-1e-3, 1e-3), speed(-1.0, 1.0), time(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> y = y0;
    for (int i = 0; i < n; i += 2) {
      y[i] += nudge(random);
      y[i + 1] += speed(random);
    }
    const double t = tested.request.t_end * time(random);
    std::vector<double> f(n), f_file(n);
    in_code.RightHandSide(t, y.data(), f.data());
    from_file.RightHandSide(t, y.data(), f_file.data());
    ASSERT_EQ(f_file, f) << "at t = " << t << ", trial " << trial;
  }
}

std::string PathOf(const Canonical& canonical) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + canonical.file;
}

TEST_P(CanonicalNetworkFile, IsTheSystemItsTestsCheck) {
  const Scenario spec = LoadScenario(PathOf(GetParam()));
  ExpectTheTestedSystem(spec, spec.Build(), GetParam().make());
}

// The run verb's system, which the reader built while checking the file, is the same one.
TEST_P(CanonicalNetworkFile, HandsTheRunTheSystemItsTestsCheck) {
  const std::string path = PathOf(GetParam());
  const LoadedScenario loaded = LoadBuiltScenario(path, {}, path);
  ASSERT_NE(loaded.system, nullptr);
  ExpectTheTestedSystem(loaded.scenario, *loaded.system, GetParam().make());
}

INSTANTIATE_TEST_SUITE_P(Scenarios, CanonicalNetworkFile,
                         ::testing::Values(Canonical{"mass_spring_damper.yaml", Msd},
                                           Canonical{"antagonist_pair.yaml", Pair},
                                           Canonical{"musculotendon_isokinetic.yaml", Mtu},
                                           Canonical{"millard_benchmark.yaml", Millard},
                                           Canonical{"chain.yaml", Chain10}),
                         [](const ::testing::TestParamInfo<Canonical>& param) {
                           std::string name = param.param.file;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace musclesim
