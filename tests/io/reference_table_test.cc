// The reference tables in the docs are the parts' descriptions as they are: each table, between
// its markers, is what ReferenceTable renders; and the descriptions' ranges are the ones the
// readers apply (a value past each bound refused with that bound's rule, the default used when
// the key is absent).
#include "musclesim/io/writers/reference_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/actuator_fields.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/dynamics/waveform_shapes.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/io/readers/identify_spec.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/model/family_fields.h"
#include "musclesim/model/fit_fields.h"
#include "musclesim/optimize/problem_fields.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/setting_fields.h"
#include "musclesim/solver/solver_fields.h"
#include "musclesim/sweep/sweep_file.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string Read(const std::string& relative) {
  std::ifstream in(std::string(MUSCLESIM_SOURCE_DIR) + "/" + relative);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between "<!-- reference: NAME -->\n" and "<!-- end reference -->" in `page`.
std::string Block(const std::string& page, const std::string& name) {
  const std::string open = "<!-- reference: " + name + " -->\n";
  const std::size_t begin = page.find(open);
  if (begin == std::string::npos) return "(no block " + name + ")";
  const std::size_t end = page.find("<!-- end reference -->", begin);
  return page.substr(begin + open.size(), end - begin - open.size());
}

constexpr const char* kRewrite =
    "the docs' table differs from the part's description: python3 scripts/reference_tables.py "
    "rewrites it";

TEST(ReferenceTable, NodeKindsInTheNetworksGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/networks.md"), "nodes"),
            ReferenceTable(NodeKinds(), "node", NameRows(NodeNames()), SignalCells(NodeSignals())))
      << kRewrite;
}

TEST(ReferenceTable, ElementLawsInTheNetworksGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/networks.md"), "element laws"),
            ReferenceTable(ElementLaws(), "type", NameRows(ElementNames())) +
                SignalRows(ActuatorSignals<Element>(), "`actuator`"))
      << kRewrite;
}

TEST(ReferenceTable, LoadsInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "loads"),
            ReferenceTable(LoadVariants(), "type", NameRows(LoadNames())))
      << kRewrite;
}

TEST(ReferenceTable, ActivationFamiliesInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "activation dynamics"),
            ReferenceTable(ActivationFamilies(), "family"))
      << kRewrite;
}

TEST(ReferenceTable, WaveformShapesInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "waveforms"), ReferenceTable(WaveformShapes()))
      << kRewrite;
}

TEST(ReferenceTable, ModelFamiliesInTheModelGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/model.md"), "model families"),
            ReferenceTable(ModelFamilies(), "family"))
      << kRewrite;
}

TEST(ReferenceTable, TheFitBlockInTheModelGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/model.md"), "fit"), ReferenceTable(FitBlock(), "block"))
      << kRewrite;
}

TEST(ReferenceTable, ControllersInTheControlGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/control.md"), "controllers"),
            ReferenceTable(ControllerTypes(), "type",
                           NameRows(ControllerNames()) + SignalRows(ControllerSignals(), "every")))
      << kRewrite;
}

TEST(ReferenceTable, TheActuatorBlockInTheScenariosGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "actuator"),
            ReferenceTable(ActuatorBlock(), "block"))
      << kRewrite;
}

TEST(ReferenceTable, TheSolverBlockInTheScenariosGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "solver"),
            ReferenceTable(SolverBlock(), "block"))
      << kRewrite;
}

TEST(ReferenceTable, TheTimeAndOutputBlocksInTheScenariosGuideAreTheDescriptions) {
  const std::string page = Read("docs/guide/scenarios.md");
  EXPECT_EQ(Block(page, "time"), ReferenceTable(TimeBlock(), "block")) << kRewrite;
  EXPECT_EQ(Block(page, "output"), ReferenceTable(OutputBlock(), "block")) << kRewrite;
}

TEST(ReferenceTable, TheSeriesFileInTheIdentificationGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/identification.md"), "identify series"),
            ReferenceHeader("entry") + ReferenceRows(IdentifySeriesFile()) +
                ReferenceRows(SeriesEntry()) + ReferenceRows(SeriesParameterEntry()))
      << kRewrite;
}

TEST(ReferenceTable, TheProblemFileInTheOptimizeGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/optimize.md"), "problem"), ProblemReference()) << kRewrite;
}

TEST(ReferenceTable, TheSweepFileInTheSweepsGuideIsTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/sweeps.md"), "sweep"), ReferenceTable(SweepFileBlock(), "block"))
      << kRewrite;
}

TEST(ReferenceTable, TheIdentifyBlocksInTheIdentificationGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/identification.md"), "identify"),
            ReferenceTable(IdentifyDataBlocks(), "block"))
      << kRewrite;
}

TEST(ReferenceTable, RendersEachFieldOnceWithItsDefaultAndBounds) {
  const std::string table = ReferenceTable(LoadVariants());
  EXPECT_THAT(table, HasSubstr("| `mass` (hanging mass) | F = mass gravity"));
  EXPECT_THAT(table, HasSubstr("| `gravity` | m/s^2 | 9.81 | from -1000 to 1000: about 100 g"));
  EXPECT_THAT(table, HasSubstr("| `stiffness` | N/m | required | from 0 to 1e+12: "));
  // a word field: its default and the names it accepts
  EXPECT_THAT(ReferenceTable(SolverBlock(), "block"),
              HasSubstr("| `method` | | bdf | a name: bdf, adams | "));
  // an open upper bound
  EXPECT_THAT(ReferenceTable(SolverBlock(), "block"),
              HasSubstr("| `rtol` | - | 1e-06 | >= 1e-14 and < 1: "));
  // names: a part's own, and one it refers to, ahead of the variants
  const std::string elements = ReferenceTable(ElementLaws(), "type", NameRows(ElementNames()));
  EXPECT_THAT(elements, HasSubstr("|---|\n| every | | `name` | | required | a plain name of "));
  EXPECT_THAT(elements, HasSubstr("| every | | `from` | | required | the name of a node | "));
}

// The message of reading the network file `text` from memory, or "(read)".
std::string NetworkError(const std::string& text) {
  try {
    ReadScenario(ParseDocument("net.yaml", text), "net.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read)";
}

// The rule a handle of `path` on `scenario` is refused with, or "found".
std::string ParameterRefusal(const Scenario& scenario, const std::string& path) {
  try {
    scenario.parameter(path);
  } catch (const ParameterError& error) {
    return error.rule();
  }
  return "found";
}

// The inner text of a map holding every field of `variant` (`name_key: type` first), nested
// fields in their own maps: `changed` at `value`, each other ranged field at half its maximum.
template <typename Part>
std::string FieldsText(const PartVariant<Part>& variant, const NumberField<Part>& changed,
                       double value, const std::string& name_key) {
  std::string keys = name_key + ": " + variant.type;
  std::string nested;  // "exponential: {k: 1, alpha: 2"
  std::string head;
  for (const NumberField<Part>& field : variant.fields) {
    const double v = &field == &changed ? value : field.range.max / 2.0;
    const std::string key = field.key;
    const std::string number = FormatNumber(v);
    if (key.find('.') == std::string::npos) {
      keys += ", " + key + ": " + number;
      continue;
    }
    const std::string h(HeadKey(key));
    if (h != head) {
      if (!nested.empty()) keys += ", " + nested + "}";
      nested = h + ": {";
      head = h;
    } else {
      nested += ", ";
    }
    nested += key.substr(h.size() + 1) + ": " + number;
  }
  if (!nested.empty()) keys += ", " + nested + "}";
  return keys;
}

// Every ranged field of every variant, through the reader: its value just past each bound is
// refused with the bound's rule at `prefix` + its key, and its largest value is read.
// `file(fields)` is a network file holding the part written as `fields`.
template <typename Part, typename File>
void ExpectEachBoundRefused(const std::vector<PartVariant<Part>>& variants,
                            const std::string& name_key, const std::string& prefix, File file) {
  for (const PartVariant<Part>& variant : variants) {
    for (const NumberField<Part>& field : variant.fields) {
      if (field.values != FieldValues::kRange) continue;
      SCOPED_TRACE(std::string(variant.name) + " " + field.key);
      const auto text = [&](double value) {
        return file(FieldsText(variant, field, value, name_key));
      };
      const double below = field.range.min_exclusive ? field.range.min : field.range.min - 1.0;
      const double above = field.range.max_exclusive ? field.range.max : field.range.max * 2.0;
      for (const double bad : {above, below}) {
        if (std::isinf(bad)) continue;  // a range up to the largest double: nothing above it
        const std::string message = NetworkError(text(bad));
        EXPECT_THAT(message, HasSubstr(prefix + field.key + " = "));
        EXPECT_THAT(message, HasSubstr(FieldRule(field)));
      }
      // the largest value accepted: the bound, or a few roundoffs below an open one
      const double largest =
          field.range.max_exclusive ? field.range.max * (1.0 - 1e-15) : field.range.max;
      EXPECT_EQ(NetworkError(text(largest)), "(read)");
    }
  }
}

constexpr const char* kTwoNodes =
    "nodes:\n  - {name: wall, fixed: 0.0}\n  - {name: load, mass: 1.0, position: 0.1}\n";
constexpr const char* kTime = "time: {start: 0.0, end: 0.1}\n";

// The output block through the reader and as handles: `interval` a time or the word `steps`
// (a row per step, and then no number to vary), absent a thousandth of the span; `file` any
// text but the empty one, absent the verb's own.
// A list's numbers come together from index 0 and none is optional on its own (an optional
// list's are optional together), which the writers and the Python dicts rely on (they take
// the list whole at its first number).
template <typename Part>
void ExpectListsContiguous(const std::vector<PartVariant<Part>>& variants) {
  for (const PartVariant<Part>& variant : variants) {
    std::string list;  // the list being walked, "" between lists
    std::size_t next = 0;
    bool optional = false;  // the list's first number's
    for (const NumberField<Part>& field : variant.fields) {
      const std::optional<ListElement> element = ElementOf(field.key);
      const std::string head = element ? std::string(element->list) : "";
      SCOPED_TRACE(std::string(variant.type) + " " + field.key);
      if (!element) {
        list.clear();
        continue;
      }
      if (head != list) {
        EXPECT_EQ(element->index, 0u);
        list = head;
        next = 0;
        optional = static_cast<bool>(field.given);
      }
      EXPECT_EQ(static_cast<bool>(field.given), optional);
      EXPECT_EQ(element->index, next++);
      EXPECT_LT(element->index, ListLength(variant, head));
    }
  }
}

TEST(ReferenceTable, EachListOfNumbersIsContiguous) {
  ExpectListsContiguous(ModelFamilies());
  ExpectListsContiguous(ActivationFamilies());
  ExpectListsContiguous(ElementLaws());
  ExpectListsContiguous(NodeKinds());
  ExpectListsContiguous(LoadVariants());
  ExpectListsContiguous(WaveformShapes());
  ExpectListsContiguous(ControllerGains());
  ExpectListsContiguous(SolverBlock());
  ExpectListsContiguous(OutputBlock());
  ExpectListsContiguous(TimeBlock());
  ExpectListsContiguous(ActuatorBlock());
  ExpectListsContiguous(IdentifyDataBlocks());
  ExpectListsContiguous(SweepFileBlock());
  ExpectListsContiguous(SeriesParameterEntry());
  ExpectListsContiguous(ControlEntry());
  ExpectListsContiguous(FinalValueEntry());
  ExpectListsContiguous(PathBoundEntry());
  ExpectListsContiguous(ParameterEntry());
  ExpectListsContiguous(FinalTimeBlock());
}

TEST(ReferenceTable, TheReaderReadsTheOutputBlock) {
  const auto file = [](const std::string& output) {
    return std::string(kTwoNodes) +
           "elements:\n  - {name: e, type: spring, from: wall, to: load, stiffness: 10, "
           "rest_length: 0.1}\n" +
           kTime + output;
  };
  const auto read = [&file](const std::string& output) {
    return ReadScenario(ParseDocument("net.yaml", file(output)), "net.yaml");
  };
  const Scenario steps = read("output: {interval: steps, file: rows.csv}\n");
  EXPECT_TRUE(steps.output.every_step);
  EXPECT_EQ(steps.output.interval, 0.0);
  EXPECT_EQ(steps.output.file, "rows.csv");
  EXPECT_THAT(ParameterRefusal(steps, "output.interval"), HasSubstr("names no numeric setting"));
  Scenario timed = read("output: {interval: 0.002}\n");
  EXPECT_FALSE(timed.output.every_step);
  EXPECT_EQ(timed.output.interval, 0.002);
  EXPECT_EQ(timed.output.file, "");
  EXPECT_EQ(timed.parameter("output.interval").Get(timed), 0.002);
  timed.parameter("output.interval").Set(timed, 0.004);
  EXPECT_EQ(timed.output.interval, 0.004);
  EXPECT_EQ(read("output: {phase_tolerance: 0.01}\n").output.interval, 0.1 / 1000.0);
  EXPECT_THAT(NetworkError(file("output: {file: \"\"}\n")),
              HasSubstr("output.file = \"\" (net.yaml:7:16): must not be empty"));
  EXPECT_THAT(NetworkError(file("output: {interval: step}\n")),
              HasSubstr("output.interval = step (net.yaml:7:20): must be a number"));
}

TEST(ReferenceTable, TheReaderAppliesEachLawsRanges) {
  ExpectEachBoundRefused(ElementLaws(), "type", "elements[0].", [](const std::string& fields) {
    return std::string(kTwoNodes) + "elements:\n  - {name: e, from: wall, to: load, " + fields +
           "}\n" + kTime;
  });
}

// Every name of a part, through the reader: left out, it is missing at its key path (an
// optional one is not); a
// part's own name with a dot is refused (it would split a CSV column's name); a reference to
// no part is refused when the network is built, at the reference's key path. `file(names)`
// is a network file holding the part with `names` ("name: e, from: wall, to: load").
template <typename Part, typename File>
void ExpectEachNameRead(const std::vector<NameField<Part>>& names, const std::string& prefix,
                        const std::map<std::string, std::string>& valid, File file) {
  const auto text = [&](const std::string& left_out, const std::string& replaced,
                        const std::string& by) {
    std::string written;
    for (const NameField<Part>& name : names) {
      if (name.key == left_out) continue;
      written += (written.empty() ? "" : ", ") + name.key + ": " +
                 (name.key == replaced ? by : valid.at(name.key));
    }
    return file(written);
  };
  EXPECT_EQ(NetworkError(text("", "", "")), "(read)");
  for (const NameField<Part>& name : names) {
    SCOPED_TRACE(name.key);
    const std::string at = prefix + name.key;
    const std::string missing = NetworkError(text(name.key, "", ""));
    if (name.required) {
      EXPECT_THAT(missing, HasSubstr(at + " ("));
      EXPECT_THAT(missing, HasSubstr("): missing required key"));
    } else {
      // one of several: the part's rule among them may refuse, not the name's absence
      EXPECT_THAT(missing, Not(HasSubstr(at + " (")));
    }
    const std::string bad = NetworkError(text("", name.key, name.is_own() ? "a.b" : "nowhere"));
    EXPECT_THAT(bad, HasSubstr(at + " = "));
    EXPECT_THAT(bad, HasSubstr(name.is_own() ? "must be a plain name" : "nowhere"));
  }
}

TEST(ReferenceTable, TheReaderReadsEachName) {
  ExpectEachNameRead(ElementNames(), "elements[0].",
                     {{"name", "e"}, {"from", "wall"}, {"to", "load"}},
                     [](const std::string& names) {
                       return std::string(kTwoNodes) + "elements:\n  - {type: spring, " + names +
                              ", stiffness: 10, rest_length: 0.1}\n" + kTime;
                     });
  ExpectEachNameRead(LoadNames(), "loads[0].", {{"node", "load"}}, [](const std::string& names) {
    return std::string(kTwoNodes) +
           "elements:\n  - {name: e, type: spring, from: wall, to: load, stiffness: 10, "
           "rest_length: 0.1}\nloads:\n  - {type: constant, value: 1.0, " +
           names + "}\n" + kTime;
  });
  // a controller's, and its measure's one name, an element's or a node's
  const auto controlled = [](const std::string& names, const std::string& measure) {
    return std::string(kTwoNodes) +
           "models:\n  m: {family: degroote2016, f_iso: 100, optimal_fiber_length: 0.1}\n"
           "elements:\n  - {name: e, type: actuator, from: wall, to: load, model: m}\n"
           "controllers:\n  - {type: pid, " +
           names + ", measure: {" + measure +
           "}, reference: {type: constant, value: 0.1}, gains: {kp: -1}}\n" + kTime;
  };
  ExpectEachNameRead(
      ControllerNames(), "controllers[0].", {{"name", "c"}, {"drives", "e"}},
      [&](const std::string& names) { return controlled(names, "element: e, quantity: length"); });
  ExpectEachNameRead(std::vector{MeasureNames()[0]}, "controllers[0].measure.", {{"element", "e"}},
                     [&](const std::string& names) {
                       return controlled("name: c, drives: e", names + ", quantity: length");
                     });
  ExpectEachNameRead(std::vector{MeasureNames()[1]}, "controllers[0].measure.", {{"node", "load"}},
                     [&](const std::string& names) {
                       return controlled("name: c, drives: e", names + ", quantity: position");
                     });
  ExpectEachNameRead(NodeNames(), "nodes[1].", {{"name", "load"}}, [](const std::string& names) {
    return "nodes:\n  - {name: wall, fixed: 0.0}\n  - {mass: 1.0, position: 0.1, " + names +
           "}\n"
           "elements:\n  - {name: e, type: spring, from: wall, to: load, stiffness: 10, "
           "rest_length: 0.1}\n" +
           kTime;
  });
}

TEST(ReferenceTable, TheReaderAppliesEachLoadsRanges) {
  ExpectEachBoundRefused(LoadVariants(), "type", "loads[0].", [](const std::string& fields) {
    return std::string(kTwoNodes) +
           "elements:\n  - {name: e, type: spring, from: wall, to: load, stiffness: 10, "
           "rest_length: 0.1}\nloads:\n  - {node: load, " +
           fields + "}\n" + kTime;
  });
}

TEST(ReferenceTable, TheReaderAppliesEachActivationFamilysRanges) {
  ExpectEachBoundRefused(
      ActivationFamilies(), "family", "elements[0].activation_dynamics.",
      [](const std::string& fields) {
        return std::string(kTwoNodes) +
               "models:\n  m: {family: degroote2016, f_iso: 100, optimal_fiber_length: 0.1}\n"
               "elements:\n  - {name: e, type: actuator, from: wall, to: load, model: m, "
               "excitation: {type: constant, value: 0.5}, activation_dynamics: {" +
               fields + "}}\n" + kTime;
      });
}

TEST(ReferenceTable, TheReaderAppliesEachGainsRange) {
  // FieldsText writes `type: pid` first, the controller's own type key
  ExpectEachBoundRefused(
      ControllerGains(), "type", "controllers[0].gains.", [](std::string fields) {
        fields.replace(0, std::string("type: pid, ").size(), "");  // the gains' own map
        return std::string(kTwoNodes) +
               "models:\n  m: {family: degroote2016, f_iso: 100, optimal_fiber_length: 0.1}\n"
               "elements:\n  - {name: e, type: actuator, from: wall, to: load, model: m}\n"
               "controllers:\n  - {name: c, type: pid, measure: {element: e, quantity: length}, "
               "reference: {type: constant, value: 0.1}, drives: e, gains: {" +
               fields + "}}\n" + kTime;
      });
}

TEST(ReferenceTable, TheReaderAppliesEachSolverRange) {
  ExpectEachBoundRefused(SolverBlock(), "type", "solver.", [](std::string fields) {
    fields.replace(0, std::string("type: solver, ").size(), "");  // the block has no type
    return std::string(kTwoNodes) +
           "elements:\n  - {name: e, type: spring, from: wall, to: load, stiffness: 10, "
           "rest_length: 0.1}\n" +
           kTime + "solver: {" + fields + "}\n";
  });
}

// A point written for `dimensions`: x itself on a line, else a list with `value` at
// coordinate c and 0 elsewhere.
std::string PointText(int dimensions, double value, std::size_t c) {
  if (dimensions == 1) return FormatNumber(value);
  std::string list = "[";
  for (std::size_t k = 0; k < static_cast<std::size_t>(dimensions); ++k) {
    list += (k == 0 ? "" : ", ") + FormatNumber(k == c ? value : 0.0);
  }
  return list + "]";
}

// Every bound of every node field and point, through the reader, on a line and in the plane:
// node x (nodes[2], of each kind in turn, its other keys at half their maxima) joined by a
// spring to a free node on a spring to the wall.
TEST(ReferenceTable, TheReaderAppliesEachNodesRanges) {
  for (const int d : {1, 2}) {
    for (const NodeVariant& variant : NodeKinds()) {
      // a node on a body (its text names the body) needs a skeleton, in 2 or 3 dimensions
      const bool on_body = !variant.texts.empty();
      if (on_body && d == 1) continue;
      const auto text = [&](const std::string& key, std::size_t c, double value) {
        std::string x = "{name: x";
        for (const NumberField<Node>& f : variant.fields) {
          x += ", " + f.key + ": " + FormatNumber(f.key == key ? value : f.range.max / 2.0);
        }
        for (const PointField<Node>& p : variant.points) {
          x += ", " + p.key + ": " +
               (p.key == key ? PointText(d, value, c) : PointText(d, p.range.max / 2.0, 0));
        }
        for (const TextField<Node>& t : variant.texts) x += ", " + t.key + ": link";
        const std::string skeleton =
            on_body ? "bodies:\n  - {name: link, mass: 1.0, inertia: [1, 1, 1, 0, 0, 0]}\n"
                      "joints:\n  - {name: hinge, type: revolute, child: link}\n"
                    : "";
        return std::string(d == 1 ? "" : "dimensions: 2\n") + skeleton +
               "nodes:\n  - {name: wall, fixed: " + PointText(d, 0.0, 0) +
               "}\n  - {name: load, mass: 1.0, position: " + PointText(d, 0.1, 0) + "}\n  - " + x +
               "}\nelements:\n  - {name: a, type: spring, from: wall, to: load, stiffness: 10, "
               "rest_length: 0.1}\n  - {name: b, type: spring, from: load, to: x, stiffness: "
               "10, rest_length: 0.1}\n" +
               kTime;
      };
      for (const NumberField<Node>& field : variant.fields) {
        SCOPED_TRACE(std::string(variant.name) + " " + field.key);
        for (const double bad : {field.range.max * 2.0, field.range.min - 1.0}) {
          const std::string message = NetworkError(text(field.key, 0, bad));
          EXPECT_THAT(message, HasSubstr("nodes[2]." + field.key + " = "));
          EXPECT_THAT(message, HasSubstr(FieldRule(field)));
        }
        EXPECT_EQ(NetworkError(text(field.key, 0, field.range.max)), "(read)");
      }
      for (const PointField<Node>& point : variant.points) {
        for (std::size_t c = 0; c < static_cast<std::size_t>(d); ++c) {
          SCOPED_TRACE(std::string(variant.name) + " " + point.key + " coordinate " +
                       std::to_string(c) + " of " + std::to_string(d));
          const std::string at = d == 1 ? point.key : point.key + "[" + std::to_string(c) + "]";
          for (const double bad : {point.range.max * 2.0, point.range.min * 2.0}) {
            const std::string message = NetworkError(text(point.key, c, bad));
            EXPECT_THAT(message, HasSubstr("nodes[2]." + at + " = "));
            EXPECT_THAT(message, HasSubstr(point.range.Rule()));
          }
          EXPECT_EQ(NetworkError(text(point.key, c, point.range.max)), "(read)");
        }
      }
    }
  }
}

// The same for the other families' model blocks: each ranged field past each bound refused
// with its rule at model.KEY, and its largest value read.
TEST(ReferenceTable, TheReaderAppliesEachModelFamilysRanges) {
  // what each family requires, in order; the field under test replaces or joins them
  const auto required = [](const ModelFamily& family) {
    return std::string_view(family.type) == "mujoco"
               ? std::vector<std::pair<std::string, std::string>>{{"f_iso", "100"},
                                                                  {"lengthrange", "[0.1, 0.2]"}}
               : std::vector<std::pair<std::string, std::string>>{{"f_iso", "100"},
                                                                  {"optimal_fiber_length", "0.1"}};
  };
  const auto error = [](const std::string& text) {
    try {
      ParseModelSpec("model.yaml", text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(read)");
  };
  for (const ModelFamily& family : ModelFamilies()) {
    if (std::string_view(family.type) == "paper") continue;  // nested: paper_model_fields_test
    for (const NumberField<ModelParams>& field : family.fields) {
      if (field.values != FieldValues::kRange) continue;
      SCOPED_TRACE(std::string(family.type) + " " + field.key);
      // a number of a list (MuJoCo's "range[1]") in its list, the others their defaults
      const std::optional<ListElement> element = ElementOf(field.key);
      const auto text = [&](double value) {
        auto fields = required(family);
        std::string key = field.key;
        std::string given_value = FormatNumber(value);
        if (element) {
          key = std::string(element->list);
          std::string list = "[";
          for (const NumberField<ModelParams>& f : family.fields) {
            const std::optional<ListElement> e = ElementOf(f.key);
            if (!e || e->list != element->list) continue;
            const double v = &f == &field ? value : f.default_value.value_or(0.1 * (e->index + 1));
            list += (list.size() > 1 ? ", " : "") + FormatNumber(v);
          }
          given_value = list + "]";
        }
        bool replaced = false;
        for (auto& [k, given] : fields) {
          if (k == key) given = given_value, replaced = true;
        }
        if (!replaced) fields.emplace_back(key, given_value);
        std::string block = std::string("{family: ") + family.type;
        for (const auto& [k, given] : fields) block += ", " + k + ": " + given;
        return block + "}";
      };
      const double below = field.range.min_exclusive ? field.range.min : field.range.min - 1.0;
      for (const double bad : {field.range.max * 2.0, below}) {
        const std::string message = error(text(bad));
        EXPECT_THAT(message, HasSubstr("model." + std::string(field.key) + " = "));
        EXPECT_THAT(message, HasSubstr(field.range.Rule()));
      }
      // a list's number at its bound may break the order of the list, not the bound
      if (element) {
        EXPECT_THAT(error(text(field.range.max)), Not(HasSubstr(field.range.Rule())));
      } else {
        EXPECT_EQ(error(text(field.range.max)), "(read)");
      }
    }
  }
}

}  // namespace
}  // namespace musclesim
