// Each part's signals (dynamics/signal_fields.h) as a file gives them: the reader puts each in
// the member the part keeps it in, its parameter handle reaches that member, its values are
// bounded at its key by the range of what it drives, and the parts' validation names it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/io/writers/reference_table.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr const char* kModel =
    "models:\n  m: {family: degroote2016, f_iso: 100, optimal_fiber_length: 0.1}\n";
constexpr const char* kTime = "time: {start: 0.0, end: 0.1}\n";
constexpr const char* kTwoNodes =
    "nodes:\n  - {name: wall, fixed: 0.0}\n  - {name: load, mass: 1.0, position: 0.1}\n";

// A ramp from `from` to `to` between 0.01 s and 0.05 s.
std::string Ramp(const std::string& from, const std::string& to) {
  return "{type: ramp, start: 0.01, end: 0.05, from: " + from + ", to: " + to + "}";
}

// A controller on the actuator e's length, driving it, with `keys` (its reference and more).
std::string Driving(const std::string& keys, const std::string& quantity = "length") {
  return std::string(kTwoNodes) + kModel +
         "elements:\n  - {name: e, type: actuator, from: wall, to: load, model: m" +
         // a tension measured on the actuator driven needs its activation a state
         (quantity == "tension"
              ? ", activation_dynamics: {tau_activation: 0.01, tau_deactivation: 0.04}"
              : "") +
         "}\ncontrollers:\n  - {name: c, type: pid, measure: {element: e, quantity: " + quantity +
         "}, drives: e, gains: {kp: -1}, " + keys + "}\n" + kTime;
}

// A pair a and b on either side of the load, its level `level`.
std::string Pair(const std::string& level) {
  return std::string(
             "nodes:\n  - {name: left, fixed: 0.0}\n  - {name: load, mass: 1.0, position: 0.1}\n"
             "  - {name: right, fixed: 0.2}\n") +
         kModel +
         "elements:\n  - {name: a, type: actuator, from: left, to: load, model: m}\n"
         "  - {name: b, type: actuator, from: load, to: right, model: m}\n"
         "controllers:\n  - {name: c, type: pid, measure: {node: load, quantity: position}, "
         "reference: {type: constant, value: 0.1}, gains: {kp: 1}, co_contraction: {actuators: "
         "[a, b], level: " +
         level + "}}\n" + kTime;
}

// An actuator with `input` (its activation, or an excitation and its dynamics).
std::string Actuator(const std::string& input) {
  return std::string(kTwoNodes) + kModel +
         "elements:\n  - {name: e, type: actuator, from: wall, to: load, model: m, " + input +
         "}\n" + kTime;
}

// A node moved by `motion` on a line, or in the plane by `motion` (a list of two), pulling a
// mass on a spring.
std::string Prescribed(const std::string& motion, int dimensions = 1) {
  const bool line = dimensions == 1;
  return (line ? "" : "dimensions: 2\n") + std::string("nodes:\n  - {name: hand, prescribed: ") +
         motion + "}\n  - {name: load, mass: 1.0, position: " + (line ? "0.5" : "[0.5, 0.0]") +
         "}\nelements:\n  - {name: s, type: spring, from: hand, to: load, stiffness: 10, "
         "rest_length: 0.1}\n" +
         kTime;
}

Scenario Read(const std::string& text) {
  return ReadScenario(ParseDocument("net.yaml", text), "net.yaml");
}

std::string ErrorOf(const std::string& text) {
  try {
    Read(text);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read)";
}

struct Case {
  std::string text;                                        // the signal a ramp from 0.2 to 0.3
  std::string path;                                        // its key path
  std::function<const Waveform&(const Scenario&)> member;  // where the part keeps it
};

TEST(SignalFields, EachSignalIsReadIntoItsMemberAndItsHandleReachesIt) {
  const std::string ramp = Ramp("0.2", "0.3");
  const std::vector<Case> cases{
      {Driving("reference: " + ramp), "controllers[0].reference",
       [](const Scenario& s) -> const Waveform& { return s.controllers[0].reference; }},
      {Driving("reference: {type: constant, value: 0.1}, feedforward: " + ramp),
       "controllers[0].feedforward",
       [](const Scenario& s) -> const Waveform& { return s.controllers[0].feedforward; }},
      {Pair(ramp), "controllers[0].co_contraction.level",
       [](const Scenario& s) -> const Waveform& { return s.controllers[0].co_contraction->level; }},
      {Actuator("activation: " + ramp), "elements[0].activation",
       [](const Scenario& s) -> const Waveform& { return s.elements[0].activation; }},
      {Actuator("excitation: " + ramp +
                ", activation_dynamics: {tau_activation: 0.01, tau_deactivation: 0.04}"),
       "elements[0].excitation",
       [](const Scenario& s) -> const Waveform& { return s.elements[0].excitation->signal; }},
      {Prescribed(ramp), "nodes[0].prescribed",
       [](const Scenario& s) -> const Waveform& { return s.nodes[0].motion; }},
      {Prescribed("[{type: constant, value: 0.1}, " + ramp + "]", 2), "nodes[0].prescribed[1]",
       [](const Scenario& s) -> const Waveform& { return s.nodes[0].motion_yz[0]; }},
  };
  for (const Case& c : cases) {
    Scenario s = Read(c.text);
    const Waveform& w = c.member(s);
    EXPECT_EQ(w.kind, WaveformKind::kRamp) << c.path;
    EXPECT_EQ(w.from, 0.2) << c.path;
    EXPECT_EQ(w.to, 0.3) << c.path;
    EXPECT_EQ(w.end, 0.05) << c.path;
    const Parameter to = s.parameter(c.path + ".to");
    EXPECT_EQ(to.Get(s), 0.3) << c.path;
    to.Set(s, 0.25);
    EXPECT_EQ(c.member(s).to, 0.25) << c.path;
    // a ramp's fields only: it has no value
    EXPECT_THROW(s.parameter(c.path + ".value"), ParameterError) << c.path;
  }
}

TEST(SignalFields, AHandleReachesOnlyTheSignalsThePartHas) {
  const Scenario driven = Read(Driving("reference: {type: constant, value: 0.1}"));
  EXPECT_THROW(driven.parameter("controllers[0].co_contraction.level.value"), ParameterError);
  EXPECT_THROW(driven.parameter("elements[0].activation.value"), ParameterError);  // controlled
  // every step of a nested signal's key, not its last alone
  const Scenario pair = Read(Pair(Ramp("0.2", "0.3")));
  EXPECT_EQ(pair.parameter("controllers[0].co_contraction.level.to").Get(pair), 0.3);
  EXPECT_THROW(pair.parameter("controllers[0].contraction.level.to"), ParameterError);
  const Scenario excited = Read(Actuator(
      "excitation: {type: constant, value: 0.5}, activation_dynamics: {tau_activation: 0.01, "
      "tau_deactivation: 0.04}"));
  EXPECT_THROW(excited.parameter("elements[0].activation.value"), ParameterError);
  EXPECT_EQ(excited.parameter("elements[0].excitation.value").Get(excited), 0.5);
  // a handle keeps to the signal's bounds at its part: a feedforward's, a tension's
  const Scenario forward =
      Read(Driving("reference: {type: constant, value: 0.1}, feedforward: " + Ramp("0", "0.5")));
  EXPECT_NO_THROW(forward.parameter("controllers[0].feedforward.to").Check(0.9));
  EXPECT_THROW(forward.parameter("controllers[0].feedforward.to").Check(1.5), ParameterError);
  EXPECT_NO_THROW(forward.parameter("controllers[0].reference.value").Check(999.0));
  EXPECT_THROW(forward.parameter("controllers[0].reference.value").Check(1001.0), ParameterError);
  const Scenario tension = Read(Driving("reference: {type: constant, value: 10}", "tension"));
  EXPECT_NO_THROW(tension.parameter("controllers[0].reference.value").Check(1e6));
  EXPECT_THROW(tension.parameter("controllers[0].reference.value").Check(2e9), ParameterError);
  const Scenario line = Read(Prescribed("{type: constant, value: 0.1}"));
  EXPECT_THROW(line.parameter("nodes[0].prescribed[0].value"), ParameterError);  // no index
  EXPECT_THROW(line.parameter("nodes[1].prescribed.value"), ParameterError);     // free
  const Scenario plane =
      Read(Prescribed("[{type: constant, value: 0.1}, {type: constant, value: 0.2}]", 2));
  EXPECT_EQ(plane.parameter("nodes[0].prescribed[0].value").Get(plane), 0.1);
  EXPECT_THROW(plane.parameter("nodes[0].prescribed.value"), ParameterError);  // needs one
  EXPECT_THROW(plane.parameter("nodes[0].prescribed[2].value"), ParameterError);
}

TEST(SignalFields, EachSignalsValuesAreBoundedAtItsKeyByWhatItDrives) {
  struct Refusal {
    std::string text;
    std::string at;    // "key = value"
    std::string rule;  // the rule stated
  };
  const std::vector<Refusal> refusals{
      {Driving("reference: " + Ramp("0", "2e9"), "tension"), "controllers[0].reference.to = 2e9",
       kForceRange.Rule()},
      {Driving("reference: " + Ramp("0", "2e3")), "controllers[0].reference.to = 2e3",
       kPositionRange.Rule()},
      {Driving("reference: {type: constant, value: 0.1}, feedforward: " + Ramp("0", "1.5")),
       "controllers[0].feedforward.to = 1.5", kFeedforwardRange.Rule()},
      {Pair(Ramp("0", "1.5")), "controllers[0].co_contraction.level", "within [0, 1]"},
      {Actuator("activation: " + Ramp("0", "1.5")), "elements[0].activation", "within [0, 1]"},
      {Prescribed(Ramp("0", "2e3")), "nodes[0].prescribed.to = 2e3", kPositionRange.Rule()},
      {Prescribed("{type: step, time: 0.01, before: 0.1, after: 0.2}"),
       "nodes[0].prescribed.type = step", "must be continuous in time"},
      {Prescribed("{type: constant, value: 0.1}", 2), "nodes[0].prescribed",
       "must be a list of 2 motions [x(t), y(t)]"},
      {Prescribed("[{type: constant, value: 0.1}]"), "nodes[0].prescribed",
       "must be one motion (a waveform) in 1 dimension"},
      {Pair("{type: wave}"), "controllers[0].co_contraction.level.type = wave", "must be one of"},
      {Driving("feedforward: " + Ramp("0", "0.1")), "controllers[0].reference",
       "missing required key"},
  };
  for (const Refusal& r : refusals) {
    const std::string message = ErrorOf(r.text);
    EXPECT_THAT(message, HasSubstr(r.at)) << r.text;
    EXPECT_THAT(message, HasSubstr(r.rule)) << r.text;
    EXPECT_THAT(message, HasSubstr("net.yaml:")) << r.text;
  }
}

TEST(SignalFields, ValidateNamesTheSignalBelowThePartsKeys) {
  Controller pair = Controller::CoContracting(
      "c", Measurement{"", "load", MeasuredQuantity::kPosition}, Waveform::Constant(0.1),
      PidGains{1.0, 0.0, 0.0}, CoContraction{"a", "b", Waveform::Constant(0.3)});
  pair.co_contraction->level = Waveform{};
  pair.co_contraction->level.kind = WaveformKind::kRamp;
  pair.co_contraction->level.start = 0.0;
  pair.co_contraction->level.end = 1.0;
  pair.co_contraction->level.to = 1.5;
  try {
    Validate(pair);
    ADD_FAILURE() << "an activation past 1 validated";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.path().rfind("co_contraction.level.", 0), 0u) << error.path();
  }
  Node node = Node::Prescribed("hand", Waveform::Constant(0.1));
  node.motion_yz[1] = Waveform{};
  node.motion_yz[1].kind = WaveformKind::kStep;
  try {
    Validate(node);
    ADD_FAILURE() << "a step motion validated";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.path(), "prescribed[2].type");
  }
}

TEST(SignalFields, TheReferenceRowsStateEachSignal) {
  const std::string rows = SignalRows(ControllerSignals(), "every");
  EXPECT_THAT(rows, HasSubstr("| every | | `reference` | m or N | required |"));
  EXPECT_THAT(rows, HasSubstr("| every | | `feedforward` | - | optional |"));
  EXPECT_THAT(rows, HasSubstr(kFeedforwardRange.why));
  EXPECT_THAT(rows,
              HasSubstr("| every | | `co_contraction.level` | - | required with co_contraction |"));
  const std::string motion = SignalCells(NodeSignals()).front().second;
  EXPECT_THAT(motion, HasSubstr("constant, ramp, sine or table, one per coordinate"));
  EXPECT_THAT(motion, HasSubstr(kPositionRange.why));
  EXPECT_EQ(SignalCells(ActuatorSignals<Element>()).size(), 2u);
}

}  // namespace
}  // namespace musclesim
