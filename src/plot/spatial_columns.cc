#include "plot/spatial_columns.h"

#include <map>
#include <string_view>
#include <unordered_map>

#include "musclesim/core/errors.h"
#include "plot/plot_text.h"
#include "plot/time_panels.h"

namespace musclesim::plot_text {

SpatialColumns FindSpatialColumns(const CsvTable& table) {
  SpatialColumns columns;
  // the header's columns by name, once: a lattice's CSV has tens of thousands
  std::unordered_map<std::string_view, int> index;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    index.emplace(table.header[c], static_cast<int>(c));
  }
  const auto find = [&](const std::string& name) {
    const auto found = index.find(name);
    return found == index.end() ? -1 : found->second;
  };
  int with_z = 0;
  for (int x : ColumnsEndingIn(table, ".x")) {
    const std::string& header = table.header[static_cast<std::size_t>(x)];
    const std::string name = header.substr(0, header.size() - 2);
    const int y = find(name + ".y");
    if (y < 0) {
      // NODE.x is written only by a run in the plane or in space, always with NODE.y
      throw InputError(table.source + ": column " + Printable(header) + " has no " +
                       Printable(name) +
                       ".y beside it: a run in the plane or in space writes "
                       "both for every node (NODE.x, NODE.y, and NODE.z in space)");
    }
    const int z = find(name + ".z");
    with_z += z >= 0 ? 1 : 0;
    columns.nodes.push_back({name, x, y, z});
  }
  if (columns.nodes.empty()) return columns;
  const int count = static_cast<int>(columns.nodes.size());
  if (with_z != 0 && with_z != count) {
    throw InputError(table.source + ": " + std::to_string(with_z) + " of its " +
                     std::to_string(count) +
                     " nodes have a NODE.z column: a run in space has one for every node, a "
                     "run in the plane for none");
  }
  columns.dimensions = with_z == 0 ? 2 : 3;
  return columns;
}

std::vector<ElementPath> ElementPaths(const Scenario& scenario, const SpatialColumns& columns,
                                      const std::string& csv) {
  const std::string mismatch = scenario.source + " does not match " + csv + ": ";
  if (scenario.space.dimensions != columns.dimensions) {
    throw InputError(
        mismatch + "the scenario has dimensions: " + std::to_string(scenario.space.dimensions) +
        ", the CSV node columns of " + std::to_string(columns.dimensions) + " (NODE.x, NODE.y" +
        (columns.dimensions == 3 ? ", NODE.z)" : ")") + "; plot a run with the scenario it ran");
  }
  std::map<std::string, int> index;  // node name -> its place in columns.nodes
  for (std::size_t i = 0; i < columns.nodes.size(); ++i) {
    index[columns.nodes[i].name] = static_cast<int>(i);
  }
  for (std::size_t i = 0; i < scenario.nodes.size(); ++i) {
    const std::string& name = scenario.nodes[i].name;
    if (index.count(name) == 0) {
      std::string message = mismatch;
      message.append("nodes[").append(std::to_string(i)).append("] '").append(Printable(name));
      message.append("' has no columns ").append(Printable(name)).append(".x, ");
      message.append(Printable(name)).append(".y in the CSV");
      throw InputError(message);
    }
  }
  if (scenario.nodes.size() != columns.nodes.size()) {
    for (const SpatialNode& node : columns.nodes) {
      bool known = false;
      for (const Node& n : scenario.nodes) known = known || n.name == node.name;
      if (!known) {
        throw InputError(mismatch + "the CSV has columns " + Printable(node.name) + ".x, " +
                         Printable(node.name) + ".y of a node the scenario does not have");
      }
    }
  }
  std::vector<ElementPath> paths;
  for (const Element& element : scenario.elements) {
    ElementPath path{element.name, {{index.at(element.from), 0.0, 0.0}}};
    for (const ViaPoint& via : element.via) {
      if (via.node.empty()) {
        path.points.push_back({-1, via.position[0], via.position[1]});
      } else {
        path.points.push_back({index.at(via.node), 0.0, 0.0});
      }
    }
    path.points.push_back({index.at(element.to), 0.0, 0.0});
    paths.push_back(std::move(path));
  }
  return paths;
}

SpatialColumns RequireSpatialTrajectory(const CsvTable& table) {
  table.Require({"t"}, "a spatial network's trajectory CSV of musclesim run");
  SpatialColumns columns = FindSpatialColumns(table);
  if (columns.nodes.empty()) {
    throw InputError(table.source +
                     ": a spatial network's trajectory CSV of musclesim run needs NODE.x and "
                     "NODE.y columns; found none");
  }
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  return columns;
}

}  // namespace musclesim::plot_text
