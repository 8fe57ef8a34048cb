// Where a spatial network's run CSV keeps its nodes' coordinates (NODE.x, NODE.y and in
// space NODE.z: scenario/run_columns.h), and how a scenario's nodes and element paths map
// onto them (private to the plot layer).
#pragma once

#include <string>
#include <vector>

#include "musclesim/io/readers/csv_table.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim::plot_text {

struct SpatialNode {
  std::string name;
  int x = -1, y = -1, z = -1;  // CSV column indices; z -1 in the plane
};

struct SpatialColumns {
  int dimensions = 0;              // 2 or 3; 0: not a spatial run
  std::vector<SpatialNode> nodes;  // every NODE with NODE.x and NODE.y, in the CSV's order
};

// The nodes of `table`: a NODE.x column with NODE.y beside it; in space when they all have
// NODE.z. Throws InputError when only some have NODE.z, or a NODE.x has no NODE.y.
SpatialColumns FindSpatialColumns(const CsvTable& table);
// FindSpatialColumns of a trajectory to plot: InputError without a `t` column, without a
// node's NODE.x and NODE.y, or without rows.
SpatialColumns RequireSpatialTrajectory(const CsvTable& table);

// A point of an element's path: a node (index into SpatialColumns::nodes) or fixed (x, y).
struct PathPoint {
  int node = -1;  // -1: the fixed point (x, y)
  double x = 0.0, y = 0.0;
};

struct ElementPath {
  std::string name;
  std::vector<PathPoint> points;  // from, the via points in order, to
};

// The paths of `scenario`'s elements in terms of `columns`' nodes. Throws InputError naming
// the scenario's file and the CSV's unless both have the same dimensions and the same nodes.
std::vector<ElementPath> ElementPaths(const Scenario& scenario, const SpatialColumns& columns,
                                      const std::string& csv);

}  // namespace musclesim::plot_text
