// Network scenario files (io/readers/scenario_yaml.h) and their CSV (io/writers/run_csv.h): what
// the reader makes of every kind of node, element and load, the CSV's columns, its first row
// against a hand computation of docs/model.md sections 2-5 and 7.1, --set on nested keys,
// and `musclesim run` on a network.
#include "musclesim/io/readers/scenario_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <sys/wait.h>

#include "musclesim/io/writers/run_csv.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/run_columns.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::ReadFile;
using testing::WriteTempFile;

// Every kind of node, element and load (tests/fixtures/every_part.yaml, whose numbers the
// hand computation below repeats).
std::string EveryPart() { return testing::FixturePath("every_part.yaml"); }

TEST(NetworkScenario, ReadsEveryNodeElementLoadAndLimit) {
  const Scenario s = LoadScenario(EveryPart());
  EXPECT_EQ(s.name, "every_part");
  EXPECT_EQ(s.form, ScenarioForm::kNetwork);
  ASSERT_EQ(s.nodes.size(), 4u);
  EXPECT_EQ(s.nodes[0].kind, NodeKind::kFixed);
  EXPECT_EQ(s.nodes[0].position, 0.0);
  EXPECT_EQ(s.nodes[1].kind, NodeKind::kFree);
  EXPECT_EQ(s.nodes[1].mass, 0.5);
  EXPECT_EQ(s.nodes[1].position, 0.1);
  EXPECT_EQ(s.nodes[1].velocity, 0.2);
  EXPECT_EQ(s.nodes[2].position, 0.2);
  EXPECT_EQ(s.nodes[3].kind, NodeKind::kPrescribed);
  EXPECT_EQ(s.nodes[3].motion.kind, WaveformKind::kSine);
  EXPECT_EQ(s.nodes[3].motion.phase, 0.5);

  ASSERT_EQ(s.elements.size(), 6u);
  const Element& flexor = s.elements[0];
  EXPECT_EQ(flexor.kind, ElementKind::kActuator);
  EXPECT_EQ(flexor.from, "wall_a");
  EXPECT_EQ(flexor.to, "load");
  EXPECT_EQ(flexor.model->params().f_iso, 100.0);  // its own model block, not the other
  EXPECT_EQ(flexor.activation.kind, WaveformKind::kStep);
  EXPECT_EQ(s.elements[1].model->params().f_iso, 80.0);
  EXPECT_EQ(s.elements[1].activation.value, 0.3);
  EXPECT_EQ(s.elements[2].kind, ElementKind::kTendon);
  EXPECT_FALSE(s.elements[2].exponential());
  EXPECT_EQ(s.elements[2].stiffness, 2.0e4);
  EXPECT_EQ(s.elements[2].slack_length, 0.18);
  EXPECT_TRUE(s.elements[3].exponential());
  EXPECT_EQ(s.elements[3].k, 3.0);
  EXPECT_EQ(s.elements[3].alpha, 20.0);
  EXPECT_EQ(s.elements[4].kind, ElementKind::kSpring);
  EXPECT_EQ(s.elements[4].rest_length, 0.08);
  EXPECT_EQ(s.elements[5].kind, ElementKind::kDamper);
  EXPECT_EQ(s.elements[5].damping, 2.0);
  EXPECT_EQ(s.models.size(), 2u);
  EXPECT_EQ(s.models.at("extensor").spec.params.velocity.n, 1);
  // each actuator holds its block's model
  EXPECT_EQ(s.elements[1].model, s.models.at("extensor").model);

  ASSERT_EQ(s.loads.size(), 3u);
  EXPECT_EQ(s.loads[0].node, "load");
  EXPECT_EQ(s.loads[0].load.force.value, 5.0);
  EXPECT_EQ(s.loads[1].load.kind, LoadKind::kMass);
  EXPECT_EQ(s.loads[2].load.anchor, 0.12);

  ASSERT_EQ(s.limits.size(), 2u);
  EXPECT_EQ(s.limits[0].element, "flexor");
  EXPECT_EQ(*s.limits[0].min_length, 0.05);
  EXPECT_EQ(*s.limits[0].max_length, 0.15);
  EXPECT_EQ(s.limits[1].element, "tendon");
  EXPECT_FALSE(s.limits[1].min_length.has_value());
  EXPECT_EQ(s.solver.linear_solver, LinearSolverKind::kDense);
  EXPECT_EQ(s.Request().t_start, 0.25);
  EXPECT_EQ(s.Request().output_interval, 0.001);
}

TEST(NetworkScenario, CsvHeaderIsTheContractsColumnsInOrder) {
  const Scenario s = LoadScenario(EveryPart());
  EXPECT_EQ(CsvHeader(RunColumns(s, s.Build())),
            "t,wall_a.position,wall_a.velocity,load.position,load.velocity,wall_b.position,"
            "wall_b.velocity,crank.position,crank.velocity,"
            "flexor.length,flexor.tension,flexor.shortening_velocity,flexor.activation,"
            "flexor.tension_passive,flexor.tension_active,flexor.phase,"
            "extensor.length,extensor.tension,extensor.shortening_velocity,extensor.activation,"
            "extensor.tension_passive,extensor.tension_active,extensor.phase,"
            "tendon.length,tendon.tension,cable.length,cable.tension,spring.length,"
            "spring.tension,damper.length,damper.tension,load.load");
}

struct Outcome {
  int exit_code;
  std::string err;
};

Outcome RunCli(const std::string& arguments) {
  const std::string err_path = ::testing::TempDir() + "network_scenario_test_stderr_" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const int status = std::system(
      (std::string(MUSCLESIM_BINARY) + " " + arguments + " >/dev/null 2>" + err_path).c_str());
  return {WEXITSTATUS(status), ReadFile(err_path)};
}

// The CSV's first two lines as column name -> text.
std::map<std::string, std::string> FirstRow(const std::string& csv) {
  std::istringstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  std::istringstream names(header), values(row);
  std::map<std::string, std::string> out;
  for (std::string name, value;
       std::getline(names, name, ',') && std::getline(values, value, ',');) {
    out[name] = value;
  }
  return out;
}

TEST(NetworkScenario, FirstRowAgreesWithAHandComputation) {
  const std::string path = EveryPart();
  const std::string csv = ::testing::TempDir() + "network_first_row.csv";
  ASSERT_EQ(RunCli("run " + path + " -o " + csv + " --quiet").exit_code, 0);
  const std::map<std::string, std::string> row = FirstRow(ReadFile(csv));
  ASSERT_EQ(row.size(), 32u);
  const auto at = [&](const std::string& column) { return std::stod(row.at(column)); };

  // docs/model.md sections 2-5 and 7.1 at t = time.start, from the file's numbers
  const double t = 0.25, pi = std::numbers::pi;
  const double x = 0.1, v = 0.2;  // the free node
  const double crank = 0.3 + 0.01 * std::sin(2.0 * pi * t + 0.5);
  const double crank_rate = 0.01 * 2.0 * pi * std::cos(2.0 * pi * t + 0.5);
  const double f_length = std::exp(-4000.0 * ((x - 0.1) * (x - 0.1) - 0.005 * 0.005) / 2.0);
  // flexor, wall_a -> load: shortening velocity -v; n = 3, eps = 1e-3, v_max = 1
  const double flexor_v = -v;
  const double phi = flexor_v * std::pow(flexor_v * flexor_v + 1e-6, (1.0 / 3.0 - 1.0) / 2.0);
  const double flexor_passive = 1.0 * (std::exp(100.0 * (x - 0.095)) - 1.0);
  const double flexor_active = 0.4 * 100.0 * f_length * (1.0 - phi);
  // extensor, load -> wall_b: shortening velocity +v; n = 1 makes g linear, 1 - v / v_max
  const double extensor_active = 0.3 * 80.0 * f_length * (1.0 - v);
  const std::map<std::string, double> expected = {
      {"t", t},
      {"wall_a.position", 0.0},
      {"wall_a.velocity", 0.0},
      {"load.position", x},
      {"load.velocity", v},
      {"wall_b.position", 0.2},
      {"wall_b.velocity", 0.0},
      {"crank.position", crank},
      {"crank.velocity", crank_rate},
      {"flexor.length", x},
      {"flexor.shortening_velocity", flexor_v},
      {"flexor.activation", 0.4},
      {"flexor.tension_passive", flexor_passive},
      {"flexor.tension_active", flexor_active},
      {"flexor.tension", flexor_passive + flexor_active},
      {"extensor.length", 0.2 - x},
      {"extensor.shortening_velocity", v},
      {"extensor.activation", 0.3},
      {"extensor.tension_passive", 0.0},
      {"extensor.tension_active", extensor_active},
      {"extensor.tension", extensor_active},
      {"tendon.length", crank - x},
      {"tendon.tension", 2.0e4 * (crank - x - 0.18)},
      {"cable.length", x},
      {"cable.tension", 3.0 * (std::exp(20.0 * (x - 0.05)) - 1.0)},
      {"spring.length", x},
      {"spring.tension", 50.0 * (x - 0.08)},
      {"damper.length", x},
      {"damper.tension", 2.0 * v},
      {"load.load", 5.0 + 0.2 * 9.81 + 100.0 * (0.12 - x)},
  };
  for (const auto& [column, value] : expected) {
    // the same formulas in another order of operations: a few roundoffs of the largest
    // term (the tendon's 2e4 N/m times a length of 0.2 m)
    EXPECT_NEAR(at(column), value, 1e-12 * std::max(1.0, std::abs(value))) << column;
  }
  // |v| = 0.2 against each actuator's own epsilon: 1e-3 for the flexor, 0.5 for the extensor
  EXPECT_EQ(row.at("flexor.phase"), "eccentric");
  EXPECT_EQ(row.at("extensor.phase"), "isometric");
}

TEST(NetworkScenario, PhaseToleranceOfTheOutputOverridesEveryModels) {
  const std::string path = EveryPart();
  const std::string csv = ::testing::TempDir() + "network_phase.csv";
  ASSERT_EQ(
      RunCli("run " + path + " -o " + csv + " --quiet --set output.phase_tolerance=0.1").exit_code,
      0);
  const std::map<std::string, std::string> row = FirstRow(ReadFile(csv));
  EXPECT_EQ(row.at("flexor.phase"), "eccentric");     // v = -0.2 < -0.1
  EXPECT_EQ(row.at("extensor.phase"), "concentric");  // v = 0.2 > 0.1
}

TEST(NetworkScenario, SetReachesNestedKeysOfListsAndModels) {
  const std::string path = EveryPart();
  const Scenario s = LoadScenario(
      path, {"elements[0].activation.after=0.5", "nodes[1].mass=2", "models.flexor.f_iso=50",
             "elements[3].exponential.k=7", "nodes[3].prescribed.amplitude=0.02",
             "loads[1].gravity=-9.81", "limits[1].max_length=0.4"});
  EXPECT_EQ(s.elements[0].activation.after, 0.5);
  EXPECT_EQ(s.nodes[1].mass, 2.0);
  EXPECT_EQ(s.elements[0].model->params().f_iso, 50.0);
  EXPECT_EQ(s.elements[3].k, 7.0);
  EXPECT_EQ(s.nodes[3].motion.amplitude, 0.02);
  EXPECT_EQ(s.loads[1].load.gravity, -9.81);
  EXPECT_EQ(*s.limits[1].max_length, 0.4);
  // an override is validated as the file's value, and named as one
  EXPECT_THAT(testing::InputErrorOf(
                  path, [&] { LoadScenario(path, {"elements[1].activation.value=1.5"}); }),
              HasSubstr("elements[1].activation.value = 1.5 (override): activation must stay "
                        "within [0, 1]"));
}

// The form of a file is told by its top-level keys (ScenarioTemplate::form, which
// LoadScenario follows): a top-level `nodes:` key is a network.
bool IsNetworkScenario(const std::string& path) {
  return ScenarioTemplate(path).form() == ScenarioForm::kNetwork;
}

TEST(NetworkScenario, IsNetworkScenarioLooksAtTopLevelKeysOnly) {
  EXPECT_TRUE(IsNetworkScenario(EveryPart()));
  EXPECT_TRUE(IsNetworkScenario(WriteTempFile("flow.yaml", "{time: {start: 0}, nodes: []}\n")));
  EXPECT_FALSE(IsNetworkScenario(testing::ScenarioPath("concentric.yaml")));
  // `nodes` as a value, or below the top level, is not the key
  EXPECT_FALSE(IsNetworkScenario(WriteTempFile("value.yaml", "name: nodes\nx: {nodes: 1}\n")));
  EXPECT_FALSE(IsNetworkScenario(WriteTempFile("list.yaml", "- nodes\n- {nodes: 1}\n")));
  // an empty file has no form: reading it says so, whichever reader is asked
  const std::string empty = WriteTempFile("empty.yaml", "# nothing\n");
  EXPECT_THAT(testing::InputErrorOf(empty, [&] { IsNetworkScenario(empty); }),
              HasSubstr("FILE: the file is empty"));
  EXPECT_THAT(testing::InputErrorOf(empty, [&] { LoadScenario(empty); }),
              HasSubstr("FILE: the file is empty"));
  EXPECT_THROW(IsNetworkScenario(::testing::TempDir() + "no_such_network.yaml"), InputError);
  // and the scenario read is of that form
  EXPECT_EQ(LoadScenario(testing::ScenarioPath("concentric.yaml")).form, ScenarioForm::kActuator);
  EXPECT_EQ(LoadScenario(EveryPart()).form, ScenarioForm::kNetwork);
}

// A free node moving towards a fixed one at 1 m/s with nothing to stop it: the spring
// between them (k = 0) reaches zero length at t = 0.1 s.
constexpr const char* kCollapse =
    R"(nodes: [{name: wall, fixed: 0.0}, {name: a, mass: 1, position: 0.1, velocity: -1}]
elements: [{name: gap, type: spring, from: wall, to: a, stiffness: 0, rest_length: 0.1}]
time: {start: 0, end: 1}
output: {interval: 0.01}
)";

TEST(NetworkScenario, AnElementReachingZeroLengthFailsTheRun) {
  const RecordedRun result = RunScenario(LoadScenario(WriteTempFile("collapse.yaml", kCollapse)));
  EXPECT_EQ(result.stats.status, RunStatus::kFailed);
  EXPECT_THAT(result.stats.message, HasSubstr("the length of gap reached zero"));
  // x = 0.1 - t exactly: the root is found to CVODE's root tolerance, far below 1e-6 s
  EXPECT_NEAR(result.stats.final_time, 0.1, 1e-6);
}

TEST(NetworkScenario, RunExitsThreeOnCollapseAndKeepsTheEarlierCsv) {
  const std::string path = WriteTempFile("collapse.yaml", kCollapse);
  const std::string csv = ::testing::TempDir() + "network_collapse.csv";
  std::ofstream(csv) << "earlier\n";
  const Outcome r = RunCli("run " + path + " -o " + csv);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_THAT(r.err, HasSubstr("solver failure: the length of gap reached zero"));
  EXPECT_EQ(ReadFile(csv), "earlier\n");
  EXPECT_THAT(ReadFile(csv + ".partial"), HasSubstr("t,wall.position,wall.velocity,a.position"));
}

TEST(NetworkScenario, RunPrintsTheLinearSolverInItsSummary) {
  const std::string path = EveryPart();
  const Outcome r = RunCli("run " + path + " -o " + ::testing::TempDir() + "network_summary.csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("every_part: completed at t = 0.26 s: "));
  EXPECT_THAT(r.err, HasSubstr(" dense linear solver, 11 rows -> "));
}

}  // namespace
}  // namespace musclesim
