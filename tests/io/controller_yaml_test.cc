// Feedback controllers in network scenario files (io/readers/scenario_yaml.h, docs/model.md 11):
// a controlled network loads and runs, its CSV's controller columns against the waveform and
// the lengths and positions recomputed here, every refusal placed at its file, line and key,
// --set and `musclesim sweep` on a controlled base, and the plot's controller panels.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "support/cli_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::WriteTempFile;

const std::string kModels = "models:\n  muscle:\n" + testing::TestModelKeys(4);

// A muscle holding a mass against a spring, its length following a ramp: the controller
// drives its activation directly (no activation dynamics).
const std::string kHold = std::string("name: controlled\n") + kModels + R"(nodes:
  - {name: wall, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1}
  - {name: anchor, fixed: 0.2}
elements:
  - {name: muscle, type: actuator, from: wall, to: load, model: muscle}
  - {name: spring, type: spring, from: load, to: anchor, stiffness: 500.0, rest_length: 0.05}
  - {name: damper, type: damper, from: wall, to: load, damping: 2.0}
controllers:
  - name: hold
    type: pid
    measure: {element: muscle, quantity: length}
    reference: {type: ramp, start: 0.1, end: 0.3, from: 0.1, to: 0.097}
    gains: {kp: -200.0, ki: -2000.0, kd: -1.0}
    feedforward: {type: constant, value: 0.2}
    drives: muscle
time: {start: 0.0, end: 0.5}
solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-12, jacobian: analytic}
output: {file: hold.csv, interval: 0.01}
)";

// An antagonist pair with activation dynamics steering a mass's position by co-contraction.
const std::string kPair = std::string("name: pair\n") + kModels + R"(nodes:
  - {name: wall, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1}
  - {name: anchor, fixed: 0.2}
elements:
  - {name: flexor, type: actuator, from: wall, to: load, model: muscle,
     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}, initial_activation: 0.3}
  - {name: extensor, type: actuator, from: load, to: anchor, model: muscle,
     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}
  - {name: damper, type: damper, from: wall, to: load, damping: 2.0}
controllers:
  - name: steer
    type: pid
    measure: {node: load, quantity: position}
    reference: {type: sine, offset: 0.1, amplitude: 0.002, frequency: 2.0}
    gains: {kp: -300.0, ki: -1000.0}
    co_contraction: {actuators: [flexor, extensor], level: {type: constant, value: 0.3}}
time: {start: 0.0, end: 0.5}
solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-12, jacobian: analytic}
output: {file: pair.csv, interval: 0.01}
)";

std::string Edit(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no '" + from + "' to edit");
  return text.replace(at, from.size(), to);
}

// "FILE:line:column" (1-based) of the first `needle` in `text`, as messages place a node; a
// '^' in the needle marks the place within it (needle "drives: ^muscle}" places at muscle).
std::string At(const std::string& text, std::string needle) {
  const auto caret = needle.find('^');
  const std::size_t skip = caret == std::string::npos ? 0 : caret;
  if (caret != std::string::npos) needle.erase(caret, 1);
  const auto found = text.find(needle);
  if (found == std::string::npos) throw std::logic_error("no '" + needle + "' in the file");
  const std::size_t at = found + skip;
  const auto line_start = text.rfind('\n', at);
  const std::size_t column = line_start == std::string::npos ? at + 1 : at - line_start;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  return "FILE:" + std::to_string(line) + ":" + std::to_string(column);
}

// The run's CSV, as musclesim run writes it, read back.
CsvTable RunToCsv(const std::string& name, const std::string& text) {
  const RecordedRun run = RunScenario(LoadScenario(WriteTempFile(name + ".yaml", text)));
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  return ReadCsv(WriteTempFile(name + ".csv", FormatRunCsv(run)));
}

double Column(const CsvTable& csv, std::size_t row, const std::string& name) {
  const int column = csv.Find(name);
  EXPECT_GE(column, 0) << name;
  return csv.Number(row, column);
}

TEST(ControllerYaml, DrivenActuatorRunsAndTheCsvRecordsTheLoop) {
  const CsvTable csv = RunToCsv("hold", kHold);
  // the controller's four columns come last, after the load's
  const std::vector<std::string> tail(csv.header.end() - 5, csv.header.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"load.load", "hold.reference", "hold.measured",
                                            "hold.error", "hold.output"}));
  ASSERT_EQ(csv.rows.size(), 51u);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = Column(csv, r, "t");
    // the ramp from 0.1 m at 0.1 s to 0.097 m at 0.3 s, evaluated here
    const double ramp = t <= 0.1 ? 0.1 : t >= 0.3 ? 0.097 : 0.1 - 0.003 * (t - 0.1) / 0.2;
    const double reference = Column(csv, r, "hold.reference");
    const double measured = Column(csv, r, "hold.measured");
    // each side a few roundoffs of 0.1 m
    EXPECT_NEAR(reference, ramp, 1e-15) << t;
    // the muscle's length from its nodes' positions: one subtraction's roundoff
    EXPECT_NEAR(measured, Column(csv, r, "load.position") - Column(csv, r, "wall.position"), 1e-16)
        << t;
    EXPECT_NEAR(Column(csv, r, "hold.error"), reference - measured, 1e-16) << t;  // as above
    // without activation dynamics the output is the muscle's activation itself, in [0, 1]
    const double output = Column(csv, r, "hold.output");
    EXPECT_EQ(output, Column(csv, r, "muscle.activation")) << t;
    EXPECT_GE(output, 0.0);
    EXPECT_LE(output, 1.0);
  }
}

TEST(ControllerYaml, CoContractionSteersThePairThroughActivationDynamics) {
  const Scenario spec = LoadScenario(WriteTempFile("pair.yaml", kPair));
  ASSERT_EQ(spec.controllers.size(), 1u);
  ASSERT_TRUE(spec.controllers[0].co_contraction.has_value());
  EXPECT_EQ(spec.controllers[0].co_contraction->first, "flexor");
  EXPECT_EQ(spec.controllers[0].co_contraction->second, "extensor");
  EXPECT_TRUE(spec.elements[0].controlled);
  ASSERT_TRUE(spec.elements[0].excitation.has_value());
  EXPECT_EQ(spec.elements[0].excitation->initial_activation, 0.3);
  EXPECT_EQ(spec.elements[1].excitation->initial_activation, 0.0);  // the default
  EXPECT_EQ(spec.controllers[0].gains.kd, 0.0);                     // the default

  const CsvTable csv = RunToCsv("pair", kPair);
  ASSERT_EQ(csv.rows.size(), 51u);
  const double pi = std::acos(-1.0);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = Column(csv, r, "t");
    // a few roundoffs of 0.1 m, the sine's phase rounded too
    EXPECT_NEAR(Column(csv, r, "steer.reference"), 0.1 + 0.002 * std::sin(2.0 * pi * 2.0 * t),
                1e-15)
        << t;
    EXPECT_EQ(Column(csv, r, "steer.measured"), Column(csv, r, "load.position")) << t;
    // the pair's excitations: level + c and level - c, each clamped to [0, 1]
    const double c = Column(csv, r, "steer.output");
    EXPECT_NEAR(Column(csv, r, "flexor.excitation"), std::clamp(0.3 + c, 0.0, 1.0), 1e-16) << t;
    EXPECT_NEAR(Column(csv, r, "extensor.excitation"), std::clamp(0.3 - c, 0.0, 1.0), 1e-16) << t;
  }
}

TEST(ControllerYaml, SetReachesAControllersGains) {
  const std::string path = WriteTempFile("hold.yaml", kHold);
  const Scenario s =
      LoadScenario(path, {"controllers[0].gains.kp=-300", "controllers[0].reference.to=0.098"});
  EXPECT_EQ(s.controllers[0].gains.kp, -300.0);
  EXPECT_EQ(s.controllers[0].reference.to, 0.098);
  EXPECT_THAT(
      InputErrorOf(path, [&] { LoadScenario(path, {"controllers[0].measure.quantity=tension"}); }),
      HasSubstr("controllers[0].gains.kd = -1 (" + At(kHold, "kd: ^-1.0") +
                "): must be 0 on a tension"));
}

// The message of loading `text`, the file's path shown as FILE.
std::string ErrorOf(const std::string& text) {
  const std::string path = WriteTempFile("bad.yaml", text);
  return InputErrorOf(path, [&] { LoadScenario(path); });
}

TEST(ControllerYaml, DrivenActuatorWithItsOwnActivationIsRefused) {
  const std::string text = Edit(kHold, "model: muscle}",
                                "model: muscle,\n     activation: {type: constant, value: 0.5}}");
  EXPECT_THAT(ErrorOf(text),
              HasSubstr("elements[0].activation = {type: constant, value: 0.5} (" +
                        At(text, "{type: constant, value: 0.5}") +
                        "): actuator muscle is driven by controllers[0] (hold): it has no "
                        "activation of its own"));
  const std::string excited =
      Edit(kPair, "initial_activation: 0.3}",
           "initial_activation: 0.3, excitation: {type: constant, value: 1}}");
  EXPECT_THAT(ErrorOf(excited),
              HasSubstr("elements[0].excitation = {type: constant, value: 1} (" +
                        At(excited, "{type: constant, value: 1}") +
                        "): actuator flexor is driven by controllers[0] (steer): it has no "
                        "activation of its own"));
  // an initial activation needs the dynamics it starts
  const std::string initial =
      Edit(kHold, "model: muscle}", "model: muscle, initial_activation: 0.2}");
  EXPECT_THAT(ErrorOf(initial), HasSubstr("elements[0].initial_activation = 0.2 (" +
                                          At(initial, "initial_activation: ^0.2") +
                                          "): only with activation_dynamics"));
}

TEST(ControllerYaml, AMisspeltDrivesIsToldAtTheControllerNotTheActuator) {
  // a misspelt `drives` leaves the actuator with no input at all: the controller's key is at
  // fault, and is named before the actuator could be blamed
  const std::string text = Edit(kHold, "drives: muscle", "drives: spring");
  EXPECT_THAT(ErrorOf(text),
              HasSubstr("controllers[0].drives = spring (" + At(text, "drives: ^spring") +
                        "): must name an actuator of the network: muscle"));
}

TEST(ControllerYaml, EntryRefusalsNameFileLineAndKey) {
  struct Case {
    std::string text, marker, message;
  };
  const auto edit = [](const std::string& from, const std::string& to) {
    return Edit(kHold, from, to);
  };
  const std::string tension =
      Edit(kHold, "{element: muscle, quantity: length}", "{element: muscle, quantity: tension}");
  const std::string second =
      "{name: again, type: pid, measure: {node: load, quantity: position}, "
      "reference: {type: constant, value: 0.1}, gains: {kp: 1}, drives: muscle}";
  const std::vector<Case> cases = {
      {edit("type: pid", "type: lqr"), "lqr", "controllers[0].type = lqr (@): must be pid"},
      {edit("drives: muscle",
            "drives: muscle\n    co_contraction: {actuators: [muscle, spring], "
            "level: {type: constant, value: 0}}"),
       "name: hold", "controllers[0] = drives and co_contraction (@): give exactly one of drives"},
      {edit("    drives: muscle\n", ""), "name: hold",
       "controllers[0] = neither (@): give exactly one of drives"},
      {edit("{element: muscle, quantity: length}",
            "{element: muscle, node: load, quantity: length}"),
       "{element: muscle, node",
       "controllers[0].measure = {element: muscle, node: load, quantity: length} (@): give exactly "
       "one of element"},
      {edit("quantity: length}", "quantity: position}"), "position}",
       "controllers[0].measure.quantity = position (@): an element's measured quantity is its "
       "length or its tension"},
      {edit("quantity: length}", "quantity: speed}"), "speed}",
       "controllers[0].measure.quantity = speed (@): must be one of length, tension, position"},
      {edit("kd: -1.0", "kd: -1.0, kf: 2"), "kf",
       "controllers[0].gains.kf (@): unknown key; allowed here: kp, ki, kd"},
      {edit("    drives: muscle\n", "    drives: muscle\n    colour: red\n"), "colour",
       "controllers[0].colour (@): unknown key; allowed here: name, type, drives, measure, "
       "reference, feedforward, co_contraction, gains"},
      {edit("    gains: {kp: -200.0, ki: -2000.0, kd: -1.0}\n", ""), "name: hold",
       "controllers[0].gains (@): missing required key"},
      {edit("name: hold", "name: \"ho,ld\""), "\"ho,ld\"",
       "controllers[0].name = ho,ld (@): must be a plain name"},
      // the core's refusals, put back at their keys
      {tension, "kd: ^-1.0", "controllers[0].gains.kd = -1 (@): must be 0 on a tension"},
      {Edit(tension, "kd: -1.0", "kd: 0.0"), "muscle, quantity: tension",
       "controllers[0].measure.element = muscle (@): is the actuator this controller drives, "
       "without activation dynamics"},
      {edit("{element: muscle, quantity: length}", "{element: musle, quantity: length}"), "musle",
       "controllers[0].measure.element = musle (@): names no element; the elements are: muscle, "
       "spring, damper"},
      {edit("{element: muscle, quantity: length}", "{node: lod, quantity: position}"), "lod",
       "controllers[0].measure.node = lod (@): names no node; the nodes are: wall, load, anchor"},
      {edit("{element: muscle, quantity: length}", "{node: wall, quantity: position}"),
       "wall, quantity",
       "controllers[0].measure.node = wall (@): must name a free node (one with a mass): it is "
       "fixed"},
      {edit("    drives: muscle\n", "    drives: muscle\n  - " + second + "\n"), "drives: ^muscle}",
       "controllers[1].drives = muscle (@): is driven by controllers[0] already"},
      {edit("    drives: muscle\n",
            "    drives: muscle\n  - " + Edit(second, "again", "hold") + "\n"),
       "hold, type", "controllers[1].name = hold (@): must be unique: controllers[0] has it too"},
  };
  for (const Case& c : cases) {
    const std::string& text = c.text;
    std::string expected = c.message;
    expected.replace(expected.find('@'), 1, At(text, c.marker));
    EXPECT_THAT(ErrorOf(text), HasSubstr(expected)) << c.message;
  }
}

TEST(ControllerYaml, CoContractionNamesAreResolved) {
  const std::string text =
      Edit(Edit(kPair, "[flexor, extensor]", "[flexor, extensr]"), "{name: damper,",
           "{name: extensor2, type: actuator, from: load, to: anchor, model: muscle,\n"
           "     activation: {type: constant, value: 0.1}}\n  - {name: damper,");
  // the misspelt name is told at its entry, before extensor (now undriven) lacks an input
  EXPECT_THAT(
      ErrorOf(text),
      HasSubstr("controllers[0].co_contraction.actuators[1] = extensr (" + At(text, "extensr]") +
                "): must name an actuator of the network: flexor, extensor, extensor2"));
  const std::string level =
      Edit(kPair, "level: {type: constant, value: 0.3}", "level: {type: constant, value: 1.5}");
  EXPECT_THAT(ErrorOf(level),
              HasSubstr("controllers[0].co_contraction.level.value = 1.5 (" + At(level, "1.5") +
                        "): activation must stay within [0, 1]"));
}

// ---- in the plane (docs/guide/networks.md "In the plane and in space") --------------------

// A 2 kg mass in the plane under gravity, hung from `ceiling` by an actuator whose controller
// holds the mass's y coordinate, held sideways by a spring; a second actuator over a fixed via
// point holds its own path's length.
const std::string kPlanarHold = std::string("name: planar\n") + kModels + R"(dimensions: 2
gravity: [0.0, -9.81]
nodes:
  - {name: ceiling, fixed: [0.04, 0.09]}
  - {name: wall, fixed: [-0.1, 0.0]}
  - {name: load, mass: 2.0, position: [0.0, -0.005]}
elements:
  - {name: lift, type: actuator, from: load, to: ceiling, model: muscle}
  - {name: brace, type: actuator, from: wall, to: load, model: muscle, via: [[-0.05, -0.03]]}
  - {name: spring, type: spring, from: wall, to: load, stiffness: 500.0, rest_length: 0.1}
controllers:
  - name: height
    type: pid
    measure: {node: load, quantity: position, coordinate: y}
    reference: {type: constant, value: 0.0}
    gains: {kp: 200.0, ki: 400.0}
    drives: lift
  - name: stretch
    type: pid
    measure: {element: brace, quantity: length}
    reference: {type: constant, value: 0.113}
    gains: {kp: -50.0, kd: -0.5}
    feedforward: {type: constant, value: 0.1}
    drives: brace
time: {start: 0.0, end: 0.3}
solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-12, jacobian: analytic}
output: {file: planar.csv, interval: 0.01}
)";

TEST(ControllerYaml, InThePlaneAControllerMeasuresACoordinateOrAPathsLength) {
  const Scenario spec = LoadScenario(WriteTempFile("planar.yaml", kPlanarHold));
  ASSERT_EQ(spec.controllers.size(), 2u);
  EXPECT_EQ(spec.controllers[0].measure.node, "load");
  EXPECT_EQ(spec.controllers[0].measure.coordinate, 1);
  EXPECT_EQ(spec.controllers[1].measure.coordinate, Measurement::kNoCoordinate);

  const CsvTable csv = RunToCsv("planar", kPlanarHold);
  ASSERT_EQ(csv.rows.size(), 31u);
  for (std::size_t r = 0; r < csv.rows.size(); ++r) {
    const double t = Column(csv, r, "t");
    // the measured coordinate is the node's y column, the measured length the path's
    EXPECT_EQ(Column(csv, r, "height.measured"), Column(csv, r, "load.y")) << t;
    EXPECT_EQ(Column(csv, r, "height.error"), -Column(csv, r, "load.y")) << t;
    EXPECT_EQ(Column(csv, r, "stretch.measured"), Column(csv, r, "brace.length")) << t;
    // the path's length from the node's coordinates, over the via point (-0.05, -0.03):
    // a few roundoffs of 0.1 m
    const double x = Column(csv, r, "load.x"), y = Column(csv, r, "load.y");
    EXPECT_NEAR(Column(csv, r, "brace.length"),
                std::hypot(0.05, 0.03) + std::hypot(x + 0.05, y + 0.03), 1e-15)
        << t;
    EXPECT_EQ(Column(csv, r, "height.output"), Column(csv, r, "lift.activation")) << t;
  }
}

TEST(ControllerYaml, AMeasuredCoordinateIsRequiredInThePlaneAndRefusedAtItsKey) {
  struct Case {
    std::string text, marker, message;
  };
  const auto edit = [](const std::string& from, const std::string& to) {
    return Edit(kPlanarHold, from, to);
  };
  const std::vector<Case> cases = {
      {edit(", coordinate: y}", "}"), "{node: load",
       "controllers[0].measure.coordinate (@): missing required key: in 2 dimensions a node's "
       "measured position is one coordinate "
       "(coordinate: x or y)"},
      {edit("coordinate: y}", "coordinate: z}"), "z}",
       "controllers[0].measure.coordinate = z (@): is beyond the scenario's coordinates (x or "
       "y): the scenario has dimensions: 2"},
      {edit("coordinate: y}", "coordinate: up}"), "up}",
       "controllers[0].measure.coordinate = up (@): must be one of x, y, z"},
      {edit("{element: brace, quantity: length}",
            "{element: brace, quantity: length, "
            "coordinate: x}"),
       "x}", "controllers[1].measure.coordinate = x (@): only a node's position has coordinates"},
      // on a line the only coordinate is x
      {Edit(kPair, "{node: load, quantity: position}",
            "{node: load, quantity: position, coordinate: y}"),
       "y}",
       "controllers[0].measure.coordinate = y (@): is beyond the scenario's coordinates (x): the "
       "scenario has dimensions: 1"},
  };
  for (const Case& c : cases) {
    std::string expected = c.message;
    expected.replace(expected.find('@'), 1, At(c.text, c.marker));
    EXPECT_THAT(ErrorOf(c.text), HasSubstr(expected)) << c.message;
  }
}

TEST(ControllerYaml, OnALineCoordinateXIsThePositionItself) {
  // the same run, to the last digit of the CSV
  const std::string with_x = Edit(kPair, "{node: load, quantity: position}",
                                  "{node: load, quantity: position, coordinate: x}");
  EXPECT_EQ(FormatRunCsv(RunScenario(LoadScenario(WriteTempFile("with_x.yaml", with_x)))),
            FormatRunCsv(RunScenario(LoadScenario(WriteTempFile("pair.yaml", kPair)))));
}

TEST(ControllerYaml, SensitivitiesOfAControlledNetworkAreRefused) {
  const std::string text = kHold + "sensitivities: [models.muscle.f_iso]\n";
  const std::string path = WriteTempFile("sensitive.yaml", text);
  EXPECT_THAT(InputErrorOf(path, [&] { RunWithSensitivities(LoadScenario(path), {}); }),
              HasSubstr(At(text, "models.muscle.f_iso]") +
                        ": sensitivities[0] models.muscle.f_iso: sensitivities of a network with "
                        "controllers are not supported yet"));
  // and from the command line: an input error
  const testing::CliOutcome r = testing::RunMusclesim("run " + WriteTempFile("hold.yaml", kHold) +
                                                      " -o - --sensitivity elements[1].stiffness");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--sensitivity elements[1].stiffness: sensitivities of a network "
                               "with controllers are not supported yet"));
}

TEST(ControllerYaml, SweepOfAControlledBaseReachesEachReference) {
  const std::string dir = testing::TempPath("sweep");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/base.yaml")
      << Edit(Edit(kHold, "{type: ramp, start: 0.1, end: 0.3, from: 0.1, to: 0.097}",
                   "{type: constant, value: 0.098}"),
              "end: 0.5}", "end: 3.0}");
  std::ofstream(dir + "/sweep.yaml")
      << "base: base.yaml\nmode: grid\nparameters:\n"
         "  controllers[0].reference.value: [0.097, 0.099]\n"
         "metrics: [final_length]\nmetric_options: {element: muscle}\n"
         "output: "
      << dir << "/sweep.csv\n";
  const testing::CliOutcome r = testing::RunMusclesim("sweep " + dir + "/sweep.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable summary = ReadCsv(dir + "/sweep.csv");
  ASSERT_EQ(summary.rows.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(summary.rows[i][static_cast<std::size_t>(summary.Find("status"))], "ok");
    // the integral gain leaves no steady error: the length settles at the reference. The
    // loop's slowest mode (kp, ki and the spring against 0.1 kg) decays about 20-fold per
    // 0.4 s, so after 3 s less than 1e-9 m of the 1e-3 m step is left; 1e-7 m leaves room
    // for the solver's error (rtol 1e-8 of 0.1 m)
    EXPECT_NEAR(Column(summary, i, "final_length"),
                Column(summary, i, "controllers[0].reference.value"), 1e-7);
  }
}

TEST(ControllerYaml, PlotHasTheControllersPanels) {
  const std::string dir = testing::TempPath("plot");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/hold.yaml") << kHold;
  testing::CliOutcome r =
      testing::RunMusclesim("run " + dir + "/hold.yaml -o " + dir + "/hold.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  r = testing::RunMusclesim("plot " + dir + "/hold.csv -o " + dir + "/hold.png --script " + dir +
                            "/hold.gp");
  const std::string script = testing::ReadText(dir + "/hold.gp");
  // the columns are t, 3 positions, 3 lengths, 3 tensions, the activation, then the
  // controller's measured value and reference, then its error
  EXPECT_THAT(script, HasSubstr("set multiplot layout 6,1"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'hold'\nplot $network using 1:12 with lines lw 2 "
                                "title 'hold measured', \\\n  $network using 1:13 with lines lw 1 "
                                "dt 2 title 'hold reference'\n"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'control error'\nplot $network using 1:14 with lines "
                                "lw 2 title 'hold'\n"));
  if (!gnuplot) GTEST_SKIP() << "gnuplot is not installed";
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(std::filesystem::file_size(dir + "/hold.png"), 0u);
}

}  // namespace
}  // namespace musclesim
