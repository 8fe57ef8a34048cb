// Bad input, every reader and every verb, run through the built program: each case asserts
// the exit code and that the message names the key path (or the flag), the place
// (file:line:column, or --set) and the rule. A new key or flag is not done until its error
// has a row here.
//
// A case's file is written with one '@' marking where the error is; the test removes it and
// expects "FILE:line:column" of that spot, found by counting lines and columns in the text
// (independently of yaml-cpp's marks).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr const char* kModel = R"(name: bad_input
model:
  f_iso: 100.0
  passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
  active_length:
    optimal_range: [0.095, 0.105]
    gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
)";

constexpr const char* kRest =
    R"(actuator: {mass: 0.1, damping: 0.0, stiffness: 0.0, rest_length: 0.1}
initial: {length: 0.1, lengthening_rate: 0.0}
activation: {type: step, time: 0.05, before: 0.0, after: 1.0}
load:
  - {type: constant, value: 40.0}
time: {start: 0.0, end: 1.0}
solver: {method: bdf, rtol: 1.0e-6, atol: 1.0e-9, jacobian: analytic, max_step: 0.0, max_steps: 100000}
output: {file: out.csv, interval: 0.001}
limits: {min_length: 0.05, max_length: 0.2}
)";

constexpr const char* kNetwork = R"(name: bad_network
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
nodes:
  - {name: wall, fixed: 0.0}
  - {name: load, mass: 0.1, position: 0.1}
  - {name: crank, prescribed: {type: ramp, start: 0.0, end: 1.0, from: 0.3, to: 0.31}}
elements:
  - {name: muscle, type: actuator, from: wall, to: load, model: muscle,
     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}
  - {name: tendon, type: tendon, from: load, to: crank, slack_length: 0.18, stiffness: 2.0e4}
  - {name: damper, type: damper, from: wall, to: load, damping: 2.0}
loads:
  - {node: load, type: constant, value: 5.0}
time: {start: 0.0, end: 1.0}
solver: {method: bdf, rtol: 1.0e-6, atol: 1.0e-9, jacobian: analytic, linear_solver: auto}
output: {file: out.csv, interval: 0.001}
limits: [{element: muscle, min_length: 0.05, max_length: 0.15}]
)";

constexpr const char* kSweep = R"(base: base.yaml
mode: grid
parameters:
  actuator.mass: [0.1, 0.2]
  model.velocity.n: {from: 2, to: 4, count: 3}
metrics: [final_length]
output: sweep.csv
)";

constexpr const char* kData = R"(passive: {csv: passive.csv}
active: {csv: active.csv, count: 2, nonnegative: true}
velocity: {csv: velocity.csv, f_iso: 100}
)";

// `text` with the first `from` replaced by `to` (which must be there: a case that edits
// nothing would test the valid file).
std::string Edit(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no '" + from + "' to edit");
  return text.replace(at, from.size(), to);
}
std::string Scenario(const std::string& from = "", const std::string& to = "") {
  const std::string text = std::string(kModel) + kRest;
  return from.empty() ? text : Edit(text, from, to);
}
// A top-level key whose value is ten aliases of a list of ten aliases, seven levels deep.
std::string AliasBomb() {
  std::ostringstream text;
  text << "a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int level = 1; level < 7; ++level) {
    text << "a" << level << ": &a" << level << " [";
    for (int i = 0; i < 10; ++i) text << (i ? ", *a" : "*a") << level - 1;
    text << "]\n";
  }
  return text.str();
}
std::string ModelOnly(const std::string& from, const std::string& to) {
  return Edit(kModel, from, to);
}
std::string Network(const std::string& from, const std::string& to) {
  return Edit(kNetwork, from, to);
}
std::string Sweep(const std::string& from, const std::string& to) { return Edit(kSweep, from, to); }
std::string Data(const std::string& from, const std::string& to) { return Edit(kData, from, to); }

struct Case {
  std::string name;
  std::string command;  // after `musclesim`; {file} is the case's file, {dir} its directory
  std::string file;     // the case's file, with one '@' where the error is ("" : none written)
  int exit_code;
  std::vector<std::string> needles;  // in standard error; {at} is FILE:line:column of '@',
                                     // {file} the file's path
  std::string extension = "yaml";
};

std::ostream& operator<<(std::ostream& out, const Case& c) { return out << c.name; }

// clang-format off
const std::vector<Case> kCases = {
    // --- any YAML file: structure -----------------------------------------------------
    {"DuplicateKeyInAFlowMap", "run {file} -o -", Scenario("rest_length: 0.1}", "rest_length: 0.1, @mass: 1}"), 2,
     {"actuator.mass ({at}): duplicate key: already given at line 9, column 12"}},
    {"DuplicateTopLevelBlock", "run {file} -o -", Scenario() + "@time: {start: 0.0, end: 2.0}\n", 2,
     {"time ({at}): duplicate key: already given at line 14, column 1"}},
    {"DuplicateKeyInAListItem", "run {file} -o -", Scenario("value: 40.0}", "value: 40.0, @value: 3}"), 2,
     {"load[0].value ({at}): duplicate key"}},
    {"DuplicateKeyInTheModel", "run {file} -o -", Scenario("k_p: 1.0,", "k_p: 1.0, @k_p: 2.0,"), 2,
     {"model.passive.k_p ({at}): duplicate key"}},
    {"SecondDocument", "run {file} -o -", Scenario() + "@---\nname: again\n", 2,
     {"{at}: a second YAML document"}},
    {"ListAsAKey", "run {file} -o -", Scenario("{type: step, time", "{type: step, @[x]: 1, time"), 2,
     {"activation ({at}): a key is a list; keys must be plain names"}},
    {"SyntaxError", "run {file} -o -", Scenario("{mass: 0.1,", "{mass: 0.1,,]"), 2,
     {"YAML syntax error"}},
    {"EmptyFile", "run {file} -o -", "# nothing\n", 2, {"{file}: the file is empty"}},
    {"TopLevelNotAMap", "run {file} -o -", "@[1, 2]\n", 2, {"(top level) = [1, 2] ({at}): must be a map of keys"}},
    {"LongValueShownByItsStart", "run {file} -o -", Scenario("name: bad_input", "name: @[" + std::string(400, '1') + "]"), 2,
     {"name = [" + std::string(116, '1') + "... ({at}): must be a text value"}},
    {"AliasCycle", "run {file} -o -", Scenario("  f_iso: 100.0", "  f_iso: @&f [*f]"), 2,
     {"model.f_iso[0] ({at}): an alias inside the value it names (a cycle)"}},
    // ten aliases of ten aliases, seven deep: seven lines of text that expand to 10^7 values
    {"AliasesMultiplied", "run {file} -o -", Scenario() + AliasBomb(), 2,
     {"the document's aliases expand it past 1000000 values"}},
    {"Directory", "run {dir} -o -", "", 2, {"is a directory; give a YAML file"}},
    {"MissingFile", "run {dir}/none.yaml -o -", "", 2, {"none.yaml: cannot open the file"}},
    // --- scenario: keys -------------------------------------------------------------------
    {"UnknownTopLevelKey", "run {file} -o -", Scenario("time: {", "@tim: {"), 2,
     {"tim ({at}): unknown key; allowed here: name, model"}},
    {"UnknownActuatorKey", "run {file} -o -", Scenario("rest_length: 0.1}", "rest_length: 0.1, @color: red}"), 2,
     {"actuator.color ({at}): unknown key; allowed here: mass, damping, stiffness, rest_length"}},
    {"MissingTimeEnd", "run {file} -o -", Scenario("time: {start: 0.0, end: 1.0}", "time: @{start: 0.0}"), 2,
     {"time.end ({at}): missing required key"}},
    // --- scenario: time -------------------------------------------------------------------
    {"TimeStartHuge", "run {file} -o -", Scenario("start: 0.0,", "start: @-1.7e308,"), 2,
     {"time.start = -1.7e308 ({at}): must be from -1e+09 to 1e+09 [s]: beyond 1e9 s"}},
    {"TimeEndHuge", "run {file} -o -", Scenario("end: 1.0}", "end: @1.7e308}"), 2,
     {"time.end = 1.7e308 ({at}): must be from -1e+09 to 1e+09 [s]"}},
    {"TimeEndNotAfterStart", "run {file} -o -", Scenario("end: 1.0}", "end: @0}"), 2,
     {"time.end = 0 ({at}): must be greater than time.start = 0 by at least 1e-09 s"}},
    {"TimeSpanBelowResolution", "run {file} -o -", Scenario("time: {start: 0.0, end: 1.0}", "time: {start: 1.0e8, end: @100000000.01}"), 2,
     {"time.end = 100000000.01 ({at}): must be greater than time.start = 1e+08 by at least 0.10000000001 s"}},
    {"TimeStartNaN", "run {file} -o -", Scenario("start: 0.0,", "start: @.nan,"), 2,
     {"time.start = .nan ({at}): must be from"}},
    // --- scenario: actuator and initial state -----------------------------------------------
    {"MassZero", "run {file} -o -", Scenario("mass: 0.1,", "mass: @0,"), 2,
     {"actuator.mass = 0 ({at}): must be from 1e-09 to 1e+09 [kg]: a microgram to a million tonnes"}},
    {"MassHuge", "run {file} -o -", Scenario("mass: 0.1,", "mass: @1e300,"), 2,
     {"actuator.mass = 1e300 ({at}): must be from 1e-09 to 1e+09 [kg]"}},
    {"MassNotANumber", "run {file} -o -", Scenario("mass: 0.1,", "mass: @abc,"), 2,
     {"actuator.mass = abc ({at}): must be a number"}},
    {"DampingNegative", "run {file} -o -", Scenario("damping: 0.0", "damping: @-1"), 2,
     {"actuator.damping = -1 ({at}): must be from 0 to 1e+12 [N s/m]"}},
    {"DampingHuge", "run {file} -o -", Scenario("damping: 0.0", "damping: @1e300"), 2,
     {"actuator.damping = 1e300 ({at}): must be from 0 to 1e+12"}},
    {"StiffnessHuge", "run {file} -o -", Scenario("stiffness: 0.0", "stiffness: @1e13"), 2,
     {"actuator.stiffness = 1e13 ({at}): must be from 0 to 1e+12 [N/m]"}},
    {"RestLengthHuge", "run {file} -o -", Scenario("rest_length: 0.1}", "rest_length: @1e4}"), 2,
     {"actuator.rest_length = 1e4 ({at}): must be from -1000 to 1000 [m]"}},
    {"InitialLengthZero", "run {file} -o -", Scenario("length: 0.1,", "length: @0,"), 2,
     {"initial.length = 0 ({at}): must be > 0 and <= 1000 [m]"}},
    {"InitialLengthHuge", "run {file} -o -", Scenario("length: 0.1,", "length: @2000,"), 2,
     {"initial.length = 2000 ({at}): must be > 0 and <= 1000 [m]"}},
    {"LengtheningRateHuge", "run {file} -o -", Scenario("lengthening_rate: 0.0", "lengthening_rate: @1e308"), 2,
     {"initial.lengthening_rate = 1e308 ({at}): must be from -1000 to 1000 [m/s]"}},
    {"LengtheningRateText", "run {file} -o -", Scenario("lengthening_rate: 0.0", "lengthening_rate: @x"), 2,
     {"initial.lengthening_rate = x ({at}): must be a number"}},
    // --- scenario: activation waveforms ---------------------------------------------------
    {"ActivationKindUnknown", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: @square, value: 1}"), 2,
     {"activation.type = square ({at}): must be one of constant, step, ramp, sine, pulses, table"}},
    {"ActivationMissingKey", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "@{type: step, time: 0.05, after: 1.0}"), 2,
     {"activation.before ({at}): missing required key"}},
    {"ActivationAboveOne", "run {file} -o -", Scenario("after: 1.0}", "after: @1.2}"), 2,
     {"activation.after = 1.2 ({at}): activation must stay within [0, 1]"}},
    {"ActivationStepTimeHuge", "run {file} -o -", Scenario("time: 0.05,", "time: @1e300,"), 2,
     {"activation.time = 1e300 ({at}): must be from -1e+09 to 1e+09 [s]"}},
    {"ActivationRampBackwards", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: ramp, start: 0.5, end: @0.2, from: 0, to: 1}"), 2,
     {"activation.end = 0.2 ({at}): must be finite and greater than start = 0.5"}},
    {"ActivationSineLeavesUnit", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: sine, offset: 0.5, amplitude: @0.7, frequency: 1}"), 2,
     {"activation.amplitude = 0.7 ({at}): activation must stay within [0, 1]"}},
    {"ActivationSineFrequencyHuge", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: sine, offset: 0.5, amplitude: 0.2, frequency: @1e7}"), 2,
     {"activation.frequency = 1e7 ({at}): must be from 0 to 1e+06 [Hz]"}},
    {"ActivationPulsesTooMany", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: pulses, start: 0, period: @1.0e-8, width: 1.0e-9, low: 0, high: 1}"), 2,
     {"activation.period = 1.0e-8 ({at}): gives more than 5 million pulses"}},
    {"ActivationPulsesBelowResolution", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: pulses, start: 0.9, period: 1.0e-6, width: @1.0e-13, low: 0, high: 1}"), 2,
     {"activation.width = 1.0e-13 ({at}): must be at least 1e-12 s"}},
    {"ActivationPulsesWidthAbovePeriod", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: pulses, start: 0, period: 0.1, width: @0.2, low: 0, high: 1}"), 2,
     {"activation.width = 0.2 ({at}): must be > 0 and at most period = 0.1"}},
    {"ActivationTableNotIncreasing", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: table, points: [[0, 0], [1, 1], [@0.5, 1]]}"), 2,
     {"activation.points[2][0] = 0.5 ({at}): table times must be strictly increasing"}},
    {"ActivationTableValueAboveOne", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: table, points: [[0, 0], [1, @1.5]]}"), 2,
     {"activation.points[1][1] = 1.5 ({at}): activation must stay within [0, 1]"}},
    {"ActivationTableTimeHuge", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: table, points: [[0, 0], [@1e10, 1]]}"), 2,
     {"activation.points[1][0] = 1e10 ({at}): must be from -1e+09 to 1e+09 [s]"}},
    {"ActivationTablePairTooLong", "run {file} -o -", Scenario("{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: table, points: [[0, 0], @[1, 1, 1]]}"), 2,
     {"activation.points[1] = [1, 1, 1] ({at}): must be a list of exactly 2 numbers"}},
    {"ActivationNotAMap", "run {file} -o -", Scenario("activation: {type: step, time: 0.05, before: 0.0, after: 1.0}", "activation: @0.5"), 2,
     {"activation = 0.5 ({at}): must be a map with a type"}},
    // --- scenario: loads ------------------------------------------------------------------
    {"LoadKindUnknown", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: @rocket, value: 1}"), 2,
     {"load[0].type = rocket ({at}): must be one of constant, step, ramp, sine, pulses, table, spring, mass"}},
    {"LoadForceHuge", "run {file} -o -", Scenario("value: 40.0}", "value: @1e300}"), 2,
     {"load[0].value = 1e300 ({at}): must be from -1e+09 to 1e+09 [N]"}},
    {"LoadStepAfterHuge", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: step, time: 0.1, before: 0, after: @1e10}"), 2,
     {"load[0].after = 1e10 ({at}): must be from -1e+09 to 1e+09 [N]"}},
    {"LoadSineOffsetHuge", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: sine, offset: @1e300, amplitude: 1e300, frequency: 1}"), 2,
     {"load[0].offset = 1e300 ({at}): must be from -1e+09 to 1e+09 [N]"}},
    {"LoadSpringStiffnessNegative", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: spring, stiffness: @-1, anchor: 0.1}"), 2,
     {"load[0].stiffness = -1 ({at}): must be from 0 to 1e+12 [N/m]"}},
    {"LoadSpringAnchorHuge", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: spring, stiffness: 1, anchor: @1e5}"), 2,
     {"load[0].anchor = 1e5 ({at}): must be from -1000 to 1000 [m]"}},
    {"LoadMassZero", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: mass, mass: @0}"), 2,
     {"load[0].mass = 0 ({at}): must be from 1e-09 to 1e+09 [kg]"}},
    {"LoadGravityHuge", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: mass, mass: 1, gravity: @1e6}"), 2,
     {"load[0].gravity = 1e6 ({at}): must be from -1000 to 1000 [m/s^2]"}},
    {"LoadMassUnknownKey", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: mass, mass: 1, @value: 2}"), 2,
     {"load[0].value ({at}): unknown key; allowed here: type, mass, gravity"}},
    {"LoadPulsesTooMany", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: pulses, start: 0, period: @1.0e-7, width: 1.0e-8, low: 0, high: 1}"), 2,
     {"load[0].period = 1.0e-7 ({at}): gives more than 5 million pulses"}},
    {"LoadTableValueHuge", "run {file} -o -", Scenario("{type: constant, value: 40.0}", "{type: table, points: [[0, 0], [1, @1e300]]}"), 2,
     {"load[0].points[1][1] = 1e300 ({at}): must be from -1e+09 to 1e+09 [N]"}},
    {"LoadNotAMapOrList", "run {file} -o -", Scenario("load:\n  - {type: constant, value: 40.0}", "load: @5"), 2,
     {"load = 5 ({at}): must be one load (a map) or a list of loads"}},
    {"SecondLoadBad", "run {file} -o -", Scenario("- {type: constant, value: 40.0}", "- {type: constant, value: 40.0}\n  - {type: constant, value: @1e12}"), 2,
     {"load[1].value = 1e12 ({at}): must be from -1e+09 to 1e+09 [N]"}},
    // --- scenario: solver, output, limits ---------------------------------------------------
    {"SolverMethodUnknown", "run {file} -o -", Scenario("method: bdf", "method: @rk4"), 2,
     {"solver.method = rk4 ({at}): must be bdf or adams"}},
    {"SolverJacobianUnknown", "run {file} -o -", Scenario("jacobian: analytic", "jacobian: @exact"), 2,
     {"solver.jacobian = exact ({at}): must be analytic or difference_quotient"}},
    {"SolverRtolZero", "run {file} -o -", Scenario("rtol: 1.0e-6", "rtol: @0"), 2,
     {"solver.rtol = 0 ({at}): must be >= 1e-14 and < 1 [-]"}},
    {"SolverAtolNegative", "run {file} -o -", Scenario("atol: 1.0e-9", "atol: @-1"), 2,
     {"solver.atol = -1 ({at}): must be > 0 and < 1 [m and m/s]"}},
    {"SolverMaxStepNegative", "run {file} -o -", Scenario("max_step: 0.0", "max_step: @-1"), 2,
     {"solver.max_step = -1 ({at}): must be >= 0 and finite [s]: 0 is no limit"}},
    {"SolverMaxStepTooSmallForTheSpan", "run {file} -o -", Scenario("max_step: 0.0", "max_step: @1.0e-9"), 2,
     {"solver.max_step = 1.0e-9 ({at}): must be 0 (no limit) or at least 1e-05 s"}},
    {"SolverMaxStepsZero", "run {file} -o -", Scenario("max_steps: 100000", "max_steps: @0"), 2,
     {"solver.max_steps = 0 ({at}): must be an integer from 1 to 1e+12 [-]"}},
    {"SolverMaxStepsFraction", "run {file} -o -", Scenario("max_steps: 100000", "max_steps: @2.5"), 2,
     {"solver.max_steps = 2.5 ({at}): must be an integer from 1 to 1e+12 [-]"}},
    {"SolverUnknownKey", "run {file} -o -", Scenario("max_steps: 100000", "max_steps: 100000, @order: 5"), 2,
     {"solver.order ({at}): unknown key"}},
    {"OutputIntervalZero", "run {file} -o -", Scenario("interval: 0.001", "interval: @0"), 2,
     {"output.interval = 0 ({at}): must be `steps` or a time [s] giving at most 1e8 rows"}},
    {"OutputIntervalText", "run {file} -o -", Scenario("interval: 0.001", "interval: @often"), 2,
     {"output.interval = often ({at}): must be a number"}},
    {"OutputIntervalTooManyRows", "run {file} -o -", Scenario("interval: 0.001", "interval: @1.0e-10"), 2,
     {"output.interval = 1.0e-10 ({at}): must be `steps` or a time [s] giving at most 1e8 rows"}},
    {"OutputFileEmpty", "run {file}", Scenario("file: out.csv", "file: @\"\""), 2,
     {"output.file = \"\" ({at}): must not be empty"}},
    {"OutputPhaseToleranceNegative", "run {file} -o -", Scenario("interval: 0.001}", "interval: 0.001, phase_tolerance: @-1}"), 2,
     {"output.phase_tolerance = -1 ({at}): must be from 0 to 1000 [m/s]"}},
    {"OutputPhaseToleranceHuge", "run {file} -o -", Scenario("interval: 0.001}", "interval: 0.001, phase_tolerance: @1e4}"), 2,
     {"output.phase_tolerance = 1e4 ({at}): must be from 0 to 1000 [m/s]"}},
    {"NoOutputFile", "run {file}", Scenario("output: {file: out.csv, interval: 0.001}\n", ""), 2,
     {"no output file: set output.file or pass -o PATH"}},
    {"LimitMinAboveInitial", "run {file} -o -", Scenario("min_length: 0.05", "min_length: @0.15"), 2,
     {"limits.min_length = 0.15 ({at}): must be >= 0 and below initial.length = 0.1"}},
    {"LimitMaxBelowInitial", "run {file} -o -", Scenario("max_length: 0.2", "max_length: @0.1"), 2,
     {"limits.max_length = 0.1 ({at}): must be above initial.length = 0.1"}},
    {"LimitMaxWhereThePassiveTensionOverflows", "run {file} -o -", Edit(Scenario("max_length: 0.2", "max_length: @0.2"), "alpha: 100.0", "alpha: 8000.0"), 2,
     {"limits.max_length = 0.2 ({at}): is a length the run may reach, and there the passive tension overflows (inf N)"}},
    {"InitialLengthWhereThePassiveTensionOverflows", "run {file} -o -", Edit(Scenario("{length: 0.1,", "{length: @0.1,"), "slack_length: 0.105", "slack_length: -10.0"), 2,
     {"initial.length = 0.1 ({at}): there the passive tension overflows (inf N)"}},
    {"SetFIsoBeyondEveryForce", "run {file} -o - --set model.f_iso=1e308", Scenario(), 2,
     {"model.f_iso = 1e308 (--set): must be > 0 and <= 1e+09 [N]"}},
    {"SetPassiveKpBeyondEveryForce", "run {file} -o - --set model.passive.k_p=1e10", Scenario(), 2,
     {"model.passive.k_p = 1e10 (--set): must be from 0 to 1e+09 [N]"}},
    {"LimitMaxHuge", "run {file} -o -", Scenario("max_length: 0.2", "max_length: @1e4"), 2,
     {"limits.max_length = 1e4 ({at}): must be above initial.length = 0.1 and at most 1000 [m]"}},
    {"SolverLinearSolverUnknown", "run {file} -o -", Scenario("max_steps: 100000", "max_steps: 100000, linear_solver: @klu"), 2,
     {"solver.linear_solver = klu ({at}): must be one of dense, band, sparse, auto"}},
    // --- scenario: activation dynamics (an excitation driving the activation) ------------------
    {"ExcitationAndActivation", "run {file} -o -", Scenario("load:\n", "excitation: @{type: constant, value: 1}\nactivation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), 2,
     {"excitation = {type: constant, value: 1} ({at}): give either activation (u(t) itself) or excitation (e(t), driving u through activation_dynamics), not both"}},
    {"NeitherActivationNorExcitation", "run {file} -o -", "@" + Scenario("activation: {type: step, time: 0.05, before: 0.0, after: 1.0}\n", ""), 2,
     {"activation ({at}): missing required key: give either activation (u(t) itself) or excitation"}},
    {"ExcitationWithoutDynamics", "run {file} -o -", Scenario("activation: {type: step", "excitation: @{type: step"), 2,
     {"excitation = {type: step, time: 0.05, before: 0.0, after: 1.0} ({at}): needs activation_dynamics: {tau_activation, tau_deactivation} [s]"}},
    {"DynamicsWithActivation", "run {file} -o -", Scenario("load:\n", "activation_dynamics: @{tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), 2,
     {"activation_dynamics = {tau_activation: 0.015, tau_deactivation: 0.05} ({at}): only with excitation"}},
    {"InitialActivationWithActivation", "run {file} -o -", Scenario("lengthening_rate: 0.0}", "lengthening_rate: 0.0, activation: @0.5}"), 2,
     {"initial.activation = 0.5 ({at}): only with excitation and activation_dynamics"}},
    {"TauActivationZero", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "tau_activation: 0.015", "tau_activation: @0"), 2,
     {"activation_dynamics.tau_activation = 0 ({at}): must be from 1e-04 to 10 [s]: muscles take 5 to 60 ms"}},
    {"TauDeactivationHuge", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "tau_deactivation: 0.05", "tau_deactivation: @1e3"), 2,
     {"activation_dynamics.tau_deactivation = 1e3 ({at}): must be from 1e-04 to 10 [s]"}},
    {"TauActivationNaN", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "tau_activation: 0.015", "tau_activation: @.nan"), 2,
     {"activation_dynamics.tau_activation = .nan ({at}): must be from 1e-04 to 10 [s]"}},
    {"TauDeactivationMissing", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "{tau_activation: 0.015, tau_deactivation: 0.05}", "@{tau_activation: 0.015}"), 2,
     {"activation_dynamics.tau_deactivation ({at}): missing required key"}},
    {"DynamicsFamilyUnknown", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "{tau_activation", "{family: @hill, tau_activation"), 2,
     {"activation_dynamics.family = hill ({at}): must be thelen2003, degroote2016 or mujoco (docs/model.md 8.1)"}},
    {"DynamicsSmoothingZero", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "{tau_activation", "{family: degroote2016, smoothing: @0, tau_activation"), 2,
     {"activation_dynamics.smoothing = 0 ({at}): must be from 0.001 to 10000 [-]"}},
    {"DynamicsTausmoothOnThelen", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "tau_deactivation: 0.05}", "tau_deactivation: 0.05, @tausmooth: 0.2}"), 2,
     {"activation_dynamics.tausmooth ({at}): unknown key"}},
    {"DynamicsTausmoothNegative", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "{tau_activation", "{family: mujoco, tausmooth: @-0.1, tau_activation"), 2,
     {"activation_dynamics.tausmooth = -0.1 ({at}): must be from 0 to 1e+09 [-]"}},
    {"DynamicsUnknownKey", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "tau_deactivation: 0.05}", "tau_deactivation: 0.05, @tau: 1}"), 2,
     {"activation_dynamics.tau ({at}): unknown key; allowed here: tau_activation, tau_deactivation"}},
    {"ExcitationAboveOne", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "after: 1.0}", "after: @1.2}"), 2,
     {"excitation.after = 1.2 ({at}): excitation must stay within [0, 1]"}},
    {"ExcitationPulsesTooMany", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: pulses, start: 0, period: @1.0e-8, width: 1.0e-9, low: 0, high: 1}"), 2,
     {"excitation.period = 1.0e-8 ({at}): gives more than 5 million pulses"}},
    {"InitialActivationAboveOne", "run {file} -o -", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "lengthening_rate: 0.0}", "lengthening_rate: 0.0, activation: @1.5}"), 2,
     {"initial.activation = 1.5 ({at}): must be from 0 to 1 [-]: an activation is a fraction of the full activation"}},
    {"SetTauActivationNegative", "run {file} -o - --set activation_dynamics.tau_activation=-1", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "name: bad_input", "name: bad_input"), 2,
     {"activation_dynamics.tau_activation = -1 (--set): must be from 1e-04 to 10 [s]"}},
    {"SetInitialActivationNegative", "run {file} -o - --set initial.activation=-0.5", Edit(Edit(Scenario("activation: {type: step", "excitation: {type: step"), "load:\n", "activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}\nload:\n"), "name: bad_input", "name: bad_input"), 2,
     {"initial.activation = -0.5 (--set): must be from 0 to 1 [-]"}},
    // --- fit target preset and curves --preset ------------------------------------------------
    {"FitPresetUnknownName", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, target: preset, name: @hill, optimal_length: 0.1}"), 2,
     {"model.active_length.fit.name = hill ({at}): must be one of degroote2016, thelen2003, gordon1966, mujoco"}},
    {"FitPresetNameMissing", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: @{count: 2, target: preset, optimal_length: 0.1}"), 2,
     {"model.active_length.fit.name = ~ ({at}): target preset needs the name of a curve: one of degroote2016"}},
    {"FitPresetOptimalLengthMissing", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: @{count: 2, target: preset, name: mujoco}"), 2,
     {"model.active_length.fit.optimal_length = ~ ({at}): target preset needs optimal_length"}},
    {"FitPresetOptimalLengthZero", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, target: preset, name: mujoco, optimal_length: @0}"), 2,
     {"model.active_length.fit.optimal_length = 0 ({at}): must be > 0 and <= 1000 [m]"}},
    {"FitPresetOptimalLengthNaN", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, target: preset, name: mujoco, optimal_length: @.nan}"), 2,
     {"model.active_length.fit.optimal_length = .nan ({at}): must be > 0 and <= 1000 [m]"}},
    {"FitPresetOptimalLengthOutsideTheRange", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, target: preset, name: mujoco, optimal_length: @0.2}"), 2,
     {"model.active_length.fit.optimal_length = 0.2 ({at}): must lie within optimal_range [0.095, 0.105]"}},
    {"FitPresetCountHigh", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: @13, target: preset, name: mujoco, optimal_length: 0.1}"), 2,
     {"model.active_length.fit.count = 13 ({at}): must be an integer from 1 to 12"}},
    {"FitPresetWithPoints", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, target: preset, name: mujoco, optimal_length: 0.1, points: @[[0.09, 0], [0.1, 1]]}"), 2,
     {"model.active_length.fit.points = 2 points ({at}): must be absent for target preset"}},
    {"FitNameWithoutPreset", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, name: @mujoco}"), 2,
     {"model.active_length.fit.name = mujoco ({at}): only for target preset (this target is indicator)"}},
    {"FitOptimalLengthWithoutPreset", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]", "fit: {count: 2, optimal_length: @0.1}"), 2,
     {"model.active_length.fit.optimal_length = 0.1 ({at}): only for target preset (this target is indicator)"}},
    {"CurvesPresetUnknown", "curves --preset hill", "", 2,
     {"--preset hill: must be one of degroote2016, thelen2003, gordon1966, mujoco"}},
    {"CurvesPresetOptimalLengthZero", "curves --preset mujoco --optimal-length 0", "", 2,
     {"--optimal-length 0: must be > 0 and <= 1000 [m]"}},
    {"CurvesPresetOptimalLengthText", "curves --preset mujoco --optimal-length x", "", 2,
     {"--optimal-length x: 'x' is not a finite number"}},
    {"CurvesPresetWithAFile", "curves {file} --preset mujoco", Scenario(), 2,
     {"--preset takes no model file"}},
    {"CurvesPresetWithVelocity", "curves --preset mujoco --velocity 0:1:3", "", 2,
     {"--preset tabulates lengths: --velocity does not apply"}},
    {"CurvesOptimalLengthWithoutPreset", "curves {file} --length 0:1:3 --optimal-length 0.1", Scenario(), 2,
     {"--optimal-length goes with --preset NAME"}},
    {"CurvesPresetLengthHuge", "curves --preset mujoco --length 0:1e4:3", "", 2,
     {"--length 0:1e4:3: B = 10000 must be from -1000 to 1000 [m]"}},
    // --- network scenario -------------------------------------------------------------------
    {"NetworkUnknownNode", "run {file} -o -", Network("to: load, model", "to: @lod, model"), 2,
     {"elements[0].to = lod ({at}): names no node; the nodes are: wall, load, crank"}},
    {"NetworkUnknownModel", "run {file} -o -", Network("model: muscle,", "model: @musle,"), 2,
     {"elements[0].model = musle ({at}): names no model; the models are: muscle"}},
    {"NetworkDuplicateNodeName", "run {file} -o -", Network("{name: crank,", "{name: @wall,"), 2,
     {"nodes[2].name = wall ({at}): must be unique: nodes[0] has it too"}},
    {"NetworkDuplicateElementName", "run {file} -o -", Network("{name: damper,", "{name: @muscle,"), 2,
     {"elements[2].name = muscle ({at}): must be unique: elements[0] has it too"}},
    {"NetworkFloatingFreeNode", "run {file} -o -", Network("  - {name: crank,", "  - {name: @loose, mass: 1, position: 0.5}\n  - {name: crank,"), 2,
     {"nodes[2].name = loose ({at}): floats: no chain of elements joins this free node to a fixed or prescribed node"}},
    {"NetworkNoFreeNode", "run {file} -o -",
     Edit(Edit(Network("{name: load, mass: 0.1, position: 0.1}", "{name: load, fixed: 0.1}"),
               "loads:\n  - {node: load, type: constant, value: 5.0}\n", ""), "nodes:\n  -", "nodes:\n  @-"), 2,
     {"nodes = 3 nodes ({at}): need at least one free node (one with a mass) or an actuator with activation dynamics: the state is their positions and activations"}},
    {"NetworkZeroStartLength", "run {file} -o -", Edit(Network("position: 0.1}", "position: 0.0}"), "  - {name: muscle,", "  - @{name: muscle,"), 2,
     {"elements[0] = muscle ({at}): must be longer than 0 at the start: its length x(load) - x(wall) is 0 m"}},
    {"NetworkNegativeStartLength", "run {file} -o -", Edit(Network("position: 0.1}", "position: -0.05}"), "  - {name: muscle,", "  - @{name: muscle,"), 2,
     {"elements[0] = muscle ({at}): must be longer than 0 at the start: its length x(load) - x(wall) is -0.05 m"}},
    {"NetworkLoadOnFixedNode", "run {file} -o -", Network("{node: load,", "{node: @wall,"), 2,
     {"loads[0].node = wall ({at}): must name a free node (one with a mass); it is fixed"}},
    {"NetworkStepAsPrescribedMotion", "run {file} -o -", Network("{type: ramp, start: 0.0, end: 1.0, from: 0.3, to: 0.31}", "{type: @step, time: 0.5, before: 0.3, after: 0.31}"), 2,
     {"nodes[2].prescribed.type = step ({at}): must be continuous in time: constant, ramp, sine or table"}},
    {"NetworkUnknownKeyInElement", "run {file} -o -", Network("damping: 2.0}", "damping: 2.0, @colour: red}"), 2,
     {"elements[2].colour ({at}): unknown key; allowed here: name, type, from, to, damping"}},
    {"NetworkLinearSolverUnknown", "run {file} -o -", Network("linear_solver: auto", "linear_solver: @klu"), 2,
     {"solver.linear_solver = klu ({at}): must be one of dense, band, sparse, auto"}},
    {"NetworkUnknownTopLevelKey", "run {file} -o -", Network("loads:", "@load:"), 2,
     {"load ({at}): unknown key; allowed here: name, models, nodes, elements, loads, time"}},
    {"NetworkNodeWithTwoKinds", "run {file} -o -", Network("  - {name: wall, fixed: 0.0}", "  - @{name: wall, fixed: 0.0, mass: 1}"), 2,
     {"nodes[0] = fixed and mass ({at}): give exactly one of fixed (its position [m]), prescribed (its motion), mass (a free node [kg], with position and velocity) or point (of a body, with its body)"}},
    {"NetworkNodeWithNoKind", "run {file} -o -", Network("  - {name: wall, fixed: 0.0}", "  - @{name: wall}"), 2,
     {"nodes[0] = none ({at}): give exactly one of fixed (its position [m]), prescribed (its motion), mass (a free node [kg], with position and velocity) or point (of a body, with its body)"}},
    {"NetworkNodeNameNotPlain", "run {file} -o -", Network("{name: crank,", "{name: @\"cr,ank\","), 2,
     {"nodes[2].name = cr,ank ({at}): must be a plain name of letters, digits, _ and -"}},
    {"NetworkElementTypeUnknown", "run {file} -o -", Network("type: damper,", "type: @dashpot,"), 2,
     {"elements[2].type = dashpot ({at}): must be one of actuator, spring, tendon, damper"}},
    {"NetworkTendonBothLaws", "run {file} -o -", Edit(Network("stiffness: 2.0e4}", "stiffness: 2.0e4, exponential: {k: 1, alpha: 10}}"), "  - {name: tendon,", "  - @{name: tendon,"), 2,
     {"elements[1] = stiffness and exponential ({at}): give exactly one of stiffness"}},
    {"NetworkLimitUnknownElement", "run {file} -o -", Network("{element: muscle,", "{element: @musle,"), 2,
     {"limits[0].element = musle ({at}): names no element; the elements are: muscle, tendon, damper"}},
    {"NetworkLimitMinAboveInitial", "run {file} -o -", Network("min_length: 0.05", "min_length: @0.2"), 2,
     {"limits[0].min_length = 0.2 ({at}): must be >= 0 and below muscle's initial length = 0.1 [m]"}},
    {"NetworkMassBelowAMicrogram", "run {file} -o -", Network("mass: 0.1,", "mass: @1e-12,"), 2,
     {"nodes[1].mass = 1e-12 ({at}): must be from 1e-09 to 1e+09 [kg]", "or exactly 0, a massless junction"}},
    {"NetworkJunctionWithoutDamping", "run {file} -o -", Edit(Network("mass: 0.1,", "mass: @0,"), "  - {name: damper, type: damper, from: wall, to: load, damping: 2.0}\n", ""), 2,
     {"nodes[1].mass = 0 ({at}): a massless junction's velocity must follow from its force balance",
      "node load has muscle (actuator), tendon (tendon)"}},
    {"NetworkJunctionWithAVelocity", "run {file} -o -", Network("mass: 0.1, position: 0.1}", "mass: 0, position: 0.1, velocity: @1}"), 2,
     {"nodes[1].velocity = 1 ({at}): must be absent (or 0) on a massless junction"}},
    {"NetworkDeGrooteTendonStrain", "run {file} -o -", Network("stiffness: 2.0e4}", "degroote2016: {max_isometric_force: 100, strain_at_one_norm_force: @0}}"), 2,
     {"elements[1].degroote2016.strain_at_one_norm_force = 0 ({at}): must be > 0 and <= 1 [-]"}},
    {"NetworkSetNestedActivation", "run {file} -o - --set elements[0].activation.after=1.5", Network("name: bad_network", "name: bad_network"), 2,
     {"elements[0].activation.after = 1.5 (--set): activation must stay within [0, 1]"}},
    {"NetworkSetMissingElement", "run {file} -o - --set elements[7].damping=1", Network("name: bad_network", "name: bad_network"), 2,
     {"--set elements[7].damping=1: elements[7] does not exist in {file}"}},
    {"NetworkExcitationAndActivation", "run {file} -o -", Network("before: 0.0, after: 1.0}}", "before: 0.0, after: 1.0},\n     excitation: @{type: constant, value: 1}}"), 2,
     {"elements[0].excitation = {type: constant, value: 1} ({at}): give either activation (u(t) itself) or excitation"}},
    {"NetworkNeitherActivationNorExcitation", "run {file} -o -", Edit(Network(",\n     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "}"), "  - {name: muscle,", "  - @{name: muscle,"), 2,
     {"elements[0].activation ({at}): missing required key: give activation (u(t) itself) or excitation"}},
    {"NetworkExcitationWithoutDynamics", "run {file} -o -", Network("     activation: {type: step", "     excitation: @{type: step"), 2,
     {"elements[0].excitation = {type: step, time: 0.05, before: 0.0, after: 1.0} ({at}): needs activation_dynamics"}},
    {"NetworkDynamicsWithActivation", "run {file} -o -", Network("before: 0.0, after: 1.0}}", "before: 0.0, after: 1.0},\n     activation_dynamics: @{tau_activation: 0.015, tau_deactivation: 0.05}}"), 2,
     {"elements[0].activation_dynamics = {tau_activation: 0.015, tau_deactivation: 0.05} ({at}): only with excitation"}},
    {"NetworkInitialActivationWithActivation", "run {file} -o -", Network("before: 0.0, after: 1.0}}", "before: 0.0, after: 1.0}, initial_activation: @0.5}"), 2,
     {"elements[0].initial_activation = 0.5 ({at}): only with excitation and activation_dynamics"}},
    {"NetworkTauDeactivationHuge", "run {file} -o -", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "tau_deactivation: 0.05", "tau_deactivation: @100"), 2,
     {"elements[0].activation_dynamics.tau_deactivation = 100 ({at}): must be from 1e-04 to 10 [s]"}},
    {"NetworkTauActivationText", "run {file} -o -", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "tau_activation: 0.015", "tau_activation: @fast"), 2,
     {"elements[0].activation_dynamics.tau_activation = fast ({at}): must be a number"}},
    {"NetworkInitialActivationNegative", "run {file} -o -", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "tau_deactivation: 0.05}", "tau_deactivation: 0.05}, initial_activation: @-0.1"), 2,
     {"elements[0].initial_activation = -0.1 ({at}): must be from 0 to 1 [-]"}},
    {"NetworkExcitationSineLeavesUnit", "run {file} -o -", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "{type: step, time: 0.05, before: 0.0, after: 1.0}", "{type: sine, offset: 0.5, amplitude: @0.7, frequency: 1}"), 2,
     {"elements[0].excitation.amplitude = 0.7 ({at}): excitation must stay within [0, 1]"}},
    {"NetworkUnknownKeyInActuator", "run {file} -o -", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "tau_deactivation: 0.05}", "tau_deactivation: 0.05}, @initial: 0.2"), 2,
     {"elements[0].initial ({at}): unknown key; allowed here: name, type, from, to, model, activation, excitation, activation_dynamics, initial_activation"}},
    {"NetworkSetInitialActivation", "run {file} -o - --set elements[0].initial_activation=2", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "name: bad_network", "name: bad_network"), 2,
     {"elements[0].initial_activation = 2 (--set): must be from 0 to 1 [-]"}},
    {"NetworkSetTauDeactivation", "run {file} -o - --set elements[0].activation_dynamics.tau_deactivation=0", Edit(Network("     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "     excitation: {type: step, time: 0.05, before: 0.0, after: 1.0},\n     activation_dynamics: {tau_activation: 0.015, tau_deactivation: 0.05}}"), "name: bad_network", "name: bad_network"), 2,
     {"elements[0].activation_dynamics.tau_deactivation = 0 (--set): must be from 1e-04 to 10 [s]"}},
    // --- the model block --------------------------------------------------------------------
    {"ModelVelocityNZero", "run {file} -o -", Scenario("n: 3", "n: @0"), 2,
     {"model.velocity.n = 0 ({at}): must be an integer from 1 to 1000 [-]"}},
    {"ModelEccentricVMaxZero", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {v_max: @0}}"), 2,
     {"model.velocity.eccentric.v_max = 0 ({at}): must be > 0 and <= 1e+12 [m/s]"}},
    {"ModelEccentricVMaxBelowEpsilon", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {v_max: @1.0e-4}}"), 2,
     {"model.velocity.eccentric.v_max = 1e-04 ({at}): must be between epsilon = 0.001 and 1e12 epsilon [m/s] (epsilon's rule"}},
    {"ModelEccentricNFraction", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {n: @2.5}}"), 2,
     {"model.velocity.eccentric.n = 2.5 ({at}): must be an integer from 1 to 1000 [-]"}},
    {"ModelEccentricLimitAtOne", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {limit: @1.0}}"), 2,
     {"model.velocity.eccentric.limit = 1.0 ({at}): must be > 1 and <= 1e+06 [-]"}},
    {"ModelEccentricLimitHuge", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {limit: @2.0e6}}"), 2,
     {"model.velocity.eccentric.limit = 2.0e6 ({at}): must be > 1 and <= 1e+06 [-]"}},
    {"ModelEccentricUnknownKey", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: {@lim: 1.5}}"), 2,
     {"model.velocity.eccentric.lim ({at}): unknown key; allowed here: v_max, n, limit"}},
    {"ModelEccentricNotAMap", "run {file} -o -", Scenario("epsilon: 1.0e-3}", "epsilon: 1.0e-3, eccentric: @1.5}"), 2,
     {"model.velocity.eccentric = 1.5 ({at}): must be a map"}},
    {"SetEccentricLimitBreaksARule", "run {file} -o - --set model.velocity.eccentric.limit=0.5", Scenario(), 2,
     {"model.velocity.eccentric.limit = 0.5 (--set): must be > 1 and <= 1e+06 [-]"}},
    {"ModelFIsoText", "run {file} -o -", Scenario("f_iso: 100.0", "f_iso: @lots"), 2,
     {"model.f_iso = lots ({at}): must be a number"}},
    {"ModelGaussiansAndFit", "run {file} -o -", Scenario("    gaussians:", "    fit: {count: 2}\n    gaussians:"), 2,
     {"model.active_length = gaussians and fit", "give exactly one of gaussians"}},
    {"ModelUnknownKey", "run {file} -o -", Scenario("  f_iso: 100.0", "  f_iso: 100.0\n  @fiso: 3"), 2,
     {"model.fiso ({at}): unknown key; allowed here: f_iso, passive, active_length, velocity"}},
    // --- --set ------------------------------------------------------------------------------
    {"SetBreaksARule", "run {file} -o - --set model.velocity.n=0", Scenario(), 2,
     {"model.velocity.n = 0 (--set): must be an integer from 1 to 1000"}},
    {"SetKeepsTheFilesLocations", "run {file} -o - --set model.velocity.n=2", Scenario("mass: 0.1,", "mass: @-1,"), 2,
     {"actuator.mass = -1 ({at}): must be from 1e-09"}},
    {"SetTimeEndHuge", "run {file} -o - --set time.end=1e300", Scenario(), 2,
     {"time.end = 1e300 (--set): must be from -1e+09 to 1e+09 [s]"}},
    {"SetIndexOnAMap", "run {file} -o - --set 'model[0].f_iso=50'", Scenario(), 2,
     {"--set model[0].f_iso=50: model is a map, not a list"}},
    {"SetIndexTooLarge", "run {file} -o - --set 'load[99999999999999999999].value=1'", Scenario(), 2,
     {"--set load[99999999999999999999].value=1: 'load[99999999999999999999].value' is not a dotted key path"}},
    {"SetEmptyKey", "run {file} -o - --set a..b=1", Scenario(), 2, {"--set a..b=1: 'a..b' is not a dotted key path"}},
    {"SetWithoutValue", "run {file} -o - --set model.velocity.n", Scenario(), 2,
     {"--set model.velocity.n: expected KEY=VALUE"}},
    {"SetMissingPath", "run {file} -o - --set model.speed.n=3", Scenario(), 2,
     {"--set model.speed.n=3: model.speed does not exist in {file}"}},
    {"SetOnAMap", "run {file} -o - --set model.velocity=3", Scenario(), 2,
     {"--set model.velocity=3: model.velocity is a map or list; an override replaces single values only"}},
    {"SetUnknownKey", "run {file} -o - --set actuator.colour=red", Scenario(), 2,
     {"actuator.colour (--set): unknown key"}},
    // --- run's arguments ----------------------------------------------------------------------
    {"RunFlagWithValue", "run {file} -o - --quiet=1", Scenario(), 2, {"--quiet=1: --quiet is a flag and takes no value"}},
    {"RunUnknownOption", "run {file} --fast", Scenario(), 2, {"unknown option --fast"}},
    {"RunOptionWithoutValue", "run {file} --stats", Scenario(), 2, {"--stats needs a value"}},
    {"RunTwoScenarios", "run {file} {file}", Scenario(), 2, {"expected one scenario file"}},
    {"RunNoScenario", "run", "", 2, {"expected one scenario file"}},
    // --- curves -------------------------------------------------------------------------------
    {"CurvesVelocityHuge", "curves {file} --velocity -1e308:1e308:3", Scenario(), 2,
     {"--velocity -1e308:1e308:3: A = -1e+308 must be from -1000 to 1000 [m/s]"}},
    {"CurvesLengthHuge", "curves {file} --length 0:1e4:3", Scenario(), 2,
     {"--length 0:1e4:3: B = 10000 must be from -1000 to 1000 [m]"}},
    {"CurvesOverflowIsNotPrinted", "curves {file} --length 0:1000:3", Scenario(), 2,
     {"--length 0:1000:3: length = 500: tension_passive = inf there"}},
    {"CurvesBackwards", "curves {file} --length 0.1:0.05:10", Scenario(), 2, {"--length 0.1:0.05:10: A must be less than B"}},
    {"CurvesCountNotANumber", "curves {file} --length 0:1:x", Scenario(), 2, {"--length 0:1:x: N must be an integer from 2"}},
    {"CurvesBothGrids", "curves {file} --length 0:1:3 --velocity 0:1:3", Scenario(), 2, {"give exactly one of --length"}},
    {"CurvesTypoOutsideTheModel", "curves {file} --length 0.1:0.2:3", Scenario("{mass: 0.1,", "{@mas: 0.1,"), 2,
     {"actuator.mas ({at}): unknown key"}},
    {"CurvesScenarioValidatedWhole", "curves {file} --length 0.1:0.2:3", Scenario("mass: 0.1,", "mass: @-0.1,"), 2,
     {"actuator.mass = -0.1 ({at}): must be from 1e-09"}},
    {"CurvesPartialScenario", "curves {file} --length 0.1:0.2:3", "@" + std::string(kModel) + "actuator: {mass: 0.1}\n", 2,
     {"time ({at}): missing required key"}},
    {"CurvesHelpWithValue", "curves --help=yes", "", 2, {"--help=yes: --help is a flag and takes no value"}},
    // --- fit ----------------------------------------------------------------------------------
    {"FitOnExplicitGaussians", "fit {file}", ModelOnly("gaussians: [", "gaussians: @["), 2,
     {"model.active_length.gaussians = 1 components ({at}): explicit components leave nothing to fit"}},
    {"FitPolygonXHuge", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]",
                                                "fit: {count: 2, target: polygon, points: [[0.09, 0], [0.1, 1], [@1e300, 0]]}"), 2,
     {"model.active_length.fit.points[2][0] = 1e300 ({at}): must be from -1000 to 1000 [m]"}},
    {"FitTargetOutsideTheRangeIsBlamed", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]",
                                                "fit: {count: 1, target: polygon, points: @[[500, 0], [501, 1], [502, 0]]}"), 2,
     {"model.active_length.fit.points = 3 points ({at}): the fit of this target gave"}},
    {"FitSampleValueHuge", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]",
                                                   "fit: {count: 1, target: samples, points: [[0.1, @1e7], [0.11, 0]]}"), 2,
     {"model.active_length.fit.points[0][1] = 1e7 ({at}): must be from -1e+06 to 1e+06 [-]"}},
    {"FitCentersHuge", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]",
                                               "fit: {count: 1, widths: [4000], centers: [@1e4]}"), 2,
     {"model.active_length.fit.centers[0] = 1e4 ({at}): must be from -1000 to 1000 [m]"}},
    {"FitCountText", "fit {file}", ModelOnly("gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]",
                                             "fit: {count: @two}"), 2,
     {"model.active_length.fit.count = two ({at}): must be a number"}},
    // --- identify -----------------------------------------------------------------------------
    {"IdentifyDuplicateKey", "identify {file}", Data("count: 2,", "count: 2, @count: 3,"), 2,
     {"active.count ({at}): duplicate key"}},
    {"IdentifyUnknownKey", "identify {file}", Data("passive: {", "@pasive: {"), 2, {"pasive ({at}): unknown key"}},
    {"IdentifyNothing", "identify {file}", "@{}\n", 2, {"(top level) = {} ({at}): give at least one of passive"}},
    {"IdentifyCountHigh", "identify {file}", Data("count: 2,", "count: @13,"), 2,
     {"active.count = 13 ({at}): must be an integer from 1 to 12"}},
    {"IdentifyFIsoHuge", "identify {file}", Data("f_iso: 100}", "f_iso: @1e10}"), 2,
     {"velocity.f_iso = 1e10 ({at}): must be > 0 and <= 1e+09 [N]"}},
    {"IdentifyCsvMissing", "identify {file}", Data("csv: passive.csv", "csv: @none.csv"), 2,
     {"passive.csv = {dir}/none.csv ({at}): {dir}/none.csv: cannot open the file"}},
    {"IdentifyCsvAllZero", "identify {file}", Data("csv: passive.csv", "csv: @zero.csv"), 2,
     {"passive.csv = {dir}/zero.csv ({at}): {dir}/zero.csv: every tension is zero"}},
    {"IdentifyCsvTooFewPositive", "identify {file}", Data("csv: passive.csv", "csv: @one_positive.csv"), 2,
     {"passive.csv = {dir}/one_positive.csv ({at}): ", "fewer than 2 points with positive tension"}},
    {"IdentifyCsvNotANumber", "identify {file}", Data("csv: velocity.csv", "csv: @text.csv"), 2,
     {"velocity.csv = {dir}/text.csv ({at}): {dir}/text.csv:3: column tension = 'heavy': must be a number"}},
    {"IdentifyEccentricWithoutConcentric", "identify {file}", Data("csv: velocity.csv", "csv: @eccentric_only.csv"), 2,
     {"velocity.csv = {dir}/eccentric_only.csv ({at}): velocity data: points with v >= 0: 1; the concentric branch (v_max, n) needs at least 2"}},
    {"IdentifyCsvIsADirectory", "identify {file}", Data("csv: passive.csv", "csv: @sub"), 2,
     {"passive.csv = {dir}/sub ({at}): {dir}/sub: is a directory"}},
    {"IdentifyCsvEmptyName", "identify {file}", Data("csv: passive.csv", "csv: @\"\""), 2,
     {"passive.csv = \"\" ({at}): must not be empty"}},
    // --- sweep --------------------------------------------------------------------------------
    {"SweepDuplicateAxis", "sweep {file} --quiet", Sweep("  model.velocity.n:", "  @actuator.mass: [0.3]\n  model.velocity.n:"), 2,
     {"parameters.actuator.mass ({at}): duplicate key: already given at line 4"}},
    {"SweepUnknownKey", "sweep {file} --quiet", Sweep("mode: grid", "@mdoe: grid"), 2, {"mdoe ({at}): unknown key"}},
    {"SweepModeUnknown", "sweep {file} --quiet", Sweep("mode: grid", "mode: @spiral"), 2,
     {"mode = spiral ({at}): must be one of grid, zip, random"}},
    {"SweepCountZero", "sweep {file} --quiet", Sweep("count: 3", "count: @0"), 2,
     {"parameters.model.velocity.n.count = 0 ({at}): must be >= 1"}},
    {"SweepPointInvalid", "sweep {file} --quiet", Sweep("  actuator.mass: [0.1, 0.2]", "  @actuator.mass: [0.1, -0.2]"), 2,
     // a numeric axis sets its number through the parameter handle: the rule is the
     // handle's, with no "(--set)"
     {"{at}: axis actuator.mass = -0.2 makes point 3 (actuator.mass=-0.2, model.velocity.n=2) an invalid scenario: actuator.mass = -0.2: must be from 1e-09"}},
    {"SweepWindowOutsideTheRun", "sweep {file} --quiet", Sweep("metrics: [final_length]", "metrics: [mean_shortening_velocity]\nmetric_options: {window: [1.5, 2.0]}"), 2,
     {"{file}: metric_options.window = [1.5, 2]: must lie within the run's time [0, 1] [s] (of point 0)"}},
    {"SweepJobsZero", "sweep {file} --jobs 0", Sweep("mode: grid", "mode: grid"), 2, {"--jobs 0: must be an integer from 1 to 4096"}},
    {"SweepFlagWithValue", "sweep {file} --resume=no", Sweep("mode: grid", "mode: grid"), 2,
     {"--resume=no: --resume is a flag and takes no value"}},
    // --- plot ---------------------------------------------------------------------------------
    {"PlotNoOutput", "plot {file}", "t,length\n0,0.1\n", 2, {"-o PATH (a .png or .svg file) is required"}, "csv"},
    {"PlotSizeMalformed", "plot {file} -o {dir}/x.png --size 10", "t,length\n0,0.1\n", 2,
     {"--size 10: expected WIDTHxHEIGHT"}, "csv"},
    {"PlotCurvesScenarioTypo", "plot --curves {file} -o {dir}/x.png", Scenario("{mass: 0.1,", "{@mas: 0.1,"), 2,
     {"actuator.mas ({at}): unknown key"}},
    {"PlotCsvIsADirectory", "plot {dir} -o {dir}/x.png", "", 2, {"is a directory; give a CSV file"}},
    {"PlotUnknownOption", "plot {file} -o {dir}/x.png --quiet", "t,length\n0,0.1\n", 2, {"unknown option --quiet"}, "csv"},
    // --- the program --------------------------------------------------------------------------
    {"UnknownVerb", "dance", "", 2, {"unknown verb 'dance'"}},
    // --- network controllers ----------------------------------------------------------------
    {"NetworkDrivenActuatorWithActivation", "run {file} -o -", Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\ncontrollers:\n  - {name: hold, type: pid, measure: {element: muscle, quantity: length}, reference: {type: constant, value: 0.1}, gains: {kp: -100}, drives: muscle}\n"), "activation: {type: step", "activation: @{type: step"), 2,
     {"elements[0].activation = {type: step, time: 0.05, before: 0.0, after: 1.0} ({at}): actuator muscle is driven by controllers[0] (hold): it has no activation of its own"}},
    {"NetworkExponentialTendonOverflowsAtTheStart", "run {file} -o -", Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\n"), "  - {name: muscle", "  - {name: cable, type: tendon, from: wall, to: load, slack_length: 0.05, exponential: {k: 1.0, alpha: 1.0e5}}\n  - {name: muscle"), 2,
     {"elements[0] = cable", "its tension at the start is inf N (length 0.1 m): its law overflows there"}},
    {"NetworkMaxLengthWhereTheLawOverflows", "run {file} -o -", Edit(Network("alpha: 100.0,", "alpha: 1.0e5,"), "max_length: 0.15", "max_length: @0.15"), 2,
     {"limits[0].max_length = 0.15 ({at}): is a length the run may reach, and there the tension of muscle overflows (inf N)"}},
    {"ControlCharacterInAValue", "run {file} -o -", Network("name: bad_network", "name: @bad\x1b[2Jnetwork\x07"), 2,
     {"name = bad\\x1B[2Jnetwork\\x07 ({at}): holds the control character \\x1B at byte 4; names and values are printable text"}},
    {"SetValueWithAControlCharacter", "run {file} -o - --set 'name=a\x1b[2Jb'", Scenario(), 2,
     {"--set name=a\\x1B[2Jb: holds a control character at byte 7; names and values are printable text"}},
    {"ControlCharacterInAKey", "run {file} -o -", Network("loads:\n", "@lo\x1b" "ads:\n"), 2,
     {"lo\\x1Bads = lo\\x1Bads ({at}): holds the control character \\x1B at byte 3"}},
    {"YamlNestedPastTheLimit", "run {file} -o -", Network("name: bad_network", "name: bad_network") + "extra: " + std::string(3000, '[') + std::string(3000, ']') + "\n", 2,
     {"{file}:", "YAML nesting ", " levels deep, past the reader's limit: a musclesim file nests a few levels"}},
    {"NetworkControllerDrivesAMisspeltActuator", "run {file} -o -", Edit(Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\ncontrollers:\n  - {name: hold, type: pid, measure: {element: muscle, quantity: length}, reference: {type: constant, value: 0.1}, gains: {kp: -100}, drives: musle}\n"), "drives: musle", "drives: @musle"), "     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "}"), 2,
     {"controllers[0].drives = musle ({at}): must name an actuator of the network: muscle"}},
    {"NetworkControllerTypeUnknown", "run {file} -o -", Edit(Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\ncontrollers:\n  - {name: hold, type: pid, measure: {element: muscle, quantity: length}, reference: {type: constant, value: 0.1}, gains: {kp: -100}, drives: muscle}\n"), "type: pid", "type: @lqr"), "     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "}"), 2,
     {"controllers[0].type = lqr ({at}): must be pid"}},
    {"NetworkControllerGainBeyondASwitch", "run {file} -o -", Edit(Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\ncontrollers:\n  - {name: hold, type: pid, measure: {element: muscle, quantity: length}, reference: {type: constant, value: 0.1}, gains: {kp: -100}, drives: muscle}\n"), "kp: -100", "kp: @-1e306"), "     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "}"), 2,
     {"controllers[0].gains.kp = -1e306 ({at}): must be from -1e+09 to 1e+09"}},
    {"NetworkControllerFeedforwardBeyondTheOutput", "run {file} -o -", Edit(Edit(Network("time: {start: 0.0, end: 1.0}\n", "time: {start: 0.0, end: 1.0}\ncontrollers:\n  - {name: hold, type: pid, measure: {element: muscle, quantity: length}, reference: {type: constant, value: 0.1}, gains: {kp: -100}, feedforward: {type: constant, value: 1e300}, drives: muscle}\n"), "value: 1e300", "value: @1e300"), "     activation: {type: step, time: 0.05, before: 0.0, after: 1.0}}", "}"), 2,
     {"controllers[0].feedforward.value = 1e300 ({at}): must be from -1 to 1"}},
    // --- outputs that would overwrite an input or another output (one guard for every verb) ----
    {"RunOutputOverTheScenario", "run {file} -o {file}", Scenario("", ""), 2,
     {"-o {file}: is the scenario file ({file}), an input: write the output elsewhere"}},
    {"RunOutputIsADirectory", "run {file} -o {dir}", Scenario("", ""), 2,
     {"-o {dir}: is a directory: name a file in it"}},
    {"RunStatsInAMissingDirectory", "run {file} -o {dir}/out.csv --stats {dir}/none/s.json", Scenario("", ""), 2,
     {"--stats {dir}/none/s.json: the directory {dir}/none does not exist: create it, or write elsewhere"}},
    {"CurvesOutputIsADirectory", "curves {file} --length 0:1:3 -o {dir}/sub", Scenario("", ""), 2,
     {"-o {dir}/sub: is a directory: name a file in it"}},
    {"RunStatsOverTheCsv", "run {file} -o {dir}/out.csv --stats {dir}/out.csv", Scenario("", ""), 2,
     {"--stats {dir}/out.csv: -o {dir}/out.csv names the same file: give each output its own"}},
    {"RunStatsOverTheScenario", "run {file} -o {dir}/out.csv --stats {file}", Scenario("", ""), 2,
     {"--stats {file}: is the scenario file ({file}), an input: write the output elsewhere"}},
    {"RunPartialIsTheScenario", "run {file} -o {dir}/case.yaml", Scenario("", ""), 2,
     {"-o {dir}/case.yaml: is written through {file}, which is the scenario file ({file}), an input"}, "yaml.partial"},
    {"RunOutputThroughDotDot", "run {file} -o {dir}/sub/../case.yaml", Scenario("", ""), 2,
     {"is the scenario file ({file}), an input: write the output elsewhere"}},
    {"SweepSummaryOverTheSweepFile", "sweep {file} -o {file} --quiet", Sweep("mode: grid", "mode: grid"), 2,
     {"the summary {file}: is the sweep file ({file}), an input: write the output elsewhere"}},
    {"SweepSummaryOverTheBaseScenario", "sweep {file} -o {dir}/base.yaml --quiet", Sweep("mode: grid", "mode: grid"), 2,
     {"the summary {dir}/base.yaml: is the base scenario ({dir}/base.yaml), an input"}},
    {"IdentifyModelOverTheDataFile", "identify {file} -o {file}", Data("count: 2,", "count: 2,"), 2,
     {"-o {file}: is the data file ({file}), an input: write the output elsewhere"}},
    {"IdentifyModelOverACurve", "identify {file} -o {dir}/passive.csv", Data("count: 2,", "count: 2,"), 2,
     {"-o {dir}/passive.csv: is passive.csv ({dir}/passive.csv), an input"}},
    {"IdentifyReportOverACurve", "identify {file} -o {dir}/m.yaml --report {dir}/velocity.csv", Data("count: 2,", "count: 2,"), 2,
     {"--report {dir}/velocity.csv: is velocity.csv ({dir}/velocity.csv), an input"}},
    {"IdentifyReportOverTheModel", "identify {file} -o {dir}/m.yaml --report {dir}/m.yaml", Data("count: 2,", "count: 2,"), 2,
     {"--report {dir}/m.yaml: -o {dir}/m.yaml names the same file: give each output its own"}},
    {"CurvesOverTheModel", "curves {file} --length 0:1:3 -o {file}", Scenario("", ""), 2,
     {"-o {file}: is the model file ({file}), an input: write the output elsewhere"}},
    {"FitOverTheModel", "fit {file} -o {file}", Scenario("", ""), 2,
     {"-o {file}: is the model file ({file}), an input: write the output elsewhere"}},
    {"PlotScriptOverTheCsv", "plot {file} -o {dir}/x.png --script {file}", "t,length\n0,0.1\n", 2,
     {"--script {file}: is the plotted CSV ({file}), an input: write the output elsewhere"}, "csv"},
    {"PlotScriptOverTheFigure", "plot {file} -o {dir}/x.png --script {dir}/x.png", "t,length\n0,0.1\n", 2,
     {"--script {dir}/x.png: -o {dir}/x.png names the same file: give each output its own"}, "csv"},
    {"SweepSummaryInAMissingDirectory", "sweep {file} -o no/such/dir/summary.csv --quiet", Sweep("mode: grid", "mode: grid"), 2,
     {"no/such/dir/summary.csv: the directory no/such/dir does not exist"}},
};
// clang-format on

struct Outcome {
  int exit_code;
  std::string err;
};

// Runs the built program with `arguments` from a shell, standard output discarded.
Outcome RunCli(const std::string& arguments, const std::string& err_path) {
  const std::string command =
      std::string(MUSCLESIM_BINARY) + " " + arguments + " >/dev/null 2>" + err_path;
  const int status = std::system(command.c_str());
  std::ifstream err_file(err_path);
  std::stringstream err;
  err << err_file.rdbuf();
  return {WEXITSTATUS(status), err.str()};
}

std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// "line:column" (1-based) of byte `offset` in `text`.
std::string LineColumn(const std::string& text, std::size_t offset) {
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return std::to_string(line) + ":" + std::to_string(offset - line_start + 1);
}

// The data files of the identify cases, beside the case's file.
void WriteIdentifyData(const std::string& dir) {
  std::ofstream(dir + "/passive.csv")
      << "length,tension\n0.10,0\n0.11,0.5\n0.12,1.5\n0.13,4\n0.14,10\n";
  std::ofstream(dir + "/active.csv")
      << "length,tension\n0.08,5\n0.085,20\n0.09,60\n0.095,95\n0.1,100\n0.105,95\n0.11,60\n"
         "0.115,20\n0.12,5\n";
  std::ofstream(dir + "/velocity.csv")
      << "shortening_velocity,tension\n0,100\n0.2,60\n0.4,35\n0.6,18\n0.8,7\n1.0,0\n";
  std::ofstream(dir + "/eccentric_only.csv")
      << "shortening_velocity,tension\n-1,150\n-0.5,140\n-0.2,120\n0,100\n";
  std::ofstream(dir + "/zero.csv") << "length,tension\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n";
  std::ofstream(dir + "/one_positive.csv") << "length,tension\n0.1,0\n0.2,0\n0.3,0\n0.4,5\n";
  std::ofstream(dir + "/text.csv") << "shortening_velocity,tension\n0,100\n0.5,heavy\n1,0\n";
  std::filesystem::create_directories(dir + "/sub");
}

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, ExitsWithTheCodeAndNamesKeyPlaceAndRule) {
  const Case& c = GetParam();
  // a directory per case: ctest runs the cases in parallel processes
  const std::string dir = ::testing::TempDir() + "bad_input_" + c.name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/case." + c.extension;
  std::string at = "(no @ in the case's file)";
  if (!c.file.empty()) {
    std::string text = c.file;
    if (const auto marker = text.find('@'); marker != std::string::npos) {
      text.erase(marker, 1);
      at = path + ":" + LineColumn(text, marker);
    }
    std::ofstream(path) << text;
  }
  WriteIdentifyData(dir);
  std::ofstream(dir + "/base.yaml") << Scenario();

  const std::string command = ReplaceAll(ReplaceAll(c.command, "{file}", path), "{dir}", dir);
  const Outcome r = RunCli(command, dir + "/stderr.txt");
  EXPECT_EQ(r.exit_code, c.exit_code) << command << "\n" << r.err;
  for (const std::string& needle : c.needles) {
    const std::string expected =
        ReplaceAll(ReplaceAll(ReplaceAll(needle, "{at}", at), "{file}", path), "{dir}", dir);
    EXPECT_THAT(r.err, HasSubstr(expected)) << command;
  }
  // one line: `main` prints one clear line
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

INSTANTIATE_TEST_SUITE_P(EveryReaderAndVerb, BadInput, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return param.param.name;
                         });

TEST(BadInputTable, CoversEnoughCases) {
  // the table is the list of every input error the program promises; it only grows
  EXPECT_GE(kCases.size(), 100u);
}

}  // namespace
}  // namespace musclesim
