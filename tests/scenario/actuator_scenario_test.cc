// The single actuator as a network (scenario/actuator_scenario.h, docs/model.md 7.4): the
// network MakeActuatorScenario builds has the actuator's own right-hand side (its closed form,
// ActuatorSystem::Acceleration) and runs as ActuatorSystem's network does, to the last bit; the
// shipped file reads into the scenario built here in code; the key paths of the two forms
// translate both ways; and bad values are refused with the form's own keys.
#include "musclesim/scenario/actuator_scenario.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "support/canonical_actuator.h"
#include "support/canonical_scenarios.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The single-actuator form of a canonical experiment (support/canonical_actuator.h).
ActuatorScenarioSpec SpecOf(const testing::Experiment& e) {
  ActuatorScenarioSpec spec;
  spec.name = "experiment";
  spec.model.params = e.system.model().params();
  spec.actuator = e.system.actuator();
  spec.initial_length = e.request.length;
  spec.initial_lengthening_rate = e.request.lengthening_rate;
  spec.activation = e.system.activation();
  spec.excitation = e.system.excitation();
  spec.loads = e.system.loads().loads();
  spec.t_start = e.request.t_start;
  spec.t_end = e.request.t_end;
  spec.solver = e.options;
  spec.output.interval = e.request.output_interval;
  spec.min_length = e.request.min_length;
  spec.max_length = e.request.max_length;
  return spec;
}

// The concentric experiment with what the canonical ones leave at zero: a damper, a parallel
// spring, a mass load and a spring load beside the step force.
testing::Experiment Everything() {
  const testing::Experiment e = testing::Concentric();
  ActuatorParams actuator = e.system.actuator();
  actuator.damping = 3.0;
  actuator.stiffness = 200.0;
  actuator.rest_length = 0.09;
  std::vector<Load> loads = e.system.loads().loads();
  loads.push_back(Load::Mass(0.05));
  loads.push_back(Load::Spring(50.0, 0.12));
  return {ActuatorSystem(e.system.shared_model(), actuator, e.system.activation(), loads),
          e.request, e.options};
}

// The twitches' activation dynamics on the concentric experiment.
testing::Experiment Excited() {
  const testing::Experiment e = testing::Concentric();
  ExcitationInput input{Waveform::Pulses(0.05, 0.1, 0.01, 0.0, 1.0), {}, 0.2};
  return {
      ActuatorSystem(e.system.shared_model(), e.system.actuator(), input, e.system.loads().loads()),
      e.request, e.options};
}

struct Case {
  const char* name;
  testing::Experiment (*make)();
};

class ActuatorScenario : public ::testing::TestWithParam<Case> {};

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST_P(ActuatorScenario, NetworkHasTheActuatorsOwnRightHandSide) {
  const testing::Experiment e = GetParam().make();
  const Scenario scenario = MakeActuatorScenario(SpecOf(e));
  EXPECT_EQ(scenario.form, ScenarioForm::kActuator);
  const NetworkSystem network = scenario.Build();
  // docs/model.md 7.4: ground and tip, the actuator, the damper and the spring, however small
  ASSERT_EQ(network.nodes().size(), 2u);
  EXPECT_EQ(network.nodes()[0].name, "ground");
  EXPECT_EQ(network.nodes()[0].kind, NodeKind::kFixed);
  EXPECT_EQ(network.nodes()[kActuatorTipNode].name, "tip");
  ASSERT_EQ(network.elements().size(), 3u);
  EXPECT_EQ(network.elements()[kActuatorElement].name, "actuator");
  EXPECT_EQ(network.elements()[kActuatorDamperElement].kind, ElementKind::kDamper);
  EXPECT_EQ(network.elements()[kActuatorSpringElement].kind, ElementKind::kSpring);

  const int n = network.state_size();
  const NetworkSystem& reference = e.system.network();
  ASSERT_EQ(reference.state_size(), n);
  // lengths within 3 cm and speeds within 1 m/s of the start, times over the run
  std::mt19937 random(11);
  std::uniform_real_distribution<double> nudge(-0.03, 0.03), speed(-1.0, 1.0), unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> y = {e.request.length + nudge(random), speed(random)};
    if (n == 3) y.push_back(unit(random));  // the activation state
    const double t = e.request.t_end * unit(random);
    std::vector<double> f(static_cast<std::size_t>(n)), g(f.size());
    network.RightHandSide(t, y.data(), f.data());
    reference.RightHandSide(t, y.data(), g.data());
    for (int i = 0; i < n; ++i) {
      ASSERT_TRUE(SameBits(f[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(i)]))
          << "state " << i << " at t = " << t << ", trial " << trial;
    }
    if (e.system.excitation()) continue;
    // the closed form of docs/model.md section 6, m xddot = F - T - c xdot - k (x - l0),
    // written without any network: the same operations on the same numbers
    EXPECT_EQ(f[0], y[1]);
    ASSERT_TRUE(SameBits(f[1], e.system.Acceleration(t, y[0], y[1])))
        << "at t = " << t << ", trial " << trial << ": " << f[1] << " and "
        << e.system.Acceleration(t, y[0], y[1]);
  }
}

TEST_P(ActuatorScenario, RunsAsTheActuatorSystemDoesToTheLastBit) {
  const testing::Experiment e = GetParam().make();
  const Scenario scenario = MakeActuatorScenario(SpecOf(e));
  std::vector<TrajectoryPoint> from_scenario;
  const RunStats stats = testing::RunActuator(scenario, from_scenario);
  const RunResult reference = e.Run();
  ASSERT_EQ(stats.status, reference.stats.status) << stats.message;
  EXPECT_EQ(stats.steps, reference.stats.steps);
  EXPECT_EQ(stats.final_time, reference.stats.final_time);
  ASSERT_EQ(from_scenario.size(), reference.trajectory.size());
  ASSERT_GT(from_scenario.size(), 10u);
  for (std::size_t k = 0; k < from_scenario.size(); ++k) {
    const ActuatorSample& a = from_scenario[k].sample;
    const ActuatorSample& b = reference.trajectory[k].sample;
    ASSERT_EQ(from_scenario[k].t, reference.trajectory[k].t) << k;
    const double mine[] = {a.length,          a.shortening_velocity, a.activation,    a.excitation,
                           a.tension.passive, a.tension.active,      a.tension.total, a.load};
    const double theirs[] = {
        b.length,          b.shortening_velocity, b.activation,    b.excitation,
        b.tension.passive, b.tension.active,      b.tension.total, b.load};
    for (int i = 0; i < 8; ++i) {
      ASSERT_TRUE(SameBits(mine[i], theirs[i])) << "field " << i << " at t = " << from_scenario[k].t
                                                << ": " << mine[i] << " and " << theirs[i];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Experiments, ActuatorScenario,
    ::testing::Values(Case{"concentric", testing::Concentric},
                      Case{"eccentric", testing::Eccentric}, Case{"isometric", testing::Isometric},
                      Case{"everything", Everything}, Case{"excited", Excited}),
    [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

TEST(ActuatorScenarioFile, TheShippedFileIsTheScenarioBuiltInCode) {
  // scenarios/concentric.yaml read, and its numbers written into code: the same parts and
  // the same run, bit for bit
  const Scenario read = LoadScenario(testing::ScenarioPath("concentric.yaml"));
  const Scenario built = testing::ConcentricScenario();
  EXPECT_EQ(read.name, built.name);
  EXPECT_EQ(read.form, built.form);
  ASSERT_EQ(read.elements.size(), built.elements.size());
  for (std::size_t e = 0; e < read.elements.size(); ++e) {
    EXPECT_EQ(read.elements[e].name, built.elements[e].name);
    EXPECT_EQ(read.elements[e].kind, built.elements[e].kind);
  }
  EXPECT_EQ(read.output.file, built.output.file);
  ASSERT_EQ(read.limits.size(), 1u);
  EXPECT_EQ(read.limits[0].element, "actuator");
  EXPECT_TRUE(testing::SameRecordedRun(RunScenario(read), RunScenario(built)));
}

TEST(ActuatorKeyPaths, EveryKeyOfTheFormHasItsPlaceInTheNetwork) {
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"model.f_iso", "models.model.f_iso"},
      {"model.velocity.eccentric.limit", "models.model.velocity.eccentric.limit"},
      {"actuator.mass", "nodes[1].mass"},
      {"actuator.damping", "elements[1].damping"},
      {"actuator.stiffness", "elements[2].stiffness"},
      {"actuator.rest_length", "elements[2].rest_length"},
      {"initial.length", "nodes[1].position"},
      {"initial.lengthening_rate", "nodes[1].velocity"},
      {"initial.activation", "elements[0].initial_activation"},
      {"activation.after", "elements[0].activation.after"},
      {"excitation.high", "elements[0].excitation.high"},
      {"activation_dynamics.tau_activation", "elements[0].activation_dynamics.tau_activation"},
      {"load[0].value", "loads[0].value"},
      {"load[2].points[1][0]", "loads[2].points[1][0]"},
      {"limits.min_length", "limits[0].min_length"},
      {"limits.max_length", "limits[0].max_length"},
      // the keys both forms share
      {"time.end", "time.end"},
      {"solver.rtol", "solver.rtol"},
      {"output.interval", "output.interval"},
      {"name", "name"},
  };
  for (const auto& [actuator, network] : pairs) {
    EXPECT_EQ(NetworkKeyPath(actuator).value_or("(none)"), network) << actuator;
    EXPECT_EQ(ActuatorKeyPath(network), actuator) << network;
    // the round trip, both ways
    EXPECT_EQ(ActuatorKeyPath(NetworkKeyPath(actuator).value_or("")), actuator);
    EXPECT_EQ(NetworkKeyPath(ActuatorKeyPath(network)).value_or("(none)"), network);
  }
  // one load written as a map is load[0]: its key reads back as load[0]
  EXPECT_EQ(NetworkKeyPath("load.value").value_or("(none)"), "loads[0].value");
  EXPECT_EQ(ActuatorKeyPath("loads[0].value"), "load[0].value");
}

TEST(ActuatorKeyPaths, KeysOutsideEitherVocabularyAreLeftAlone) {
  // not a key of the single-actuator form: the network's own vocabulary, or nothing
  for (const char* path : {"nodes[1].mass", "models.model.f_iso", "elements[0].activation.after",
                           "loads[0].value", "actuators.mass", "modelx.f_iso", "colour"}) {
    EXPECT_FALSE(NetworkKeyPath(path).has_value()) << path;
  }
  // a path into the network with no key of the form reads back unchanged
  for (const char* path :
       {"nodes[0].fixed", "elements[3].stiffness", "controllers[0].gains.kp", "nodes[1].mass2"}) {
    EXPECT_EQ(ActuatorKeyPath(path), path);
  }
}

// The ParameterError MakeActuatorScenario throws for the concentric spec changed by `edit`.
template <typename Edit>
std::string RefusalOf(Edit edit) {
  ActuatorScenarioSpec spec = testing::ConcentricSpec();
  edit(spec);
  try {
    MakeActuatorScenario(spec);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ActuatorScenarioSpec, BadValuesAreRefusedWithTheFormsKeys) {
  EXPECT_THAT(RefusalOf([](ActuatorScenarioSpec& s) { s.actuator.mass = 0.0; }),
              HasSubstr("actuator.mass = 0"));
  EXPECT_THAT(RefusalOf([](ActuatorScenarioSpec& s) { s.actuator.damping = -1.0; }),
              HasSubstr("actuator.damping = -1"));
  EXPECT_THAT(RefusalOf([](ActuatorScenarioSpec& s) { s.actuator.stiffness = -5.0; }),
              HasSubstr("actuator.stiffness = -5"));
  EXPECT_THAT(RefusalOf([](ActuatorScenarioSpec& s) { s.model.params.velocity.n = 0; }),
              HasSubstr("model.velocity.n = 0"));
  EXPECT_THAT(RefusalOf([](ActuatorScenarioSpec& s) {
                s.excitation = ExcitationInput{Waveform::Constant(0.5), {}, 1.5};
              }),
              HasSubstr("initial.activation = 1.5"));
  EXPECT_EQ(RefusalOf([](ActuatorScenarioSpec&) {}), "accepted");
}

TEST(ActuatorSampleOf, IsTheActuatorElementAndTheLoadOnTheTip) {
  NetworkSample s;
  s.position = {0.0, 0.1};
  s.velocity = {0.0, 0.0};
  s.load = {0.0, 40.0};
  s.elements.resize(3);
  s.elements[kActuatorElement].length = 0.1;
  s.elements[kActuatorElement].lengthening_rate = 0.0;
  s.elements[kActuatorElement].activation = 0.5;
  s.elements[kActuatorElement].excitation = 0.75;
  s.elements[kActuatorElement].parts = {1.0, 2.0, 3.0, 0.0, 0.0, 0.0};
  s.elements[kActuatorDamperElement].tension = 99.0;  // not the actuator's
  const ActuatorSample a = ActuatorSampleOf(s);
  EXPECT_EQ(a.length, 0.1);
  EXPECT_EQ(a.activation, 0.5);
  EXPECT_EQ(a.excitation, 0.75);
  EXPECT_EQ(a.tension.total, 3.0);
  EXPECT_EQ(a.load, 40.0);
  // at rest the shortening velocity is +0, not -0 (the CSV writes "0", never "-0")
  EXPECT_TRUE(SameBits(a.shortening_velocity, 0.0));
  s.elements[kActuatorElement].lengthening_rate = -0.25;
  EXPECT_EQ(ActuatorSampleOf(s).shortening_velocity, 0.25);
}

}  // namespace
}  // namespace musclesim
