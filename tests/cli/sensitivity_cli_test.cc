// `musclesim run --sensitivity PATH` and a scenario's `sensitivities:` list, end to end
// through the built program: the CSV's header (the plain run's columns, then
// d_<column>/d_<path> for every parameter and differentiated column), the same columns from
// the scenario's key as from the flag, the stats JSON naming how each df/dp is computed, the
// plain columns of a run with sensitivities against a plain run's, and the exit code of each
// refusal.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/cli_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::ContainsRegex;
using testing::CsvText;
using ::testing::HasSubstr;
using testing::ReadCsv;
using testing::RunMusclesim;
using testing::TempPath;

constexpr const char* kModel = R"(model:
  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians:
      - {amplitude: 2.2575025981825489, width: 4125.1402656159307, center: 0.097194271247335401}
      - {amplitude: 1.3136662819543681, width: 3009.3607405177986, center: 0.1301541244400391}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2}
)";

// A concentric contraction: activated at 0.05 s as a 40 N load comes on (a breakpoint).
constexpr const char* kSingleRest = R"(actuator: {mass: 0.1, damping: 0.0}
initial: {length: 0.1}
activation: {type: step, time: 0.05, before: 0.2, after: 1.0}
load:
  - {type: step, time: 0.05, before: 10.0, after: 40.0}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-10, atol: 1.0e-13}
output: {file: single.csv, interval: 0.01}
)";

// The same through activation dynamics.
constexpr const char* kExcitedRest = R"(actuator: {mass: 0.1}
initial: {length: 0.1, activation: 0.2}
excitation: {type: step, time: 0.05, before: 0.2, after: 1.0}
activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}
load: {type: constant, value: 30.0}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-10, atol: 1.0e-13}
output: {file: excited.csv, interval: 0.01}
)";

// Two actuators of one model holding a mass, the flexor through activation dynamics; a
// spring from the mass to a third wall.
constexpr const char* kNetwork = R"(name: cli_network
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-2}
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1, velocity: 0.0}
  - {name: wall_b, fixed: 0.2}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle, excitation: {type: constant, value: 0.6}, activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}, initial_activation: 0.3}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle, activation: {type: constant, value: 0.4}}
  - {name: holder, type: spring, from: load, to: wall_b, stiffness: 100.0, rest_length: 0.1}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-10, atol: 1.0e-13}
output: {file: network.csv, interval: 0.01}
)";

std::string Single(const std::string& extra = "") {
  return testing::WriteTempFile("single.yaml",
                                std::string("name: cli_single\n") + kModel + kSingleRest + extra);
}
std::string Excited() {
  return testing::WriteTempFile("excited.yaml",
                                std::string("name: cli_excited\n") + kModel + kExcitedRest);
}
std::string Network() { return testing::WriteTempFile("network.yaml", kNetwork); }

// The columns the CSV documents for a single actuator (docs/guide/scenarios.md).
constexpr const char* kPlainHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,"
    "phase";
constexpr const char* kPlainHeaderWithExcitation =
    "t,length,shortening_velocity,activation,excitation,tension_passive,tension_active,"
    "tension_total,load,phase";

// d_<column>/d_<path> for every path, and within it every differentiated column.
std::string DerivativeColumns(const std::vector<std::string>& paths,
                              const std::vector<std::string>& columns) {
  std::string out;
  for (const std::string& path : paths) {
    for (const std::string& column : columns) out += ",d_" + column + "/d_" + path;
  }
  return out;
}

// `musclesim run SCENARIO -o CSV --quiet` with `arguments`; the CSV, after a zero exit.
CsvText RunToCsv(const std::string& scenario, const std::string& csv,
                 const std::string& arguments = "") {
  const testing::CliOutcome r =
      RunMusclesim("run " + scenario + " -o " + csv + " --quiet " + arguments);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return ReadCsv(csv);
}

TEST(SensitivityCli, SingleActuatorHeader) {
  const CsvText csv = RunToCsv(Single(), TempPath("out.csv"),
                               "--sensitivity model.f_iso --sensitivity actuator.mass");
  EXPECT_EQ(csv.header,
            kPlainHeader + DerivativeColumns({"model.f_iso", "actuator.mass"},
                                             {"length", "shortening_velocity", "tension_passive",
                                              "tension_active", "tension_total"}));
  ASSERT_FALSE(csv.rows.empty());
  for (const auto& row : csv.rows) EXPECT_EQ(row.size(), csv.columns.size());
}

TEST(SensitivityCli, SingleActuatorHeaderWithActivationDynamics) {
  // the activation is a state here, and differentiated with the others
  const CsvText csv =
      RunToCsv(Excited(), TempPath("out.csv"), "--sensitivity activation_dynamics.tau_activation");
  EXPECT_EQ(csv.header,
            kPlainHeaderWithExcitation +
                DerivativeColumns({"activation_dynamics.tau_activation"},
                                  {"length", "shortening_velocity", "activation", "tension_passive",
                                   "tension_active", "tension_total"}));
}

TEST(SensitivityCli, NetworkHeader) {
  const std::string scenario = Network();
  // the plain run's own header comes first, unchanged
  const CsvText plain = RunToCsv(scenario, TempPath("plain.csv"));
  const CsvText csv = RunToCsv(scenario, TempPath("out.csv"),
                               "--sensitivity models.muscle.f_iso --sensitivity 'nodes[1].mass'");
  // free nodes' states, then every element's length and tension, an actuator's activation
  // (a state only with activation dynamics) and its tension's parts (scenario/sensitivity_run.h)
  const std::vector<std::string> columns = {"load.position",           "load.velocity",
                                            "flexor.length",           "flexor.tension",
                                            "flexor.activation",       "flexor.tension_passive",
                                            "flexor.tension_active",   "extensor.length",
                                            "extensor.tension",        "extensor.tension_passive",
                                            "extensor.tension_active", "holder.length",
                                            "holder.tension"};
  EXPECT_EQ(csv.header,
            plain.header + DerivativeColumns({"models.muscle.f_iso", "nodes[1].mass"}, columns));
}

TEST(SensitivityCli, ScenarioKeyGivesTheFlagsColumns) {
  // the flag's parameters come first, then the file's list, a repeat dropped: the same bytes
  // as both given by the flag in that order
  const std::string listed = Single("sensitivities: [model.f_iso, actuator.mass]\n");
  const std::string by_key = TempPath("key.csv");
  RunToCsv(listed, by_key, "--sensitivity 'load[0].after' --sensitivity model.f_iso");
  const std::string by_flag = TempPath("flag.csv");
  RunToCsv(Single(), by_flag,
           "--sensitivity 'load[0].after' --sensitivity model.f_iso --sensitivity actuator.mass");
  const std::string key_text = testing::ReadText(by_key);
  EXPECT_THAT(key_text, HasSubstr("d_length/d_load[0].after,"));
  EXPECT_EQ(key_text, testing::ReadText(by_flag));
}

TEST(SensitivityCli, StatsNameTheDerivativeSource) {
  const std::string stats = TempPath("stats.json");
  RunToCsv(Single(), TempPath("out.csv"),
           "--sensitivity model.velocity.v_max --sensitivity 'load[0].after' --stats " + stats);
  const std::string json = testing::ReadText(stats);
  // a tension model's parameter in closed form, anything else by difference quotient
  EXPECT_THAT(json, HasSubstr(R"({"path": "model.velocity.v_max", "derivative": "analytic"})"));
  EXPECT_THAT(json, HasSubstr(R"({"path": "load[0].after", "derivative": "difference_quotient"})"));
  EXPECT_THAT(json, HasSubstr("\"sensitivity_rhs_evals\": "));

  const std::string network_stats = TempPath("network.json");
  RunToCsv(Network(), TempPath("network.csv"),
           "--sensitivity models.muscle.passive.k_p --sensitivity "
           "'elements[0].activation_dynamics.tau_activation' --stats " +
               network_stats);
  const std::string network_json = testing::ReadText(network_stats);
  EXPECT_THAT(network_json,
              HasSubstr(R"({"path": "models.muscle.passive.k_p", "derivative": "analytic"})"));
  EXPECT_THAT(network_json,
              HasSubstr(R"({"path": "elements[0].activation_dynamics.tau_activation", )"
                        R"("derivative": "difference_quotient"})"));
}

// Every plain column of a run with sensitivities against the plain run's. The two follow the
// same trajectory but take different steps (the sensitivities join the error test), so they
// differ by the integrators' global errors: at rtol 1e-10 those stay below 1e-8 of each
// column's scale here (measured 1.6e-9), where a wrong state or column would be off by far
// more.
void ExpectPlainColumnsMatch(const std::string& scenario, const std::string& parameter) {
  const CsvText plain = RunToCsv(scenario, TempPath("plain.csv"));
  const CsvText with = RunToCsv(scenario, TempPath("with.csv"), "--sensitivity " + parameter);
  ASSERT_EQ(with.rows.size(), plain.rows.size());
  const std::size_t columns = plain.columns.size();
  ASSERT_EQ(std::vector<std::string>(with.columns.begin(), with.columns.begin() + columns),
            plain.columns);
  for (std::size_t c = 0; c < columns; ++c) {
    const std::string& name = plain.columns[c];
    if (name.size() >= 5 && name.compare(name.size() - 5, 5, "phase") == 0) {
      // a label by |v| against v_tol = epsilon = 1e-2 m/s: the same wherever |v| is further
      // from it than the runs' difference (1e-6 m/s is a thousand times that)
      const int v = plain.Column(name.substr(0, name.size() - 5) + "shortening_velocity");
      ASSERT_GE(v, 0) << name;
      for (std::size_t r = 0; r < plain.rows.size(); ++r) {
        if (std::abs(std::abs(std::stod(plain.rows[r][v])) - 1e-2) < 1e-6) continue;
        EXPECT_EQ(with.rows[r][c], plain.rows[r][c]) << name << " at t = " << plain.rows[r][0];
      }
      continue;
    }
    double scale = 0.0;
    for (const auto& row : plain.rows) scale = std::max(scale, std::abs(std::stod(row[c])));
    if (scale == 0.0) scale = 1.0;
    for (std::size_t r = 0; r < plain.rows.size(); ++r) {
      EXPECT_NEAR(std::stod(with.rows[r][c]), std::stod(plain.rows[r][c]), 1e-8 * scale)
          << name << " at t = " << plain.rows[r][0];
    }
  }
  // the time column is the grid itself, bit for bit
  for (std::size_t r = 0; r < plain.rows.size(); ++r) EXPECT_EQ(with.rows[r][0], plain.rows[r][0]);
}

TEST(SensitivityCli, PlainColumnsMatchAPlainRunSingle) {
  ExpectPlainColumnsMatch(Single(), "model.f_iso");
}

TEST(SensitivityCli, PlainColumnsMatchAPlainRunWithActivationDynamics) {
  ExpectPlainColumnsMatch(Excited(), "activation_dynamics.tau_deactivation");
}

TEST(SensitivityCli, PlainColumnsMatchAPlainRunNetwork) {
  ExpectPlainColumnsMatch(Network(), "'nodes[1].position'");
}

// A network in the plane listing its own sensitivities: a cable from a wall over a free
// pulley node (a spring holds it to a fixed point above) to a free tip pulled along x, under
// gravity; the cable stays taut throughout (0.122 m or longer against its 0.12 m slack
// length) and no segment shorter than 0.02 m.
constexpr const char* kPlanar = R"(name: cli_planar
dimensions: 2
gravity: [0.0, -9.81]
nodes:
  - {name: wall, fixed: [0.0, 0.0]}
  - {name: top, fixed: [0.05, 0.1]}
  - {name: pulley, mass: 0.05, position: [0.05, 0.03], velocity: [0.0, 0.0]}
  - {name: tip, mass: 0.2, position: [0.1, -0.02], velocity: [0.0, 0.0]}
elements:
  - {name: cable, type: tendon, from: wall, to: tip, via: [pulley], slack_length: 0.12, stiffness: 2000.0}
  - {name: holder, type: spring, from: top, to: pulley, stiffness: 500.0, rest_length: 0.05}
loads:
  - {node: tip, type: constant, value: 20.0, direction: [1.0, 0.0]}
time: {start: 0.0, end: 0.2}
solver: {rtol: 1.0e-12, atol: 1.0e-14}
output: {file: planar.csv, interval: 0.01}
)";

// The plain run's columns, then d_<column>/d_<path> with a free node's named as its run
// columns (NODE.x, NODE.y, NODE.vx, NODE.vy); each derivative column against a central
// difference of two plain runs at p +- 1e-4 |p| (--set), to 1e-5 of the column's scale (the
// quotient's truncation, ~1e-7, and its share of the runs' errors at rtol 1e-12, ~1e-7, well
// within): the program end to end, the finer check being
// tests/scenario/spatial_sensitivity_test.cc.
TEST(SensitivityCli, PlanarNetworkFromItsOwnList) {
  const std::string scenario = testing::WriteTempFile(
      "planar.yaml",
      std::string(kPlanar) + "sensitivities: ['elements[1].stiffness', 'gravity[1]']\n");
  const std::string without = testing::WriteTempFile("plain.yaml", kPlanar);
  const CsvText plain = RunToCsv(without, TempPath("plain.csv"));
  const CsvText csv = RunToCsv(scenario, TempPath("out.csv"));
  const std::vector<std::string> columns = {
      "pulley.x", "pulley.y", "pulley.vx",    "pulley.vy",     "tip.x",         "tip.y",
      "tip.vx",   "tip.vy",   "cable.length", "cable.tension", "holder.length", "holder.tension"};
  const std::vector<std::string> paths = {"elements[1].stiffness", "gravity[1]"};
  EXPECT_EQ(csv.header, plain.header + DerivativeColumns(paths, columns));
  ASSERT_EQ(csv.rows.size(), plain.rows.size());
  const std::vector<double> values = {500.0, -9.81};
  for (std::size_t p = 0; p < paths.size(); ++p) {
    const double h = 1e-4 * std::abs(values[p]);
    const auto run_at = [&](double value, const std::string& name) {
      char set[96];
      std::snprintf(set, sizeof set, "--set '%s=%.17g'", paths[p].c_str(), value);
      return RunToCsv(without, TempPath(name), set);
    };
    const CsvText below = run_at(values[p] - h, "below.csv");
    const CsvText above = run_at(values[p] + h, "above.csv");
    for (const std::string& column : columns) {
      const int d = csv.Column("d_" + column + "/d_" + paths[p]);
      const int c = plain.Column(column);
      ASSERT_GE(d, 0) << column;
      ASSERT_GE(c, 0) << column;
      double scale = 0.0;
      for (const auto& row : csv.rows) scale = std::max(scale, std::abs(std::stod(row[d])));
      for (std::size_t r = 0; r < csv.rows.size(); ++r) {
        const double difference =
            (std::stod(above.rows[r][c]) - std::stod(below.rows[r][c])) / (2.0 * h);
        EXPECT_NEAR(std::stod(csv.rows[r][d]), difference, 1e-5 * scale)
            << "d_" << column << "/d_" << paths[p] << " at t = " << csv.rows[r][0];
      }
    }
  }
}

// Each refusal exits 2, naming the path and the rule.
void ExpectRefused(const std::string& scenario, const std::string& path, const std::string& rule) {
  const testing::CliOutcome r = RunMusclesim("run " + scenario + " -o " + TempPath("out.csv") +
                                             " --quiet --sensitivity '" + path + "'");
  EXPECT_EQ(r.exit_code, 2) << path << ": " << r.err;
  EXPECT_THAT(r.err, HasSubstr("--sensitivity " + path)) << path;
  EXPECT_THAT(r.err, HasSubstr(rule)) << path;
}

constexpr const char* kMovesABreakpoint = "moves when an input jumps";

TEST(SensitivityCli, RefusesAParameterThatMovesABreakpoint) {
  ExpectRefused(Single(), "load[0].time", kMovesABreakpoint);
  ExpectRefused(Single(), "activation.time", kMovesABreakpoint);
  ExpectRefused(Excited(), "excitation.time", kMovesABreakpoint);
}

TEST(SensitivityCli, RefusesAnInteger) {
  ExpectRefused(Single(), "model.velocity.n", "cannot change continuously");
}

TEST(SensitivityCli, RefusesASetting) {
  ExpectRefused(Single(), "solver.rtol", "a setting of the run, not a parameter");
  ExpectRefused(Single(), "time.end", "a setting of the run, not a parameter");
  ExpectRefused(Single(), "output.interval", "a setting of the run, not a parameter");
}

// What a path names is found by the parameter handles (scenario/parameter.h), which read the
// scenario in memory, not its file: a key left out of the file holds its default there.
TEST(SensitivityCli, RefusesAPathAbsentFromTheFile) {
  // no eccentric block: no limit, which as a number is infinite
  ExpectRefused(Single(), "model.velocity.eccentric.limit", "= inf: not a finite number");
  ExpectRefused(Network(), "elements[7].stiffness", ": indexes past the end of elements");
}

TEST(SensitivityCli, AValueTheFileLeavesOutIsDifferentiated) {
  // initial.lengthening_rate, left out of the file, is the scenario's 0 m/s
  const CsvText with =
      RunToCsv(Single(), TempPath("rate.csv"), "--sensitivity initial.lengthening_rate");
  EXPECT_GE(with.Column("d_length/d_initial.lengthening_rate"), 0) << with.header;
}

TEST(SensitivityCli, RefusesANonNumber) {
  ExpectRefused(Single(), "load[0].type", ": names no field of this step waveform");
  ExpectRefused(Network(), "elements[2].from", ": names no number of this spring");
}

TEST(SensitivityCli, RefusesTheScenarioKeysBadEntriesWithTheirPlace) {
  // the key's entry is named by its place in the file (FILE:line:column)
  const std::string scenario = Single("sensitivities: [model.f_iso, solver.rtol]\n");
  const testing::CliOutcome r =
      RunMusclesim("run " + scenario + " -o " + TempPath("out.csv") + " --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(scenario + ":"));
  EXPECT_THAT(r.err, ContainsRegex(":[0-9]+:[0-9]+: sensitivities\\[1\\] solver.rtol: a "
                                   "setting of the run"));
}

// An empty `sensitivities:` list is a plain run through the sensitivity path, no derivative
// columns.
TEST(SensitivityCli, AnEmptySensitivitiesListRunsAsAPlainRun) {
  const CsvText plain = RunToCsv(Single(), TempPath("plain.csv"));
  const CsvText listed = RunToCsv(Single("sensitivities: []\n"), TempPath("listed.csv"));
  EXPECT_EQ(listed.header, plain.header);
  EXPECT_EQ(listed.rows.size(), plain.rows.size());
}

}  // namespace
}  // namespace musclesim
