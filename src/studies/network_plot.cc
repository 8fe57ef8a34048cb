#include <sstream>
#include <string>
#include <vector>

#include "musclesim/errors.h"
#include "musclesim/studies/plot.h"
#include "plot_text.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

// The columns whose name ends in `.suffix`, in the CSV's order.
std::vector<int> ColumnsEndingIn(const CsvTable& table, const std::string& suffix) {
  std::vector<int> columns;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const std::string& name = table.header[c];
    if (name.size() > suffix.size() && EndsWith(name, suffix)) columns.push_back(static_cast<int>(c));
  }
  return columns;
}

struct Panel {
  std::string ylabel;
  std::string suffix;
  std::vector<int> columns;
  std::string dashed_suffix;  // drawn dashed in the same panel ("" none): the excitations
  std::vector<int> dashed;
};

}  // namespace

bool IsNetworkTrajectory(const CsvTable& table) {
  return !ColumnsEndingIn(table, ".position").empty();
}

std::string NetworkPlotScript(const CsvTable& table, const PlotOptions& options) {
  table.Require({"t"}, "a network trajectory CSV of musclesim run");
  std::vector<Panel> panels = {{"position [m]", ".position", {}, "", {}},
                               {"length [m]", ".length", {}, "", {}},
                               {"tension [N]", ".tension", {}, "", {}},
                               {"activation [-]", ".activation", {}, ".excitation", {}}};
  std::vector<int> data = {table.Find("t")};  // the inline data's columns, time first
  for (Panel& panel : panels) {
    for (int column : ColumnsEndingIn(table, panel.suffix)) {
      data.push_back(column);
      panel.columns.push_back(static_cast<int>(data.size()));  // gnuplot counts from 1
    }
    if (panel.dashed_suffix.empty()) continue;
    for (int column : ColumnsEndingIn(table, panel.dashed_suffix)) {
      data.push_back(column);
      panel.dashed.push_back(static_cast<int>(data.size()));
    }
  }
  if (panels[0].columns.empty()) {
    throw InputError(table.source + ": a network trajectory CSV of musclesim run needs "
                     "<node>.position columns; found none");
  }
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  std::erase_if(panels, [](const Panel& p) { return p.columns.empty(); });

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
    s << "set ylabel '" << panel.ylabel << "'\nplot ";
    for (std::size_t i = 0; i < panel.columns.size(); ++i) {
      const int column = panel.columns[i];
      const std::string& name = table.header[static_cast<std::size_t>(data[column - 1])];
      const std::string label = name.substr(0, name.size() - panel.suffix.size());
      s << (i ? ", \\\n  " : "") << "$network using 1:" << column << " with lines lw 2 title "
        << GnuplotString(label, "column " + Printable(name));
    }
    for (const int column : panel.dashed) {
      const std::string& name = table.header[static_cast<std::size_t>(data[column - 1])];
      const std::string label = name.substr(0, name.size() - panel.dashed_suffix.size());
      s << ", \\\n  $network using 1:" << column << " with lines lw 1 dt 2 title "
        << GnuplotString(label + " excitation", "column " + Printable(name));
    }
    s << "\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace musclesim
