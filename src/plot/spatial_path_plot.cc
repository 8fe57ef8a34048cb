// A spatial network's run: its nodes' paths in the x-y plane beside its elements' panels.
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "plot/plot_text.h"
#include "plot/spatial_columns.h"
#include "plot/time_panels.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

constexpr std::size_t kMostKeyedNodes = 20;  // beyond, a key would hide the plane
constexpr double kTop = 0.94;                // [-] of the figure's height below the title

// The plane's axis labels: a 3-D run is seen from +z.
const char* PlaneLabels(int dimensions) {
  return dimensions == 3 ? "set xlabel 'x [m] (x-y projection)'\nset ylabel 'y [m]'\n"
                         : "set xlabel 'x [m]'\nset ylabel 'y [m]'\n";
}

// The nodes' paths as one block of (x, y) rows, a data set per node (two blank lines apart):
// beyond kMostKeyedNodes, one curve of them all rather than a titled curve per node, each of
// which would cost gnuplot a pass over every column of a wide block.
void WritePathsBlock(const CsvTable& table, const SpatialColumns& columns, std::ostringstream& s) {
  s << "$plane << EOD\n";
  for (std::size_t i = 0; i < columns.nodes.size(); ++i) {
    if (i > 0) s << "\n\n";
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      s << Number(FiniteValue(table, r, columns.nodes[i].x)) << " "
        << Number(FiniteValue(table, r, columns.nodes[i].y)) << "\n";
    }
  }
  s << "EOD\n";
}

}  // namespace

bool IsSpatialTrajectory(const CsvTable& table) { return !FindSpatialColumns(table).nodes.empty(); }

std::string SpatialPathPlotScript(const CsvTable& table, const PlotOptions& options) {
  const SpatialColumns columns = RequireSpatialTrajectory(table);
  // the plane: t, then x and y of every node
  std::vector<int> plane = {table.Find("t")};
  for (const SpatialNode& node : columns.nodes) {
    plane.push_back(node.x);
    plane.push_back(node.y);
  }
  TimePanels lines(table);
  std::vector<Panel> panels = {
      {"length [m]", {}, ""}, {"tension [N]", {}, ""}, {"activation [-]", {}, ""}};
  lines.AddKind(panels[0], ".length", "", false);
  lines.AddKind(panels[1], ".tension", "", false);
  lines.AddKind(panels[2], ".activation", "", false);
  lines.AddKind(panels[2], ".excitation", " excitation", true);
  std::erase_if(panels, [](const Panel& p) { return p.lines.empty(); });

  std::ostringstream s;
  s << kFrame;
  const bool keyed = columns.nodes.size() <= kMostKeyedNodes;
  if (keyed) {
    WriteDataBlock(table, plane, "$plane", s);
  } else {
    WritePathsBlock(table, columns, s);
  }
  if (!panels.empty()) {
    WriteDataBlock(table, lines.data(), "$network", s);
    WriteGroupedBlocks(table, lines.data(), panels, "$network", s);
  }
  const double plane_width = panels.empty() ? 1.0 : 0.5;
  s << "set multiplot title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set origin 0,0\nset size ratio -1 " << Number(plane_width) << "," << Number(kTop) << "\n"
    << PlaneLabels(columns.dimensions)
    << (keyed ? "set key outside bottom center horizontal\n" : "set key off\n");
  if (!keyed) {
    // one curve of a piece per node, each its own colour
    s << "plot $plane using 1:2:(column(-2) + 1) with lines lw 1 lc variable notitle";
  } else {
    s << "plot ";
  }
  for (std::size_t i = 0; keyed && i < columns.nodes.size(); ++i) {
    const SpatialNode& node = columns.nodes[i];
    s << (i ? ", \\\n  " : "") << "$plane using " << 2 * i + 2 << ":" << 2 * i + 3
      << " with lines lw 2 title "
      << GnuplotString(node.name,
                       "column " + Printable(table.header[static_cast<std::size_t>(node.x)]));
  }
  s << "\n";
  if (!panels.empty()) {
    // the elements' panels in a column on the right, sharing the time axis
    const double height = kTop / static_cast<double>(panels.size());
    s << "set size noratio\nset lmargin 12\nset rmargin 26\nset key on\n"
      << "set key outside right top\nset format x ''\nunset xlabel\n";
    WritePanels(panels, "$network", s, [&](std::size_t p) {
      s << "set origin 0.5," << Number(kTop - height * static_cast<double>(p + 1))
        << "\nset size 0.5," << Number(height) << "\n";
    });
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace musclesim
