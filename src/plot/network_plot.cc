#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "plot/plot_text.h"
#include "plot/time_panels.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

// The controllers of the CSV: every prefix P with P.reference, P.measured and P.error columns
// (scenario/run_columns.h), in the CSV's order.
std::vector<std::string> ControllerNames(const CsvTable& table) {
  std::vector<std::string> names;
  for (int column : ColumnsEndingIn(table, ".reference")) {
    const std::string& name = table.header[static_cast<std::size_t>(column)];
    const std::string prefix = name.substr(0, name.size() - std::string(".reference").size());
    if (table.Find(prefix + ".measured") >= 0 && table.Find(prefix + ".error") >= 0) {
      names.push_back(prefix);
    }
  }
  return names;
}

}  // namespace

bool IsNetworkTrajectory(const CsvTable& table) {
  return !ColumnsEndingIn(table, ".position").empty();
}

std::string NetworkPlotScript(const CsvTable& table, const PlotOptions& options) {
  table.Require({"t"}, "a network trajectory CSV of musclesim run");
  TimePanels lines(table);  // the inline data's columns, time first
  std::vector<Panel> panels = {{"position [m]", {}, ""},
                               {"length [m]", {}, ""},
                               {"tension [N]", {}, ""},
                               {"activation [-]", {}, ""}};
  lines.AddKind(panels[0], ".position", "", false);
  lines.AddKind(panels[1], ".length", "", false);
  lines.AddKind(panels[2], ".tension", "", false);
  lines.AddKind(panels[3], ".activation", "", false);
  lines.AddKind(panels[3], ".excitation", " excitation", true);
  if (panels[0].lines.empty()) {
    throw InputError(table.source +
                     ": a network trajectory CSV of musclesim run needs "
                     "<node>.position columns; found none");
  }
  // a controller's panel: what it measures against its reference (in the measured unit),
  // then one panel of every controller's error
  const std::vector<std::string> controllers = ControllerNames(table);
  Panel errors{"control error", {}, ""};  // reference - measured
  for (const std::string& name : controllers) {
    Panel panel{name, {}, name + ".reference"};
    lines.Add(panel, table.Find(name + ".measured"), name + " measured", false);
    lines.Add(panel, table.Find(name + ".reference"), name + " reference", true);
    panels.push_back(std::move(panel));
    lines.Add(errors, table.Find(name + ".error"), name, false);
  }
  panels.push_back(std::move(errors));
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  std::erase_if(panels, [](const Panel& p) { return p.lines.empty(); });

  std::ostringstream s;
  s << kFrame;
  WriteDataBlock(table, lines.data(), "$network", s);
  WriteGroupedBlocks(table, lines.data(), panels, "$network", s);
  s << "set multiplot layout " << panels.size() << ",1 title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set lmargin 12\nset rmargin 26\nset key outside right top\nset format x ''\n";
  WritePanels(panels, "$network", s);
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace musclesim
