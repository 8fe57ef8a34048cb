#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "plot/plot_text.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

// The columns whose name ends in `.suffix`, in the CSV's order.
std::vector<int> ColumnsEndingIn(const CsvTable& table, const std::string& suffix) {
  std::vector<int> columns;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const std::string& name = table.header[c];
    if (name.size() > suffix.size() && EndsWith(name, suffix))
      columns.push_back(static_cast<int>(c));
  }
  return columns;
}

// One line of a panel: an inline data column (gnuplot counts from 1), its legend and the CSV
// column it came from (for messages).
struct Line {
  int column;
  std::string label;
  std::string source;
  bool dashed;  // thin and dashed: the excitations, the references
};

struct Panel {
  std::string ylabel;
  std::vector<Line> lines;
  std::string ylabel_source;  // the CSV column a ylabel made from a name came from ("": none)
};

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
  std::vector<int> data = {table.Find("t")};  // the inline data's columns, time first
  // adds a CSV column to the inline data as a line of `panel`
  const auto add = [&](Panel& panel, int column, const std::string& label, bool dashed) {
    data.push_back(column);
    panel.lines.push_back({static_cast<int>(data.size()), label,
                           table.header[static_cast<std::size_t>(column)], dashed});
  };
  // a line per column ending in `suffix`, labelled by its part's name and `label_end`
  const auto add_kind = [&](Panel& panel, const std::string& suffix, const std::string& label_end,
                            bool dashed) {
    for (int column : ColumnsEndingIn(table, suffix)) {
      const std::string& name = table.header[static_cast<std::size_t>(column)];
      add(panel, column, name.substr(0, name.size() - suffix.size()) + label_end, dashed);
    }
  };
  std::vector<Panel> panels = {{"position [m]", {}, ""},
                               {"length [m]", {}, ""},
                               {"tension [N]", {}, ""},
                               {"activation [-]", {}, ""}};
  add_kind(panels[0], ".position", "", false);
  add_kind(panels[1], ".length", "", false);
  add_kind(panels[2], ".tension", "", false);
  add_kind(panels[3], ".activation", "", false);
  add_kind(panels[3], ".excitation", " excitation", true);
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
    add(panel, table.Find(name + ".measured"), name + " measured", false);
    add(panel, table.Find(name + ".reference"), name + " reference", true);
    panels.push_back(std::move(panel));
    add(errors, table.Find(name + ".error"), name, false);
  }
  panels.push_back(std::move(errors));
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  std::erase_if(panels, [](const Panel& p) { return p.lines.empty(); });

  std::ostringstream s;
  s << kFrame << "$network << EOD\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < data.size(); ++c) {
      s << (c ? " " : "") << Number(FiniteValue(table, r, data[c]));
    }
    s << "\n";
  }
  s << "EOD\n";
  s << "set multiplot layout " << panels.size() << ",1 title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set lmargin 12\nset rmargin 26\nset key outside right top\nset format x ''\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Panel& panel = panels[p];
    if (p + 1 == panels.size()) s << "set format x '%g'\nset xlabel 'time [s]'\n";
    s << "set ylabel " << GnuplotString(panel.ylabel, "column " + Printable(panel.ylabel_source))
      << "\nplot ";
    for (std::size_t i = 0; i < panel.lines.size(); ++i) {
      const Line& line = panel.lines[i];
      s << (i ? ", \\\n  " : "") << "$network using 1:" << line.column
        << (line.dashed ? " with lines lw 1 dt 2 title " : " with lines lw 2 title ")
        << GnuplotString(line.label, "column " + Printable(line.source));
    }
    s << "\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace musclesim
