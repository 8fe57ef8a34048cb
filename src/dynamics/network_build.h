// Private: building a network's model (network_build.cc): its parts validated and resolved
// into ends, links, free nodes and kinks, and its Jacobian's pattern and slots found. The
// steps of the other concerns (junctions, control, space) are in their own headers.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "musclesim/dynamics/network_model.h"

namespace musclesim::network {

// Validates the parts, indexes them by name, resolves them and builds the Jacobian's pattern
// and slots (ParameterError with the parts' paths, network.h).
void Build(NetworkModel& m);

// A part's index by name, -1 if none.
int FindNode(const NetworkModel& m, std::string_view name);
int FindElement(const NetworkModel& m, std::string_view name);
int FindController(const NetworkModel& m, std::string_view name);
// A node's index by name (ParameterError at `path` if none).
int NodeNamed(const NetworkModel& m, const std::string& name, const std::string& path);

// Build's steps: the nodes' ends, their states numbered (returns how many); element e's link
// and kinks, an excitation's state numbered from `states`; the loads of each node; the free
// nodes, each required `anchored` to a fixed or prescribed node; the single free node's
// shortcut (Anchored).
void Resolve(NetworkModel& m);
int NumberEnds(NetworkModel& m);
void AddLink(NetworkModel& m, std::size_t e, int& states);
std::vector<std::vector<Load>> LoadsByNode(const NetworkModel& m);
void AddFreeNodes(NetworkModel& m, std::vector<std::vector<Load>> node_loads,
                  const std::vector<bool>& anchored);
void FindSingleNode(NetworkModel& m);
void BuildPattern(NetworkModel& m);
// BuildPattern's steps on a line: the links' pattern entries (their ends' acceleration rows,
// by their positions, velocities and activation), and their slots.
void AddLinePattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
void FindLineSlots(NetworkModel& m, const std::function<int(int, int)>& slot);

}  // namespace musclesim::network
