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
// network's Jacobian is not banded, and `auto` gives it the dense or the sparse solver.) The
// model (network_model.h) is immutable once built (but for HoldActivation, which a stepper
// applies to its own copy) and shared by every thread that integrates it; what an evaluation
// writes besides its results is in a NetworkScratch its caller owns (network_scratch.h). This
// class is its public face: each method is the algorithm of the same name over the model
// (src/dynamics/network_*.h), or composed of them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "musclesim/dynamics/network_model.h"
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
  // With a `skeleton` (docs/model.md 15; 2 or 3 dimensions): nodes on its bodies move with
  // them, and the forces of the elements on such nodes move the bodies.
  NetworkSystem(std::vector<Node> nodes, std::vector<Element> elements,
                std::vector<NodeLoad> loads = {}, std::vector<Controller> controllers = {},
                Space space = {}, std::shared_ptr<const Skeleton> skeleton = nullptr);

  int state_size() const { return network::StateSize(model_); }
  // The free nodes' positions and velocities: the first this many states.
  int node_state_count() const { return model_.node_states; }
  // The skeleton, or null; its coordinates' states start at skeleton_state() (then the
  // speeds), right after the nodes'.
  const Skeleton* skeleton() const { return model_.skeleton.get(); }
  int skeleton_state() const { return model_.skeleton_state; }
  // Whether element e's length changes with skeleton coordinate k (some of its path's points
  // move with k, some do not): it has a moment arm about k.
  bool Spans(int e, int k) const;
  // How many actuators have activation dynamics: their states follow the nodes' and the
  // skeleton's.
  int activation_count() const { return static_cast<int>(model_.activations.size()); }
  // How many controllers have an integral state: the last this many states are theirs.
  int integral_count() const { return model_.integral_count; }
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
  const JacobianPattern& jacobian_pattern() const { return model_.pattern; }

  // The length of element e at (t, y) [m], and its rate of change [m/s].
  double Length(int e, double t, const double* y) const;
  double LengtheningRate(int e, double t, const double* y) const;
  // In 2 or 3 dimensions: how many segments element e's path has (its via points + 1), and
  // the length of segment k at (t, y) [m] (on a line: 1, and the element's length).
  int SegmentCount(int e) const;
  double SegmentLength(int e, int k, double t, const double* y) const;
  // The shortest a segment may become: a run stops there, as its direction is lost at 0.
  static constexpr double kMinSegmentLength = network::kMinSegmentLength;  // [m]
  // Where an element's tension has a kink, as the zero of a scalar function of (t, y): the
  // integrator restarts there (network_model.h).
  using Kink = network::Kink;
  // The kink's function at (t, y): its sign changes where the kink is crossed.
  double KinkValue(const Kink& kink, double t, const double* y) const;
  const std::vector<Kink>& kinks() const { return model_.kinks; }
  // Where the inputs jump (activations, excitations, force loads, prescribed motions):
  // sorted, in (t0, t1).
  std::vector<double> Breakpoints(double t0, double t1) const;

  void Observe(double t, const double* y, NetworkSample& sample) const;
  // Parts of Observe, for a record that needs only a few columns (RunColumns): element e's
  // sample, node i's position [m] and velocity [m/s], and the sum of the loads on node i [N]
  // (0 unless it is free). Each equals Observe's to the last bit.
  void ObserveElement(int e, double t, const double* y, ElementSample& out) const;
  // (In 2 or 3 dimensions: the x coordinate; NodeCoordinate has them all.)
  double NodePosition(int i, double t, const double* y) const;
  double NodeVelocity(int i, double t, const double* y) const;
  // Coordinate c (0: x, 1: y, 2: z) of node i's position [m] and velocity [m/s].
  double NodeCoordinate(int i, int c, double t, const double* y) const;
  double NodeCoordinateRate(int i, int c, double t, const double* y) const;
  // (In 2 or 3 dimensions: the load's magnitude; Observe has its coordinates.)
  double LoadOn(int i, double t, const double* y) const;
  // What made the right-hand side at (t, y) non-finite, for a failed run's message: the first
  // node, element tension or load that is not finite, with its values and the time.
  std::string NonFiniteCause(double t, const double* y) const;

  const std::vector<Node>& nodes() const { return model_.nodes; }
  const std::vector<Element>& elements() const { return model_.elements; }
  const std::vector<NodeLoad>& loads() const { return model_.loads; }
  const std::vector<Controller>& controllers() const { return model_.controllers; }
  const Space& space() const { return model_.space; }
  int dimensions() const { return model_.space.dimensions; }
  int FindNode(std::string_view name) const;        // -1 if none
  int FindElement(std::string_view name) const;     // -1 if none
  int FindController(std::string_view name) const;  // -1 if none
  // The state index of a node's position, -1 unless free.
  int StateIndex(int node) const { return model_.ends[node].state; }
  // The state index of a node's velocity (right after its position's d coordinates), -1
  // unless free with a mass: a massless junction's velocity is not a state.
  int VelocityStateIndex(int node) const { return model_.ends[node].rate; }
  // How many free nodes are massless junctions (docs/model.md 14.4).
  int junction_count() const { return static_cast<int>(model_.junctions.size()); }
  // The state index of an element's activation, -1 unless it is an actuator with activation
  // dynamics.
  int ActivationStateIndex(int element) const { return model_.links[element].activation; }
  // The state index of a controller's integral, -1 unless its integral gain is nonzero.
  int IntegralStateIndex(int controller) const { return model_.loops[controller].integral; }

  // Holds an actuator's activation (or, with activation dynamics, its excitation) at `value`
  // from now on: an input set from outside, between the steps of a Stepper (solver/stepper.h).
  // Throws ParameterError unless element `e` is an actuator that no controller drives and
  // `value` is in [0, 1].
  void HoldActivation(int e, double value);

  // For forward sensitivities (docs/model.md section 10).
  // Derivatives of an element's length and tension, the tension split as an actuator's is
  // (other kinds: all of it in `total`).
  using ElementPartials = network::ElementPartials;
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
  network::NetworkModel model_;
};

}  // namespace musclesim
