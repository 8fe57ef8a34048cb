// A network on a line (docs/model.md section 7), in the plane or in space (section 12) as a
// first-order system. The state is
//   y = (x_1, xdot_1, x_2, xdot_2, ..., u_1, u_2, ..., z_1, z_2, ...):
// (x_i, xdot_i) of every free node, in the order the nodes are given, interleaved, so a chain
// given in order has a banded Jacobian (in d dimensions x_i and xdot_i are d coordinates each:
// (x, y, xdot, ydot) in the plane); a massless junction (a free node of mass 0, on a line,
// docs/model.md 14.4) has x_i alone, its velocity the root of its force balance; then the
// activation u_k of every actuator with activation dynamics (docs/model.md section 8), in the order
// the elements are given; then the integral z_j of every controller with an integral gain (section
// 11), in the order the controllers are given. A network without either has exactly the node
// states. (An activation column couples its actuator's nodes to the end of the state: such a
// network's Jacobian is not banded, and `auto` gives it the dense or the sparse solver.) The model:
// immutable once built and shared by every thread that integrates it; what an evaluation
// writes besides its results is in a NetworkScratch its caller owns (network_scratch.h).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/jacobian_pattern.h"
#include "musclesim/dynamics/network_parts.h"
#include "musclesim/dynamics/network_sample.h"
#include "musclesim/dynamics/network_scratch.h"

namespace musclesim {

class NetworkSystem {
 public:
  // Validates every part and how they fit (ParameterError with paths such as
  // "nodes[1].mass", "elements[2].to", "loads[0].node"): names unique and non-empty, every
  // reference resolved, loads on free nodes, at least one free node, every free node joined
  // by elements to a fixed or prescribed node; every controller's measure and actuators
  // resolved ("controllers[0].drives"), every controlled actuator driven by one controller,
  // no algebraic loop (docs/model.md 11).
  // In 2 or 3 dimensions (`space`, docs/model.md 12) also: via points resolved ("elements[1]
  // .via[0]"), no node twice on one path, two fixed via points never in the same place, load
  // directions not zero, a coordinate named for every node a controller measures
  // ("controllers[0].measure.coordinate"), within the dimensions.
  NetworkSystem(std::vector<Node> nodes, std::vector<Element> elements,
                std::vector<NodeLoad> loads = {}, std::vector<Controller> controllers = {},
                Space space = {});

  int state_size() const { return node_state_count() + activation_count() + integral_count(); }
  // The free nodes' positions and velocities: the first this many states.
  int node_state_count() const { return node_states_; }
  // How many actuators have activation dynamics: the states after the nodes' are theirs.
  int activation_count() const { return static_cast<int>(activations_.size()); }
  // How many controllers have an integral state: the last this many states are theirs.
  int integral_count() const { return integral_count_; }
  // y at a run's start t_start [s]: every free node's position and velocity, every
  // activation state at its initial_activation (by default its excitation at t_start).
  void InitialState(double t_start, double* y) const;
  // The same at t_start = 0.
  void InitialState(double* y) const { InitialState(0.0, y); }
  // Throws ParameterError("elements[i]", ...) unless every element is longer than zero at
  // (t, y) and its tension there is finite (an exponential law whose alpha overflows at the
  // element's initial stretch is refused before the run, not by CVODE at its first step).
  void CheckInitialState(double t, const double* y) const;

  // ydot = f(t, y), with the buffers of `scratch` (allocating nothing once they have grown).
  void RightHandSide(double t, const double* y, double* ydot, NetworkScratch& scratch) const;
  // df/dy at (t, y), one value per entry of jacobian_pattern().
  void Jacobian(double t, const double* y, double* values, NetworkScratch& scratch) const;
  // The same for one evaluation, with a scratch of their own (which a network with massless
  // junctions allocates): an integrator keeps one scratch and passes it.
  void RightHandSide(double t, const double* y, double* ydot) const {
    NetworkScratch scratch;
    RightHandSide(t, y, ydot, scratch);
  }
  void Jacobian(double t, const double* y, double* values) const {
    NetworkScratch scratch;
    Jacobian(t, y, values, scratch);
  }
  const JacobianPattern& jacobian_pattern() const { return pattern_; }

  // The length of element e at (t, y) [m], and its rate of change [m/s].
  double Length(int e, double t, const double* y) const;
  double LengtheningRate(int e, double t, const double* y) const;
  // In 2 or 3 dimensions: how many segments element e's path has (its via points + 1), and
  // the length of segment k at (t, y) [m] (on a line: 1, and the element's length).
  int SegmentCount(int e) const;
  double SegmentLength(int e, int k, double t, const double* y) const;
  // The shortest a segment may become: a run stops there, as its direction is lost at 0.
  static constexpr double kMinSegmentLength = 1e-6;  // [m]
  // Where an element's tension has a kink, as the zero of a scalar function of (t, y): the
  // integrator restarts there. kLength: the length at `level` (an actuator's passive slack
  // length, a tendon's slack length); kLengtheningRate: dl/dt at `level` (an actuator whose
  // tension-velocity slopes differ at v = 0); kExcitation: an actuator's activation state at
  // its excitation, e(t) - u (`level` unused), where d(udot)/du jumps (docs/model.md 8);
  // kCommand: a controlled actuator's unclamped command at `level` (0 or 1), where its clamp
  // starts or stops acting (section 11).
  struct Kink {
    enum Kind { kLength, kLengtheningRate, kExcitation, kCommand };
    Kind kind;
    int element;
    double level;  // [m] or [m/s]
  };
  // The kink's function at (t, y): its sign changes where the kink is crossed.
  double KinkValue(const Kink& kink, double t, const double* y) const;
  const std::vector<Kink>& kinks() const { return kinks_; }
  // Where the inputs jump (activations, excitations, force loads, prescribed motions):
  // sorted, in (t0, t1).
  std::vector<double> Breakpoints(double t0, double t1) const;

  void Observe(double t, const double* y, NetworkSample& sample) const;
  // Parts of Observe, for a record that needs only a few columns (RunColumns): element e's
  // sample, node i's position [m] and velocity [m/s], and the sum of the loads on node i [N]
  // (0 unless it is free). Each equals Observe's to the last bit.
  void ObserveElement(int e, double t, const double* y, ElementSample& out) const;
  // (In 2 or 3 dimensions: the x coordinate; NodeCoordinate has them all.)
  double NodePosition(int i, double t, const double* y) const {
    return space_.dimensions == 1 ? PositionOf(ends_[i], t, y) : NodeCoordinate(i, 0, t, y);
  }
  double NodeVelocity(int i, double t, const double* y) const {
    return space_.dimensions == 1 ? VelocityOf(ends_[i], t, y) : NodeCoordinateRate(i, 0, t, y);
  }
  // Coordinate c (0: x, 1: y, 2: z) of node i's position [m] and velocity [m/s].
  double NodeCoordinate(int i, int c, double t, const double* y) const;
  double NodeCoordinateRate(int i, int c, double t, const double* y) const;
  // (In 2 or 3 dimensions: the load's magnitude; Observe has its coordinates.)
  double LoadOn(int i, double t, const double* y) const;
  // What made the right-hand side at (t, y) non-finite, for a failed run's message: the first
  // node, element tension or load that is not finite, with its values and the time.
  std::string NonFiniteCause(double t, const double* y) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Element>& elements() const { return elements_; }
  const std::vector<NodeLoad>& loads() const { return loads_; }
  const std::vector<Controller>& controllers() const { return controllers_; }
  const Space& space() const { return space_; }
  int dimensions() const { return space_.dimensions; }
  int FindNode(std::string_view name) const;        // -1 if none
  int FindElement(std::string_view name) const;     // -1 if none
  int FindController(std::string_view name) const;  // -1 if none
  // The state index of a node's position, -1 unless free.
  int StateIndex(int node) const { return ends_[node].state; }
  // The state index of a node's velocity (right after its position's d coordinates), -1
  // unless free with a mass: a massless junction's velocity is not a state.
  int VelocityStateIndex(int node) const { return ends_[node].rate; }
  // How many free nodes are massless junctions (docs/model.md 14.4).
  int junction_count() const { return static_cast<int>(junctions_.size()); }
  // The state index of an element's activation, -1 unless it is an actuator with activation
  // dynamics.
  int ActivationStateIndex(int element) const { return links_[element].activation; }
  // The state index of a controller's integral, -1 unless its integral gain is nonzero.
  int IntegralStateIndex(int controller) const { return loops_[controller].integral; }

  // Holds an actuator's activation (or, with activation dynamics, its excitation) at `value`
  // from now on: an input set from outside, between the steps of a Stepper (solver/stepper.h).
  // Throws ParameterError unless element `e` is an actuator that no controller drives and
  // `value` is in [0, 1].
  void HoldActivation(int e, double value);

  // For forward sensitivities (docs/model.md section 10).
  // Derivatives of an element's length and tension, the tension split as an actuator's is
  // (other kinds: all of it in `total`).
  struct ElementPartials {
    double length = 0.0;                              // of l [m per unit]
    double total = 0.0, passive = 0.0, active = 0.0;  // of T [N per unit]
  };
  // The derivatives of element e's length and tension along the state direction s at (t, y):
  // dl/dy s and dT/dy s. (Networks without controllers.) In 2 or 3 dimensions dl/dy s sums
  // G_j . s_q over the free points of the path, and d(ldot)/dy s adds the turning of the
  // directions, (d ldot/dq_j) . s_q (docs/model.md 12).
  ElementPartials Along(int e, double t, const double* y, const double* s) const;
  // The derivative of node `node`'s velocity along s at (t, y) (on a line): s of its velocity
  // state for a node with a mass, dw/dy s for a massless junction (the implicit function
  // theorem on its balance, as the Jacobian's row), 0 for a fixed or prescribed node.
  double NodeVelocityAlong(int node, double t, const double* y, const double* s) const;
  // Adds to `ydot` what a tension `tension` [N] of element e at (t, y) adds to the right-hand
  // side (its nodes' accelerations), the way a change of that element's tension enters df/dp:
  // on a line +-T on its ends; in 2 or 3 dimensions -T G_j on every free point of its path
  // (G_j at (t, y)).
  void AddTension(int e, double t, const double* y, double tension, double* ydot) const;

 private:
  // A node as the right-hand side sees it.
  struct End {
    NodeKind kind;
    int state;            // free: index of x in y; else -1
    double position;      // fixed
    int node;             // index in nodes_ (prescribed: its motion; an index, so copies work)
    Coordinates point{};  // fixed, in 2 or 3 dimensions
    int rate = -1;        // free with a mass: index of xdot in y; else -1
    int free = -1;        // free: index in free_nodes_; else -1
    int junction = -1;    // massless junction: index in junctions_; else -1
  };
  // An element as the right-hand side sees it: its ends and where its Jacobian goes.
  struct Link {
    int from, to;  // node indices
    // entry of (row: accel from/to, column: x_from, v_from, x_to, v_to); -1 if none
    int slot[2][4];
    int activation;          // actuator with activation dynamics: index of u in y; else -1
    int slot_activation[2];  // entry of (row: accel from/to, column: u); -1 if none
    int loop = -1;           // controlled actuator: index of its controller in loops_
    int side = 0;            // controlled actuator: +1 takes level + c, -1 level - c
    // in 2 or 3 dimensions: its path's points in path_points_[path_begin, path_end), and its
    // Jacobian entries from path_slots_[slot_begin] (space_jacobian.cc)
    int path_begin = 0, path_end = 0, slot_begin = 0;
  };
  // A point of a path in 2 or 3 dimensions: a node, or fixed coordinates.
  struct PathPoint {
    int node;  // index in nodes_, or -1
    Coordinates position;
  };
  // A controller as the right-hand side sees it. The command c depends on at most the
  // states in `columns`: the measured element's ends (x_from, v_from, x_to, v_to; a node
  // measured as the `to` end), the measured actuator's activation state, the integral.
  static constexpr int kLoopColumns = 6;
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
    // loop_columns_[column_begin, column_end), and its Jacobian entries from
    // loop_slots_[slot_begin] (space_control.cc)
    int column_begin = 0, column_end = 0, slot_begin = 0;
  };
  // What a controller computes at (t, y), with derivatives along its columns (on a line; in
  // 2 or 3 dimensions they are SpaceControlJacobian's, and these stay 0).
  struct Command {
    double reference, measured, error;
    double value;                   // c
    double by_state[kLoopColumns];  // dc/dy at the columns
    double error_by_state[kLoopColumns];
    double high, low;  // c beyond which no actuator can respond further
  };
  // An activation state (docs/model.md section 8).
  struct Activation {
    int element;  // index in elements_
    int state;    // index of u in y
    int slot;     // entry (u row, u column): d(udot)/du
  };
  // Loads along one direction, in 2 or 3 dimensions.
  struct DirectedLoads {
    Coordinates direction;  // unit
    LoadSet loads;
  };
  struct FreeNode {
    int node;             // index in nodes_
    LoadSet loads;        // on a line
    double inverse_mass;  // 1 / (mass + mass loads) [1/kg]
    // entries (x row, xdot column): 1, per coordinate; (xdot row, x column): the loads'
    // slope, per pair of coordinates (row * 3 + column)
    int slot_rate[3] = {-1, -1, -1};
    int slot_position[9] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
    std::vector<DirectedLoads> directed;  // in 2 or 3 dimensions
    bool massless = false;                // a junction: inverse_mass unused
  };
  // A massless junction on a line (docs/model.md 14.4, network_junction.cc): its velocity w
  // is the root of R(w) = its loads + the forces of its elements = 0, and the only state it
  // depends on is in `columns` (its position; each neighbour's position and velocity; each
  // actuator's activation). Its Jacobian entries: (its position row, columns[k]) in
  // row_slots[k], dw/dy by the implicit function theorem; and, for each element it ends, the
  // entries (the other end's acceleration row, columns[k]) in neighbour_slots[i * columns +
  // k], -1 unless that end is a free node with a mass.
  struct Junction {
    int free;                          // index in free_nodes_
    int state;                         // index of its position in y
    std::vector<int> links;            // the active elements with an end here
    std::vector<int> columns;          // sorted state indices
    std::vector<int> row_slots;        // one per column
    std::vector<int> neighbour_slots;  // links.size() * columns.size()
    // per link: the position in `columns` of the other end's position and velocity and of
    // the element's activation, -1 where absent; and of this junction's own position
    std::vector<std::array<int, 3>> link_columns;
    int own_column = -1;
  };
  // Terms of the junction's balance R(w) and dR/dw at (t, y) with its velocity w, and the sum
  // of their magnitudes (R's rounding scale).
  struct Balance {
    double residual, by_velocity, magnitude;
  };
  // `elastic`: the loads and the springs' and tendons' terms alone, which w does not change;
  // else the other elements' alone.
  Balance JunctionBalance(const Junction& junction, double t, const double* y, double w,
                          bool elastic) const;
  // w of junction k at (t, y), to machine precision by bracketed Newton (NaN if no bracket is
  // found: the run then fails and NonFiniteCause names the junction).
  double JunctionVelocity(int k, double t, const double* y) const;
  // Why junction k has no finite velocity at (t, y), for messages: an elastic element's
  // tension that overflows, or a balance without a finite root; "" when it has one.
  std::string JunctionFailure(int k, double t, const double* y) const;
  // dw/dy s of junction k at (t, y): -(dR/dy s) / (dR/dw).
  double JunctionVelocityAlong(int k, double t, const double* y, const double* s) const;
  // Every junction's w at (t, y), in `velocities` (nullptr if none).
  const double* JunctionVelocities(double t, const double* y,
                                   std::vector<double>& velocities) const;
  // An end's velocity, a junction's taken from `w` (JunctionVelocities).
  double RateOf(const End& end, double t, const double* y, const double* w) const {
    return end.junction >= 0 ? w[end.junction] : VelocityOf(end, t, y);
  }
  // Resolve's step for junctions: each checked (on a line, with no controllers, no two
  // adjacent, a rate-dependent element at it), its links and columns; BuildPattern's: their
  // pattern entries and slots; Jacobian's: their rows and the neighbours' terms through w.
  void ResolveJunctions();
  void AddJunctionPattern(std::vector<std::pair<int, int>>& pairs) const;
  void FindJunctionSlots(const std::function<int(int, int)>& slot);
  // (`rate_slopes`: room for dT/d(ldot) of a junction's elements)
  void JunctionJacobian(double t, const double* y, const double* w, double* values,
                        std::vector<double>& rate_slopes) const;

  double PositionOf(const End& end, double t, const double* y) const;
  double VelocityOf(const End& end, double t, const double* y) const;
  // T, dT/dl, dT/d(dl/dt) and dT/du of element e at length l and lengthening rate ldot (an
  // actuator's u read from y when it is a state, else its waveform's at t).
  struct Tension {
    double value, by_length, by_rate, by_activation;
  };
  // (Defined inline in src/dynamics/element_tension.h, so that the right-hand side, which
  // needs only the value, computes no derivative for nothing.)
  Tension TensionOf(int e, double t, double l, double ldot, const double* y) const;
  void Resolve();
  // Resolve's steps: a node's index by name (ParameterError at `path` if none); the nodes'
  // ends, their states numbered (returns how many); element e's link and kinks, an
  // excitation's state numbered from `states`; the loads of each node; the free nodes, each
  // required `anchored` to a fixed or prescribed node.
  int NodeNamed(const std::string& name, const std::string& path) const;
  int NumberEnds();
  void AddLink(std::size_t e, int& states);
  std::vector<std::vector<Load>> LoadsByNode() const;
  void AddFreeNodes(std::vector<std::vector<Load>> node_loads, const std::vector<bool>& anchored);
  void FindSingleNode();
  void ResolveControllers(int& states);
  // ResolveControllers' steps: controllers[k]'s loop with what it measures; the actuator
  // `name` at controllers[k].`key`, checked to be one it may drive; the actuators it drives,
  // their drivers noted in `driver`; the refusal of a tension measured through a
  // controller's output; the loop's state columns.
  Loop MeasuredLoop(std::size_t k) const;
  // The measured node's coordinate: named in 2 or 3 dimensions, within the dimensions.
  void RequireCoordinate(std::size_t k) const;
  int DrivableActuator(std::size_t k, const char* key, const std::string& name,
                       const std::vector<int>& driver) const;
  void AttachDriven(std::size_t k, Loop& loop, std::vector<int>& driver);
  void RequireNoAlgebraicLoop(std::size_t k, const std::vector<int>& driver) const;
  void PlaceLoopColumns(std::size_t k);
  void BuildPattern();
  // BuildPattern's steps on a line: the links' pattern entries (their ends' acceleration rows,
  // by their positions, velocities and activation), and their slots.
  void AddLinePattern(std::vector<std::pair<int, int>>& pairs) const;
  void FindLineSlots(const std::function<int(int, int)>& slot);
  void AddControlPattern(std::vector<std::pair<int, int>>& pairs) const;
  void FindControlSlots(const std::vector<std::pair<int, int>>& pairs);

  // Feedback control (network_control.cc).
  Command CommandOf(int controller, double t, const double* y) const;
  // A controlled actuator's command before its clamp: level +- c, or c.
  double UnclampedOutput(int e, const Command& command, double t) const;
  // A controlled actuator's activation (no activation dynamics) or excitation, clamped.
  double ControlOutput(int e, double t, const double* y) const;
  // udot's excitation e of an actuator with activation dynamics: its signal's, or its
  // controller's output.
  double ExcitationOf(int e, double t, const double* y) const;
  // zdot = weight err: the weight of the integral's fade near the bounds, and its derivative
  // by c.
  struct IntegralFade {
    double weight, by_value;
  };
  static IntegralFade FadeOf(const Command& command, double ki);
  // zdot with its fade near the bounds, and its derivatives along the loop's columns.
  double IntegralRate(const Command& command, double ki, double* by_state) const;
  void ControlRightHandSide(double t, const double* y, double* ydot) const;
  // Adds the feedback terms dT/du du/dy, d(udot)/de de/dy and d(zdot)/dy (before the rows'
  // 1/m scaling).
  void ControlJacobian(double t, const double* y, double* values) const;
  void ObserveControllers(double t, const double* y, NetworkSample& sample) const;

  // Feedback control in 2 or 3 dimensions (space_control.cc): a loop's columns (the free
  // points of the measured element's path, or the measured node's coordinate and its rate,
  // then an activation state and the integral); the rows a driven actuator's output reaches
  // (its activation row, or the acceleration rows of its path's free points); their pattern
  // and entries; the measured quantity and its rate, with (unless nullptr) their derivatives
  // along the loop's columns; the feedback terms of the Jacobian (before the rows' 1/m).
  std::vector<int> loop_columns_;
  std::vector<int> loop_slots_;
  void PlaceSpaceLoopColumns(std::size_t k);
  void DrivenRows(int e, std::vector<int>& rows) const;
  void AddSpaceControlPattern(std::vector<std::pair<int, int>>& pairs) const;
  void FindSpaceControlSlots(const std::vector<std::pair<int, int>>& pairs);
  double MeasureInSpace(int k, double t, const double* y, double& rate,
                        double* measured_by = nullptr, double* rate_by = nullptr) const;
  void SpaceControlJacobian(double t, const double* y, double* values) const;

  std::vector<Node> nodes_;
  std::vector<Element> elements_;
  std::vector<NodeLoad> loads_;
  std::vector<Controller> controllers_;
  Space space_;
  // each part's index by its name
  std::unordered_map<std::string, int> node_index_, element_index_, controller_index_;
  std::vector<Loop> loops_;  // one per controller
  int integral_count_ = 0;
  std::vector<End> ends_;
  std::vector<Link> links_;
  // the links that can exert a force: not a damper of damping 0 or a spring of stiffness 0,
  // whose tension is a signed zero that changes no sum (a single actuator's network has
  // both, docs/model.md 7.4)
  std::vector<int> active_links_;
  // One free node whose active elements all end at fixed nodes, and no activation or
  // integral state (a single actuator on its rig): its right-hand side without the general
  // bookkeeping, the same operations in the same order. The link's sign is +1 when the free
  // node is its `to` end (l = x - p), -1 when it is its `from` end (l = p - x).
  struct Anchored {
    int element;
    double position;  // of the fixed end [m]
    int sign;
  };
  bool single_node_ = false;
  std::vector<Anchored> anchored_;
  void SingleNodeRightHandSide(double t, const double* y, double* ydot) const;

  // In 2 or 3 dimensions (network_space.cc, space_jacobian.cc).
  std::vector<PathPoint> path_points_;
  std::vector<int> path_slots_;
  void AddPath(std::size_t e);
  void ResolveSpace();
  // Element e's path at (t, y): its points' positions and velocities, measured.
  struct PathState;
  void MeasureLink(int e, double t, const double* y, PathState& state) const;
  void SpaceRightHandSide(double t, const double* y, double* ydot) const;
  void SpaceJacobian(double t, const double* y, double* values) const;
  void AddSpacePattern(std::vector<std::pair<int, int>>& pairs) const;
  // The state index of each point of the link's path (-1 unless a free node), in order.
  void PathStates(const Link& link, std::vector<int>& states) const;
  void FindSpaceSlots(const std::function<int(int, int)>& slot);
  void ObserveSpace(double t, const double* y, NetworkSample& sample) const;
  void CheckInitialPaths(double t, const double* y) const;
  double SpaceLengtheningRate(int e, double t, const double* y) const;
  // Along and AddTension in 2 or 3 dimensions (space_sensitivity.cc).
  ElementPartials SpaceAlong(int e, double t, const double* y, const double* s) const;
  void AddSpaceTension(int e, double t, const double* y, double tension, double* ydot) const;
  // The sum of free node f's loads, each along its direction [N].
  Coordinates DirectedLoad(const FreeNode& f, double t, const double* y) const;
  std::vector<FreeNode> free_nodes_;
  std::vector<Junction> junctions_;
  int node_states_ = 0;                  // the free nodes' states: the first this many of y
  std::vector<Activation> activations_;  // in element order, their states after the nodes'
  std::vector<int> row_scale_;  // per Jacobian entry: the free node whose 1/m scales it, or -1
  std::vector<Kink> kinks_;
  JacobianPattern pattern_;
};

}  // namespace musclesim
