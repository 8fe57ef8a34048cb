// A network's model (docs/model.md 7, 12): its parts as given and what building them resolved,
// the ends, links, free nodes, junctions, controllers' loops, kinks and the Jacobian's pattern
// and slots. Plain data, as Pinocchio's Model: built and validated once (network_build.cc),
// never changed by an evaluation, shared by every thread that integrates it. The algorithms
// over it are free functions grouped by concern (src/dynamics/network_*.h: evaluation on a
// line, junctions, control, the plane and space, sensitivities, diagnosis); what they write
// besides their results is in a NetworkScratch their caller owns. NetworkSystem (network.h)
// is its public face.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/jacobian_pattern.h"
#include "musclesim/dynamics/network_parts.h"
#include "musclesim/dynamics/skeleton.h"

namespace musclesim::network {

// A node as the right-hand side sees it.
struct End {
  NodeKind kind;
  int state;            // free: index of x in y; else -1
  double position;      // fixed
  int node;             // index in nodes (prescribed: its motion; an index, so copies work)
  Coordinates point{};  // fixed, in 2 or 3 dimensions
  int rate = -1;        // free with a mass: index of xdot in y; else -1
  int free = -1;        // free: index in free_nodes; else -1
  int junction = -1;    // massless junction: index in junctions; else -1
  int body = -1;        // on a body: index in the skeleton's bodies; else -1
};

// An element as the right-hand side sees it: its ends and where its Jacobian goes.
struct Link {
  int from, to;  // node indices
  // entry of (row: accel from/to, column: x_from, v_from, x_to, v_to); -1 if none
  int slot[2][4];
  int activation;          // actuator with activation dynamics: index of u in y; else -1
  int slot_activation[2];  // entry of (row: accel from/to, column: u); -1 if none
  int loop = -1;           // controlled actuator: index of its controller in loops
  int side = 0;            // controlled actuator: +1 takes level + c, -1 level - c
  // in 2 or 3 dimensions: its path's points in path_points[path_begin, path_end), and its
  // Jacobian entries from path_slots[slot_begin] (space_jacobian.cc)
  int path_begin = 0, path_end = 0, slot_begin = 0;
};

// A point of a path in 2 or 3 dimensions: a node, or fixed coordinates; or a wrap surface of
// the skeleton between the points before and after it.
struct PathPoint {
  int node;  // index in nodes, or -1
  Coordinates position;
  int wrap = -1;  // index in the skeleton's wraps, or -1
};

// A wrap surface as the right-hand side sees it: its unit axis and the unit x of its side,
// across the axis, in its body's frame.
struct PlacedWrap {
  Coordinates axis, x;
};

// A controller as the right-hand side sees it. The command c depends on at most the states in
// `columns`: the measured element's ends (x_from, v_from, x_to, v_to; a node measured as the
// `to` end), the measured actuator's activation state, the integral.
constexpr int kLoopColumns = 6;
struct Loop {
  int element = -1;                 // measured element, or -1
  int node = -1;                    // measured node, or -1
  int integral = -1;                // index of z in y, or -1
  int driven[2] = {-1, -1};         // the actuators driven (the second: co-contraction)
  int columns[kLoopColumns];        // state indices, -1 where absent
  int slot_integral[kLoopColumns];  // entries (z row, column)
  // entries (row, column) of each driven actuator's rows: its ends' acceleration rows, or
  // with activation dynamics its activation row (row 0)
  int slot_driven[2][2][kLoopColumns];
  // in 2 or 3 dimensions, in place of `columns` and the slots above: its columns in
  // loop_columns[column_begin, column_end), and its Jacobian entries from
  // loop_slots[slot_begin] (space_control.cc)
  int column_begin = 0, column_end = 0, slot_begin = 0;
};

// An activation state (docs/model.md section 8).
struct Activation {
  int element;  // index in elements
  int state;    // index of u in y
  int slot;     // entry (u row, u column): d(udot)/du
};

// Loads along one direction, in 2 or 3 dimensions.
struct DirectedLoads {
  Coordinates direction;  // unit
  LoadSet loads;
};

struct FreeNode {
  int node;             // index in nodes
  LoadSet loads;        // on a line
  double inverse_mass;  // 1 / (mass + mass loads) [1/kg]
  // entries (x row, xdot column): 1, per coordinate; (xdot row, x column): the loads' slope,
  // per pair of coordinates (row * 3 + column)
  int slot_rate[3] = {-1, -1, -1};
  int slot_position[9] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
  std::vector<DirectedLoads> directed;  // in 2 or 3 dimensions
  bool massless = false;                // a junction: inverse_mass unused
};

// A massless junction on a line (docs/model.md 14.4, network_junction.cc): its velocity w is
// the root of R(w) = its loads + the forces of its elements = 0, and the only state it depends
// on is in `columns` (its position; each neighbour's position and velocity; each actuator's
// activation). Its Jacobian entries: (its position row, columns[k]) in row_slots[k], dw/dy by
// the implicit function theorem; and, for each element it ends, the entries (the other end's
// acceleration row, columns[k]) in neighbour_slots[i * columns + k], -1 unless that end is a
// free node with a mass.
struct Junction {
  int free;                          // index in free_nodes
  int state;                         // index of its position in y
  std::vector<int> links;            // the active elements with an end here
  std::vector<int> columns;          // sorted state indices
  std::vector<int> row_slots;        // one per column
  std::vector<int> neighbour_slots;  // links.size() * columns.size()
  // per link: the position in `columns` of the other end's position and velocity and of the
  // element's activation, -1 where absent; and of this junction's own position
  std::vector<std::array<int, 3>> link_columns;
  int own_column = -1;
};

// Where an element's tension has a kink, as the zero of a scalar function of (t, y): the
// integrator restarts there. kLength: the length at `level` (an actuator's passive slack
// length, a tendon's slack length); kLengtheningRate: dl/dt at `level` (an actuator whose
// tension-velocity slopes differ at v = 0); kExcitation: an actuator's activation state at its
// excitation, e(t) - u (`level` unused), where d(udot)/du jumps (docs/model.md 8); kCommand: a
// controlled actuator's unclamped command at `level` (0 or 1), where its clamp starts or stops
// acting (section 11).
struct Kink {
  enum Kind { kLength, kLengtheningRate, kExcitation, kCommand };
  Kind kind;
  int element;
  double level;  // [m] or [m/s]
};

// One free node whose active elements all end at fixed nodes, and no activation or integral
// state (a single actuator on its rig): its right-hand side without the general bookkeeping,
// the same operations in the same order. The link's sign is +1 when the free node is its `to`
// end (l = x - p), -1 when it is its `from` end (l = p - x).
struct Anchored {
  int element;
  double position;  // of the fixed end [m]
  int sign;
};

// The derivatives of an element's length and tension along a state direction, the tension
// split as an actuator's is (other kinds: all of it in `total`); for forward sensitivities
// (docs/model.md section 10).
struct ElementPartials {
  double length = 0.0;                              // of l [m per unit]
  double total = 0.0, passive = 0.0, active = 0.0;  // of T [N per unit]
};

// The shortest a segment of a path in 2 or 3 dimensions may become: a run stops there, as its
// direction is lost at 0.
constexpr double kMinSegmentLength = 1e-6;  // [m]

struct NetworkModel {
  // the parts as given
  std::vector<Node> nodes;
  std::vector<Element> elements;
  std::vector<NodeLoad> loads;
  std::vector<Controller> controllers;
  Space space;
  // each part's index by its name
  std::unordered_map<std::string, int> node_index, element_index, controller_index;

  std::vector<End> ends;    // one per node
  std::vector<Link> links;  // one per element
  // the links that can exert a force: not a damper of damping 0 or a spring of stiffness 0,
  // whose tension is a signed zero that changes no sum (a single actuator's network has both,
  // docs/model.md 7.4)
  std::vector<int> active_links;
  std::vector<FreeNode> free_nodes;  // in node order
  std::vector<Junction> junctions;
  int node_states = 0;  // the free nodes' states: the first this many of y
  // the skeleton (docs/model.md 15), or null: its coordinates q from y[skeleton_state], then
  // its speeds u, right after the nodes' states
  std::shared_ptr<const Skeleton> skeleton;
  int skeleton_state = -1;
  std::vector<Activation> activations;  // in element order, their states after the nodes'
  std::vector<Loop> loops;              // one per controller
  int integral_count = 0;               // the last this many states
  std::vector<Kink> kinks;

  bool single_node = false;  // the right-hand side of Anchored applies
  std::vector<Anchored> anchored;

  // in 2 or 3 dimensions (network_space.cc, space_jacobian.cc, space_control.cc)
  std::vector<PathPoint> path_points;
  std::vector<PlacedWrap> wraps;    // one per wrap surface of the skeleton
  std::vector<bool> wrapped_links;  // per element: whether its path has a wrap surface
  std::vector<int> path_slots;
  std::vector<int> loop_columns;
  std::vector<int> loop_slots;

  JacobianPattern pattern;
  std::vector<int> row_scale;  // per Jacobian entry: the free node whose 1/m scales it, or -1
};

inline int SkeletonStateCount(const NetworkModel& m) {
  return m.skeleton ? 2 * m.skeleton->coordinate_count() : 0;
}

inline int StateSize(const NetworkModel& m) {
  return m.node_states + SkeletonStateCount(m) + static_cast<int>(m.activations.size()) +
         m.integral_count;
}

}  // namespace musclesim::network
