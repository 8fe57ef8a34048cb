// A spatial network's shape at chosen times: a strip of frames on common x-y axes.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "plot/plot_text.h"
#include "plot/spatial_columns.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

constexpr int kFramesPerRow = 4;
constexpr std::size_t kMostKeyedElements = 12;  // beyond, a key would hide the frame

// The row whose time is nearest `t` (the earlier of two as near).
std::size_t NearestRow(const std::vector<double>& row_times, double t) {
  std::size_t best = 0;
  for (std::size_t r = 1; r < row_times.size(); ++r) {
    if (std::abs(row_times[r] - t) < std::abs(row_times[best] - t)) best = r;
  }
  return best;
}

// A frame's points: the nodes at its row, then each element's path.
struct FramePoints {
  std::vector<std::pair<double, double>> nodes;
  std::vector<std::vector<std::pair<double, double>>> paths;
};

FramePoints PointsAt(const CsvTable& table, std::size_t row, const SpatialColumns& columns,
                     const std::vector<ElementPath>& paths) {
  FramePoints f;
  for (const SpatialNode& node : columns.nodes) {
    f.nodes.emplace_back(FiniteValue(table, row, node.x), FiniteValue(table, row, node.y));
  }
  for (const ElementPath& path : paths) {
    std::vector<std::pair<double, double>> points;
    for (const PathPoint& p : path.points) {
      points.push_back(p.node < 0 ? std::make_pair(p.x, p.y)
                                  : f.nodes[static_cast<std::size_t>(p.node)]);
    }
    f.paths.push_back(std::move(points));
  }
  return f;
}

// Elements drawn as one curve, under one key entry.
struct Group {
  std::string label;
  std::vector<std::size_t> elements;  // indices into the scenario's elements (paths)
};

std::vector<Group> OnePerElement(const std::vector<ElementPath>& paths) {
  std::vector<Group> groups;
  for (std::size_t e = 0; e < paths.size(); ++e) groups.push_back({paths[e].name, {e}});
  return groups;
}

// A group per kind of element the scenario holds, in the order of their first element,
// labelled by the kind and how many there are ("springs (1984)").
std::vector<Group> GroupsByKind(const Scenario& scenario) {
  std::vector<Group> groups;
  std::vector<ElementKind> kinds;
  for (std::size_t e = 0; e < scenario.elements.size(); ++e) {
    const ElementKind kind = scenario.elements[e].kind;
    const auto at = std::find(kinds.begin(), kinds.end(), kind);
    if (at == kinds.end()) {
      kinds.push_back(kind);
      groups.push_back({std::string(ToString(kind)), {e}});
    } else {
      groups[static_cast<std::size_t>(at - kinds.begin())].elements.push_back(e);
    }
  }
  for (Group& group : groups) {
    group.label += "s (" + std::to_string(group.elements.size()) + ")";
  }
  return groups;
}

// "[lo:hi]" around `values`, padded by `pad` on each side.
std::string Range(double lo, double hi, double pad) {
  std::string range = "[";
  range.append(Number(lo - pad)).append(":").append(Number(hi + pad)).append("]");
  return range;
}

// A tick step of 1, 2 or 5 times a power of ten giving about four ticks over `span`: narrow
// frames side by side have no room for gnuplot's own choice.
double TickStep(double span) {
  const double rough = span / 4.0;
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= rough) return m * decade;
  }
  return 10.0 * decade;
}

}  // namespace

std::vector<double> EvenlySpacedFrameTimes(const CsvTable& table, int count) {
  if (count < 1 || count > kMaxFrames) {
    throw ParameterError("frame-count", std::to_string(count),
                         std::string("must be 1 to ").append(std::to_string(kMaxFrames)));
  }
  table.Require({"t"}, "a spatial network's trajectory CSV of musclesim run");
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  const int t = table.Find("t");
  const double first = FiniteValue(table, 0, t);
  const double last = FiniteValue(table, table.rows.size() - 1, t);
  std::vector<double> times = {first};
  for (int k = 1; k < count; ++k) {
    times.push_back(k + 1 == count ? last : first + (last - first) * k / (count - 1));
  }
  return times;
}

// The row nearest each of `times`, which must lie within the table's; `row_times` gets every
// row's t.
std::vector<std::size_t> FrameRows(const CsvTable& table, const std::vector<double>& times,
                                   std::vector<double>& row_times) {
  const int t_column = table.Find("t");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    row_times.push_back(FiniteValue(table, r, t_column));
  }
  const double first = row_times.front(), last = row_times.back();
  std::vector<std::size_t> rows;
  for (double t : times) {
    if (!std::isfinite(t) || t < first || t > last) {
      throw ParameterError("frames", Number(t),
                           "outside the run's times: " + table.source +
                               " holds t = " + Number(first) + " to " + Number(last) + " s");
    }
    rows.push_back(NearestRow(row_times, t));
  }
  return rows;
}

std::string SpatialFramesPlotScript(const CsvTable& table, const std::vector<double>& times,
                                    const Scenario* scenario, const PlotOptions& options) {
  const SpatialColumns columns = RequireSpatialTrajectory(table);
  if (times.empty() || times.size() > static_cast<std::size_t>(kMaxFrames)) {
    throw ParameterError(
        "frames", std::to_string(times.size()) + " times",
        std::string("give 1 to ").append(std::to_string(kMaxFrames)).append(" times"));
  }
  const std::vector<ElementPath> paths =
      scenario ? ElementPaths(*scenario, columns, table.source) : std::vector<ElementPath>{};
  std::vector<double> row_times;
  const std::vector<std::size_t> rows = FrameRows(table, times, row_times);

  std::ostringstream s;
  s << kFrame;
  // every frame's block: index 0 the nodes, index 1 + k element k's path
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  const auto extend = [&](const std::pair<double, double>& p) {
    x_lo = std::min(x_lo, p.first);
    x_hi = std::max(x_hi, p.first);
    y_lo = std::min(y_lo, p.second);
    y_hi = std::max(y_hi, p.second);
  };
  // beyond kMostKeyedElements the elements are drawn by kind, a curve per kind whose pieces
  // (one blank line apart) are its elements: a curve per element costs gnuplot a scan of the
  // block to its data set, which for thousands of elements took minutes
  const std::vector<Group> groups =
      paths.size() > kMostKeyedElements ? GroupsByKind(*scenario) : OnePerElement(paths);
  for (std::size_t f = 0; f < rows.size(); ++f) {
    const FramePoints points = PointsAt(table, rows[f], columns, paths);
    s << "$frame" << f << " << EOD\n";
    for (const auto& p : points.nodes) {
      extend(p);
      s << Number(p.first) << " " << Number(p.second) << "\n";
    }
    for (const Group& group : groups) {
      s << "\n";
      for (std::size_t e : group.elements) {
        s << "\n";
        for (const auto& p : points.paths[e]) {
          extend(p);
          s << Number(p.first) << " " << Number(p.second) << "\n";
        }
      }
    }
    s << "EOD\n";
  }
  // common axes, a margin of 5% of the wider span (1 cm when every point coincides)
  const double span = std::max(x_hi - x_lo, y_hi - y_lo);
  const double pad = span > 0.0 ? 0.05 * span : 0.01;
  const int per_row = std::min(kFramesPerRow, static_cast<int>(rows.size()));
  const int row_count = (static_cast<int>(rows.size()) + per_row - 1) / per_row;
  s << "set multiplot layout " << row_count << "," << per_row << " title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set size ratio -1\nset xrange " << Range(x_lo, x_hi, pad) << "\nset yrange "
    << Range(y_lo, y_hi, pad) << "\nset xtics " << Number(TickStep(x_hi - x_lo + 2 * pad))
    << "\nset ytics " << Number(TickStep(y_hi - y_lo + 2 * pad)) << "\n"
    << (columns.dimensions == 3 ? "set xlabel 'x [m] (x-y projection)'\n" : "set xlabel 'x [m]'\n")
    << "set ylabel 'y [m]'\n"
    << "set key inside top right opaque box\n";
  // the nodes' points shrink as they crowd: 1.2 up to 100 nodes, as 1 / sqrt(n) beyond
  const double nodes = static_cast<double>(columns.nodes.size());
  const double point_size = nodes <= 100.0 ? 1.2 : std::max(0.2, 12.0 / std::sqrt(nodes));
  for (std::size_t f = 0; f < rows.size(); ++f) {
    s << "set title 't = " << Number(row_times[rows[f]]) << " s'\nplot ";
    for (std::size_t k = 0; k < groups.size(); ++k) {
      s << "$frame" << f << " index " << k + 1 << " using 1:2 with lines lw "
        << (groups[k].elements.size() > 1 ? 1 : 2) << " lc " << k % 8 + 1
        << (f == 0 ? std::string(" title ").append(
                         GnuplotString(groups[k].label, scenario->source + ": an element's name"))
                   : std::string(" notitle"))
        << ", \\\n  ";
    }
    s << "$frame" << f << " index 0 using 1:2 with points pt 7 ps " << Number(point_size)
      << " lc rgb '#000000' " << (f == 0 ? "title 'nodes'\nset key off" : "notitle") << "\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

std::string FramesPlotScript(const CsvTable& table, const std::vector<double>& times, int count,
                             const Scenario* scenario, const std::string& flag,
                             const PlotOptions& options) {
  if (!IsSpatialTrajectory(table)) {
    throw InputError(flag + ": " + table.source +
                     " is not the run of a network in the plane or in space (frames need "
                     "NODE.x and NODE.y columns, written by a run with dimensions: 2 or 3)");
  }
  return SpatialFramesPlotScript(
      table, times.empty() ? EvenlySpacedFrameTimes(table, count) : times, scenario, options);
}

}  // namespace musclesim
