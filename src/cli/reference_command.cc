// musclesim reference PART: prints the reference table of a described part (core/part_fields.h)
// as Markdown, the tables docs/guide/ holds (tests/io/reference_table_test.cc checks them).
#include <iostream>
#include <string>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/dynamics/actuator_signals.h"
#include "musclesim/dynamics/actuator_fields.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/node_kinds.h"
#include "musclesim/dynamics/waveform_shapes.h"
#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/io/readers/identify_spec.h"
#include "musclesim/io/writers/reference_table.h"
#include "musclesim/model/family_fields.h"
#include "musclesim/model/fit_fields.h"
#include "musclesim/optimize/problem_fields.h"
#include "musclesim/scenario/setting_fields.h"
#include "musclesim/solver/solver_fields.h"
#include "musclesim/sweep/sweep_file.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim reference PART

Prints, as a Markdown table, every key of PART with its unit, default, accepted values and
their reason, and its meaning: what the readers, --set and the parameter handles apply.
PART is one of
  actuator  the single actuator's `actuator:` block
  nodes     a network's nodes: fixed, prescribed and free
  elements  the laws of springs, tendons and dampers (a network's elements), and an
            actuator's activation or excitation
  loads     the spring and mass loads (a force load is a waveform)
  waveforms the shapes of a signal over time (activations, excitations, force loads,
            prescribed motions, references)
  gains     a controller's gains
  controllers
            a controller's names, signals (reference, feedforward, co_contraction.level) and
            gains
  models    the model blocks of the curve families (paper, degroote2016, mujoco)
  fit       the paper's active_length.fit block: its Gaussians fitted at load
  activation_dynamics
            the families of activation dynamics (their `family:` in place of `type:`)
  time      the `time:` span
  solver    the `solver:` block: CVODES' tolerances, step guards, method and linear solver
  output    the `output:` block: the rows' interval (a time or `steps`), phase tolerance and file
  sweep     the keys of a sweep file (`musclesim sweep`)
  problem   the keys of an optimal control problem (`musclesim optimize`): the file's, its
            lists' entries and its blocks
  identify  the blocks of `musclesim identify`'s data file: passive, active and velocity
  identify_series
            the keys of its data file on time series: the file's, a series' and a
            parameter's
)";

}  // namespace

int ReferenceCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return 0;
  }
  if (args.positional.size() != 1) throw UsageError("expected one part (see --help)");
  const std::string& part = args.positional[0];
  if (part == "actuator") {
    std::cout << ReferenceTable(ActuatorBlock(), "block");
  } else if (part == "nodes") {
    std::cout << ReferenceTable(NodeKinds(), "node", NameRows(NodeNames()),
                                SignalCells(NodeSignals()));
  } else if (part == "elements") {
    std::cout << ReferenceTable(ElementLaws(), "type", NameRows(ElementNames()))
              << SignalRows(ActuatorSignals<Element>(), "`actuator`");
  } else if (part == "loads") {
    std::cout << ReferenceTable(LoadVariants(), "type", NameRows(LoadNames()));
  } else if (part == "waveforms") {
    std::cout << ReferenceTable(WaveformShapes());
  } else if (part == "gains") {
    std::cout << ReferenceTable(ControllerGains());
  } else if (part == "controllers") {
    std::cout << ReferenceTable(
        ControllerTypes(), "type",
        NameRows(ControllerNames()) + SignalRows(ControllerSignals(), "every"));
  } else if (part == "models") {
    std::cout << ReferenceTable(ModelFamilies(), "family");
  } else if (part == "fit") {
    std::cout << ReferenceTable(FitBlock(), "block");
  } else if (part == "activation_dynamics") {
    std::cout << ReferenceTable(ActivationFamilies(), "family");
  } else if (part == "time") {
    std::cout << ReferenceTable(TimeBlock(), "block");
  } else if (part == "output") {
    std::cout << ReferenceTable(OutputBlock(), "block");
  } else if (part == "solver") {
    std::cout << ReferenceTable(SolverBlock(), "block");
  } else if (part == "problem") {
    std::cout << ProblemReference();
  } else if (part == "sweep") {
    std::cout << ReferenceTable(SweepFileBlock(), "block");
  } else if (part == "identify_series") {
    std::cout << ReferenceHeader("entry") + ReferenceRows(IdentifySeriesFile()) +
                     ReferenceRows(SeriesEntry()) + ReferenceRows(SeriesParameterEntry());
  } else if (part == "identify") {
    std::cout << ReferenceTable(IdentifyDataBlocks(), "block");
  } else {
    throw UsageError(
        "unknown part '" + part +
        "': actuator, nodes, elements, loads, waveforms, gains, controllers, models, fit, "
        "activation_dynamics, time, solver, output, sweep, problem, identify or "
        "identify_series (see --help)");
  }
  return 0;
}

}  // namespace musclesim::cli
